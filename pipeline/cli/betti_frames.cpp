#include "betti_frames.h"

#include "diagram_selection.h"
#include "interrupt.h"

#include "medusa/medusa/complex_index.h"

#include <optional>

namespace medusa::cli {

std::vector<TypeSlices> slices_at_frames(const Medusa& medusa) {
  std::vector<std::optional<int>> types{std::nullopt};
  for (int t : distinct_types(vertex_types(medusa)))
    types.emplace_back(t);
  std::vector<TypeSlices> all;
  // One pass over the cells per frame and type rather than an interval index per type: the index of
  // a million-cell run is gigabytes, a pass a fraction of a second.
  for (const std::optional<int>& type : types) {
    TypeSlices slices{type ? std::to_string(*type) : "all", {}};
    for (std::size_t k = 0; k < medusa.input.frames(); ++k) {
      check_interrupted();
      slices.at_frame.push_back(signature_of(medusa, cells_at_frame(medusa, k, type), check_interrupted));
    }
    all.push_back(std::move(slices));
  }
  return all;
}

} // namespace medusa::cli
