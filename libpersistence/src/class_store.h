// Writing class representatives into an open diagram group (diagram_store.cpp calls it).
#pragma once

#include "medusa/persistence/representatives.h"

#include <hdf5.h>

#include <string>

namespace medusa::persistence::detail {

// Adds the subgroup `classes` to the diagram group `group` of a store at `path` (for messages);
// `points` is the number of points of the diagram. Throws StoreError.
void write_classes(hid_t group, const ClassRepresentatives& classes, std::size_t points,
                   const std::string& path);

} // namespace medusa::persistence::detail
