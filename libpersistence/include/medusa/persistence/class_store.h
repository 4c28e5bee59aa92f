// Representatives of persistence classes stored next to their diagram: the subgroup `classes` of a
// diagram's group under `/persistence` (docs/FORMAT.md, "Class representatives").
#pragma once

#include "medusa/persistence/representatives.h"

#include <optional>
#include <string>

namespace medusa::persistence {

// The representatives stored with the diagram `/persistence/<diagram_name>`, or nothing when the
// store has no such diagram or the diagram has none. Throws StoreError when the file cannot be read
// as HDF5 or the subgroup is malformed (wrong version, lengths, rows outside the diagram).
std::optional<ClassRepresentatives> read_classes(const std::string& store_path,
                                                 const std::string& diagram_name);

} // namespace medusa::persistence
