#include "run_summary.h"

#include "diagram_export.h"
#include "diagram_selection.h"
#include "position_source.h"

#include <cmath>
#include <cstdio>

namespace medusa::cli {
namespace {

std::string mcs(double t) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", t);
  return buffer;
}

const char* const feature_names[] = {"cluster", "loop", "cavity"};
const char* const feature_plurals[] = {"clusters", "loops", "cavities"};

// H2 of a planar run's medusa is no cavity of the flat tissue: its space-time lives in R^3, where by
// docs/MATH.md §7.6's argument for H3 one dimension down every H2 class is a bubble of space-time (a hole
// that opened inside the tissue and closed again, born when it closes) and none of positive length
// dies (tests/medusa/test_medusa_2d.cpp checks it on the real 2D run).
void describe_planar_bubbles(std::ostream& out, const persistence::Diagram& diagram) {
  std::size_t count = 0;
  for (const persistence::PersistencePair& p : diagram.pairs)
    count += p.dim == 2 && !p.zero_length ? 1 : 0;
  out << "  " << count << (count == 1 ? " space-time bubble" : " space-time bubbles")
      << " (holes that opened inside the tissue and closed again)\n";
}

} // namespace

void describe_forward_diagram(std::ostream& out, const persistence::Diagram& diagram, double t0, double t_end,
                              int dimension) {
  // Components alive just after t0: born in batch 0 and not killed there (zero-length pairs are
  // killed in their birth batch, docs/MATH.md §7.5). Those alive at the end are the essential classes.
  std::size_t at_start = 0, at_end = 0;
  const persistence::PersistencePair* last_merge = nullptr; // the longest-lived finite H0 class
  for (const persistence::PersistencePair& p : diagram.pairs)
    if (p.dim == 0) {
      at_start += p.birth_time.batch == 0 && !p.zero_length ? 1 : 0;
      at_end += p.essential ? 1 : 0;
      if (!p.essential && !p.zero_length &&
          (last_merge == nullptr || p.death - p.birth > last_merge->death - last_merge->birth))
        last_merge = &p;
    }
  out << "  " << at_start << (at_start == 1 ? " cluster" : " clusters") << " at MCS " << mcs(t0)
      << " merge into " << at_end << " by MCS " << mcs(t_end);
  if (last_merge != nullptr)
    out << "; longest-lived separate cluster born at MCS " << mcs(last_merge->birth) << ", merged at MCS "
        << mcs(last_merge->death);
  out << "\n";
  // Loops and cavities: a class that dies was filled; an essential one never was. It is a class of
  // the whole space-time medusa, so it need not be open at the end: a ring that later breaks apart
  // without being filled stays one (docs/MATH.md §7.5, §7.6). The longest-lived filled one is the telling
  // feature; essential classes are counted apart.
  for (int k = 1; k <= 2; ++k) {
    if (k == 2 && dimension == 2) {
      describe_planar_bubbles(out, diagram);
      continue;
    }
    const persistence::PersistencePair* longest = nullptr;
    std::size_t filled = 0, never = 0;
    for (const persistence::PersistencePair& p : diagram.pairs) {
      if (p.dim != k || p.zero_length)
        continue;
      if (p.essential) {
        ++never;
        continue;
      }
      ++filled;
      if (longest == nullptr || p.death - p.birth > longest->death - longest->birth)
        longest = &p;
    }
    const std::size_t count = filled + never;
    out << "  " << count << " " << (count == 1 ? feature_names[k] : feature_plurals[k]) << " (" << filled
        << " filled, " << never << " never filled)";
    if (longest != nullptr)
      out << "; longest-lived filled " << feature_names[k] << " born at MCS " << mcs(longest->birth)
          << ", filled at MCS " << mcs(longest->death) << " (lifetime "
          << mcs(longest->death - longest->birth) << " MCS)";
    out << "\n";
  }
}

void write_run_summary(std::ostream& out, const medusa::Medusa& medusa,
                       const kinetic::KineticStatistics& stats,
                       const std::vector<persistence::Diagram>& diagrams, const std::string& radius_text) {
  const kinetic::Trajectories& input = medusa.input;
  const double t0 = input.frame_times.empty() ? 0.0 : static_cast<double>(input.frame_times.front());
  const double t_end = input.frame_times.empty() ? 0.0 : static_cast<double>(input.frame_times.back());
  out << "cells: " << input.cells.size() << " trajectories, frames: " << input.frames() << " (MCS " << mcs(t0)
      << " to " << mcs(t_end) << "), dimension " << input.dimension << "\n"
      << "radius: " << radius_text << " lattice units\n";
  if (positions_from_vtk(medusa.run))
    out << "positions: " << describe_positions(medusa.run) << "\n";
  out << "events: " << stats.flips() << " flips (";
  // A planar run flips 2-2, a 3D run 2-3 and 3-2 (the hull flips of either are counted apart).
  if (input.dimension == 2)
    out << stats.flips22 << " 2-2, ";
  else
    out << stats.flips23 << " 2-3, " << stats.flips32 << " 3-2, ";
  out << stats.hull_flips << " hull), " << stats.radius_events << " radius events, " << stats.insertions
      << " insertions, " << stats.deletions << " deletions\n"
      << "medusa cells:";
  const int top = input.dimension + 1; // space-time cells go one dimension above space
  for (int k = 0; k <= top; ++k)
    out << " dim " << k << ": " << medusa.cells_of_dimension(k).size() << (k < top ? "," : "\n");
  for (const persistence::Diagram& d : diagrams) {
    if (d.direction != persistence::Direction::forward)
      continue;
    if (d.cell_type == persistence::all_types) {
      out << "all cells:\n";
    } else {
      const auto index = static_cast<std::size_t>(d.cell_type);
      const std::string name = index < input.type_names.size() ? input.type_names[index] : "";
      out << "type " << d.cell_type << (name.empty() ? "" : " (" + name + ")") << ":\n";
    }
    describe_forward_diagram(out, d, t0, t_end, input.dimension);
  }
  out << "(forward filtration; \"never filled\" counts loops" << (input.dimension == 2 ? "" : " and cavities")
      << " that no cells ever filled, including those that broke open instead: see README, Reading the "
         "summary)\n";
}

} // namespace medusa::cli
