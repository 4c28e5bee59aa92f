#include "wrapping_summary.h"

#include "medusa/persistence/class_records.h"
#include "medusa/persistence/class_winding.h"

#include <map>

namespace medusa::cli {

void write_wrapping_loops(std::ostream& out, const medusa::Medusa& medusa, const std::string& store_path) {
  if (medusa.run.periodic_axes.empty())
    return;
  persistence::RepresentativeOptions options;
  options.max_dim = 1;
  const persistence::DiagramWithClasses classes = persistence::diagram_with_classes(
      store_path, medusa, persistence::Direction::forward, persistence::all_types, options);
  const std::vector<std::string> axes = persistence::class_wrapping_axes(medusa, classes);
  std::size_t loops = 0;
  std::map<std::string, std::size_t> wrapping; // by axes
  for (std::size_t i = 0; i < classes.classes.size(); ++i) {
    if (classes.diagram.pairs[classes.classes.rows[i]].dim != 1)
      continue;
    ++loops;
    if (!axes[i].empty())
      ++wrapping[axes[i]];
  }
  std::size_t wraps = 0;
  std::string along;
  for (const auto& [axes, n] : wrapping) {
    wraps += n;
    along += (along.empty() ? "" : ", ") + std::to_string(n) + " along " + axes;
  }
  out << "periodic domain (" << medusa.run.periodic_axes << "): ";
  if (wraps == 0) {
    out << "no loop of all cells wraps around the domain\n";
    return;
  }
  const bool one = wraps == 1;
  out << wraps << " of " << loops << " loop" << (loops == 1 ? "" : "s") << " of all cells "
      << (one ? "wraps" : "wrap") << " around the domain"
      << (wrapping.size() == 1 ? " along " + wrapping.begin()->first : ": " + along)
      << (one ? " (not a hole in the tissue" : " (not holes in the tissue")
      << ": the tissue closes on itself through the periodic boundary; column 'wraps' of `medusa classes "
         "--dim "
         "1`)\n";
}

} // namespace medusa::cli
