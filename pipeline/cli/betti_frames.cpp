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
  for (const std::optional<int>& type : types) {
    const ComplexIndex index(medusa, type);
    TypeSlices slices{type ? std::to_string(*type) : "all", {}};
    for (std::size_t k = 0; k < medusa.input.frames(); ++k) {
      check_interrupted();
      slices.at_frame.push_back(signature_of(medusa, index.at_frame(k), check_interrupted));
    }
    all.push_back(std::move(slices));
  }
  return all;
}

} // namespace medusa::cli
