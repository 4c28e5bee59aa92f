// Class representatives stored beside their diagrams (docs/FORMAT.md, /persistence/<diagram>/classes):
// round trip, and malformed subgroups refused.
#include "../kinetic/kinetic_test_support.h"
#include "medusa/core/error.h"
#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "medusa/medusa/medusa_builder.h"
#include "medusa/medusa/store_reader.h"
#include "medusa/medusa/store_writer.h"
#include "medusa/persistence/class_records.h"
#include "medusa/persistence/class_store.h"
#include "medusa/persistence/diagram_store.h"
#include "medusa/persistence/medusa_diagrams.h"
#include "support/temp_files.h"

#include <catch2/catch.hpp>
#include <hdf5.h>

#include <memory>

using namespace medusa;
using namespace medusa::persistence;
using medusa::test::TempDir;

namespace {

// A complete store of a small random walk (two cell types), written by the real pipeline stages,
// with its diagrams and the representatives of the forward ones, in a folder removed with it.
struct StoredRun {
  std::shared_ptr<TempDir> dir;
  std::string path;
  std::vector<Diagram> diagrams;
  std::vector<ClassRepresentatives> classes;
};

StoredRun make_store(const std::string& name, const RepresentativeOptions& representatives = {}) {
  auto dir = std::make_shared<TempDir>("classes");
  StoredRun run{dir, dir->file(name), {}, {}};
  const kinetic::Trajectories t = kinetic::testing::random_walk(91, 24, 4, 5800, 600);
  kinetic::KineticOptions options;
  options.rho2.num = 1200 * 1200;
  {
    kinetic::KineticAlphaComplex engine(t, options);
    medusa::StoreWriter writer(run.path);
    medusa::MedusaBuilder builder(writer);
    medusa::RunInfo info;
    info.radius_text = "1200";
    info.radius = 1200;
    builder.set_run(info, t);
    engine.run(builder);
  }
  const medusa::Medusa m = medusa::read_store(run.path);
  std::vector<int> vertex_type;
  for (const kinetic::Trajectory& c : m.input.cells)
    vertex_type.push_back(c.type);
  DiagramRunOptions diagram_options;
  diagram_options.forward_classes = &run.classes;
  diagram_options.representatives = representatives;
  run.diagrams = compute_medusa_diagrams(m.cells, vertex_type, {1, 2}, diagram_options);
  std::vector<const ClassRepresentatives*> stored;
  for (std::size_t i = 0; i < run.diagrams.size(); ++i)
    stored.push_back(run.diagrams[i].direction == Direction::forward ? &run.classes[i] : nullptr);
  write_diagrams(run.path, run.diagrams, stored);
  return run;
}

} // namespace

TEST_CASE("Stored class representatives read back as they were computed, for the forward diagrams only") {
  const StoredRun run = make_store("classes_round_trip.h5");
  std::size_t represented = 0;
  for (std::size_t i = 0; i < run.diagrams.size(); ++i) {
    const auto back = read_classes(run.path, diagram_group_name(run.diagrams[i]));
    if (run.diagrams[i].direction == Direction::reverse) {
      CHECK_FALSE(back.has_value());
      continue;
    }
    REQUIRE(back.has_value());
    CHECK(back->rows == run.classes[i].rows);
    CHECK(back->cycles == run.classes[i].cycles);
    CHECK(back->clusters == run.classes[i].clusters);
    CHECK(back->options.max_dim == 2);
    CHECK_FALSE(back->options.zero_length);
    represented += back->size();
  }
  CHECK(represented > 0);
  CHECK_FALSE(read_classes(run.path, "forward_type9").has_value());
  // Read back through diagram_with_classes, the stored classes equal a fresh computation.
  const medusa::Medusa m = medusa::read_store(run.path);
  const DiagramWithClasses stored = diagram_with_classes(run.path, m, Direction::forward, 1, {});
  const Filtration f = make_type_filtration(
      m.cells,
      [&] {
        std::vector<int> types;
        for (const kinetic::Trajectory& c : m.input.cells)
          types.push_back(c.type);
        return types;
      }(),
      1, Direction::forward);
  const DiagramWithClasses fresh = compute_diagram_with_classes(m.cells, f);
  CHECK(stored.classes.rows == fresh.classes.rows);
  CHECK(stored.classes.cycles == fresh.classes.cycles);
  CHECK(stored.classes.clusters == fresh.classes.clusters);
  CHECK_THROWS_AS(diagram_with_classes(run.path, m, Direction::forward, 9, {}), InputError);
}

