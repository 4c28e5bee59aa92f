// A cell type as a user gives it on the command line or in Python: "all" (the whole medusa, where a
// command allows it), the CompuCell3D type id ("1") or the type's name from the run's CC3DML or CSV
// ("Condensing"). Shared by every command with --type and by the Python module.
#pragma once

#include "medusa/kinetic/trajectories.h"

#include <string>
#include <vector>

namespace medusa::cli {

// The distinct types of the run's cells, increasing.
std::vector<int> cell_types(const kinetic::Trajectories& input);

// persistence::all_types for "all" (when `allow_all`), else the id of the type `text` names: a decimal
// id, or a type name matched exactly, or else case-blind when that is unique. Throws InputError naming
// `source` and listing the run's types when `text` names no type of its cells.
int resolve_cell_type(const std::string& text, const kinetic::Trajectories& input, const std::string& source,
                      bool allow_all = true);

// A run's type names indexed by type id, "" where it names none (kinetic::Trajectories::type_names):
// what outputs print beside the ids.
using TypeNames = std::vector<std::string>;

// The run's name for a type ("" where it names none), and the type in words: "type 1 (Condensing)", or
// "type 4" for a type without a name.
std::string cell_type_name(const TypeNames& names, int type);
std::string cell_type_name(const kinetic::Trajectories& input, int type);
std::string cell_type_title(const TypeNames& names, int type);
std::string cell_type_title(const kinetic::Trajectories& input, int type);

// For a type label of the outputs ("all" or a decimal id): "all cells" or cell_type_title, and the
// type's name ("" for all and for a type without one).
std::string type_label_title(const TypeNames& names, const std::string& label);
std::string type_label_name(const TypeNames& names, const std::string& label);

// "1 (Condensing), 2 (NonCondensing)": the run's cell types with their names where it has them.
std::string cell_type_list(const kinetic::Trajectories& input);

} // namespace medusa::cli
