// A cell type as a user gives it (pipeline/cli/cell_type.cpp): by id, by name exactly, by name in any
// case when only one type has it, or "all"; anything else names the run's types in its message.
#include "cell_type.h"

#include "medusa/core/error.h"
#include "medusa/persistence/filtration.h"

#include <catch2/catch.hpp>

using medusa::cli::resolve_cell_type;

namespace {

// Cells of types 1, 2, 4 and 5; types 0 and 3 are named but have no cell, type 4 has no name.
medusa::kinetic::Trajectories run() {
  medusa::kinetic::Trajectories t;
  t.type_names = {"Medium", "Condensing", "condensing", "Dead", "", "Loose"};
  for (int type : {2, 1, 5, 4, 1}) {
    medusa::kinetic::Trajectory c;
    c.type = type;
    c.positions = {{0, 0, 0}};
    t.cells.push_back(c);
  }
  return t;
}

std::string refusal(const std::string& text, bool allow_all = true) {
  try {
    resolve_cell_type(text, run(), "run.h5", allow_all);
  } catch (const medusa::InputError& e) {
    return e.what();
  }
  return "accepted";
}

const std::string types = "; its cell types are 1 (Condensing), 2 (condensing), 4, 5 (Loose)";

} // namespace

TEST_CASE("a cell type is given by its id, by its exact name or as all", "[cli][types]") {
  CHECK(resolve_cell_type("4", run(), "run.h5") == 4);
  CHECK(resolve_cell_type("Condensing", run(), "run.h5") == 1);
  CHECK(resolve_cell_type("condensing", run(), "run.h5") == 2);
  CHECK(resolve_cell_type("all", run(), "run.h5") == medusa::persistence::all_types);
}

TEST_CASE("a name in another case is accepted only when one type has it", "[cli][types]") {
  CHECK(resolve_cell_type("LOOSE", run(), "run.h5") == 5);
  CHECK(refusal("CONDENSING") == "no cell type is named 'CONDENSING' in run.h5" + types);
}

TEST_CASE("a type without cells is refused with the run's types listed", "[cli][types]") {
  CHECK(refusal("Dead") == "cell type Dead (3) has no cells in run.h5" + types);
  CHECK(refusal("3") == "cell type 3 (Dead) has no cells in run.h5" + types);
  CHECK(refusal("Medium") == "cell type Medium (0) has no cells in run.h5" + types);
  CHECK(refusal("9") == "cell type 9 has no cells in run.h5" + types);
  CHECK(refusal("1.5") == "no cell type is named '1.5' in run.h5" + types);
}

TEST_CASE("all is no cell type where a command asks for one type", "[cli][types]") {
  CHECK(refusal("all", false) == "no cell type is named 'all' in run.h5" + types);
}