// Shortened cycles (docs/MATH.md §7.13) are stored as such and read back as such; asked for on a
// store of unshortened ones, they are shortened on reading, to what a shortened run stores.
TEST_CASE("Stored representatives say whether they are shortened, and shortening on reading matches") {
  RepresentativeOptions shorten;
  shorten.shorten = true;
  const StoredRun plain = make_store("classes_plain.h5");
  const StoredRun shortened = make_store("classes_shortened.h5", shorten);
  const medusa::Medusa m = medusa::read_store(plain.path);
  for (int type : {all_types, 1, 2}) {
    Diagram d;
    d.cell_type = type;
    const auto stored_plain = read_classes(plain.path, diagram_group_name(d));
    const auto stored_short = read_classes(shortened.path, diagram_group_name(d));
    REQUIRE(stored_plain.has_value());
    REQUIRE(stored_short.has_value());
    CHECK_FALSE(stored_plain->options.shorten);
    CHECK(stored_short->options.shorten);
    const DiagramWithClasses on_reading =
        diagram_with_classes(plain.path, m, Direction::forward, type, shorten);
    CHECK(on_reading.classes.options.shorten);
    CHECK(on_reading.classes.rows == stored_short->rows);
    CHECK(on_reading.classes.cycles == stored_short->cycles);
    REQUIRE(stored_short->size() == stored_plain->size());
    for (std::size_t i = 0; i < stored_plain->size(); ++i)
      CHECK(stored_short->cycles[i].size() <= stored_plain->cycles[i].size());
    // Without --shorten a shortened store still gives its shortened cycles, marked so.
    const DiagramWithClasses as_stored =
        diagram_with_classes(shortened.path, m, Direction::forward, type, {});
    CHECK(as_stored.classes.options.shorten);
    CHECK(as_stored.classes.cycles == stored_short->cycles);
  }
}

TEST_CASE("Class representatives whose rows run past their diagram are a store error") {
  const StoredRun run = make_store("classes_corrupt.h5");
  {
    const hid_t file = H5Fopen(run.path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    REQUIRE(file >= 0);
    const hid_t rows = H5Dopen2(file, "/persistence/forward_all/classes/row", H5P_DEFAULT);
    REQUIRE(rows >= 0);
    const hsize_t first = 0, one = 1;
    const hid_t space = H5Dget_space(rows);
    H5Sselect_hyperslab(space, H5S_SELECT_SET, &first, nullptr, &one, nullptr);
    const hid_t memory = H5Screate_simple(1, &one, nullptr);
    const std::uint64_t far = 1u << 30;
    REQUIRE(H5Dwrite(rows, H5T_NATIVE_UINT64, memory, space, H5P_DEFAULT, &far) >= 0);
    H5Sclose(memory);
    H5Sclose(space);
    H5Dclose(rows);
    H5Fclose(file);
  }
  CHECK_THROWS_AS(read_classes(run.path, "forward_all"), StoreError);
  // Representatives that do not fit their diagram are refused when written, too.
  ClassRepresentatives wrong = run.classes[0];
  wrong.rows.push_back(run.diagrams[0].pairs.size());
  wrong.cycles.push_back({});
  wrong.clusters.push_back({});
  CHECK_THROWS_AS(write_diagrams(run.path, {run.diagrams[0]}, {&wrong}), StoreError);
}
