#include "side_outputs.h"

#include "medusa/core/error.h"

#include <fstream>
#include <regex>

namespace medusa::cli {

namespace {

// The run id a side output names: the CSV's first line `# medusa run <id>`, the SVG's root attribute
// data-medusa-run; "" if it names none.
std::string stamped_id(const std::string& path, bool csv) {
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  static const std::regex csv_id("^# medusa run ([0-9a-f]{32})\n");
  static const std::regex svg_id("<svg [^>]*data-medusa-run=\"([0-9a-f]{32})\"");
  std::smatch m;
  return std::regex_search(head, m, csv ? csv_id : svg_id) ? m[1].str() : std::string();
}

} // namespace

std::string output_stem(const std::string& output) {
  const std::string suffix = ".h5";
  if (output.size() > suffix.size() &&
      output.compare(output.size() - suffix.size(), suffix.size(), suffix) == 0)
    return output.substr(0, output.size() - suffix.size());
  return output;
}

void check_side_outputs(const std::string& store, const std::string& run_id) {
  if (run_id.empty())
    return;
  const std::string stem = output_stem(store);
  for (const auto& [path, csv] :
       {std::pair{stem + ".diagrams.csv", true}, std::pair{stem + ".barcode.svg", false},
        std::pair{stem + ".diagram.svg", false}}) {
    std::ifstream probe(path);
    if (!probe)
      continue;
    const std::string id = stamped_id(path, csv);
    if (id != run_id)
      throw StoreError("store " + store + ": " + path + " beside it comes from another run (" +
                       (id.empty() ? "no run id" : "run id " + id) + "; the store's is " + run_id +
                       "); run medusa run again, or remove it");
  }
}

} // namespace medusa::cli
