// The /persistence group of a medusa store (docs/FORMAT.md): round trip, h5py, determinism and the
// safe-write guarantees of write_diagrams.
#include "../kinetic/kinetic_test_support.h"
#include "medusa/core/error.h"
#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "medusa/medusa/medusa_builder.h"
#include "medusa/medusa/store_reader.h"
#include "medusa/medusa/store_writer.h"
#include "medusa/persistence/diagram_store.h"
#include "medusa/persistence/medusa_diagrams.h"
#include "support/command_output.h"
#include "support/temp_files.h"

#include <catch2/catch.hpp>
#include <hdf5.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace medusa;
using namespace medusa::persistence;
using medusa::test::command_output;
using medusa::test::temp_path;
namespace fs = std::filesystem;

namespace {

// A complete store of a small random walk (two cell types), written by the real pipeline stages.
constexpr std::uint64_t store_seed = 77;

void make_store(const std::string& path) {
  const kinetic::Trajectories t = kinetic::testing::random_walk(store_seed, 24, 4, 5800, 600);
  kinetic::KineticOptions options;
  options.rho2.num = 1200 * 1200;
  kinetic::KineticAlphaComplex engine(t, options);
  medusa::StoreWriter writer(path);
  medusa::MedusaBuilder builder(writer);
  medusa::RunInfo info;
  info.radius = 1200; // as the text says; read_store refuses a store whose radius is not positive
  info.radius_text = "1200";
  builder.set_run(info, t);
  engine.run(builder);
}

std::vector<Diagram> diagrams_of(const std::string& store) {
  const medusa::Medusa m = medusa::read_store(store);
  std::vector<int> vertex_type;
  for (const kinetic::Trajectory& c : m.input.cells)
    vertex_type.push_back(c.type);
  return compute_medusa_diagrams(m.cells, vertex_type, {1, 2});
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// The stored part of a pair (diagram_store.h).
bool same_stored_pair(const PersistencePair& a, const PersistencePair& b) {
  return a.dim == b.dim && same_bits(a.birth, b.birth) && same_bits(a.death, b.death) &&
         a.birth_cell == b.birth_cell && a.death_cell == b.death_cell && a.essential == b.essential &&
         a.zero_length == b.zero_length;
}

// The raw bytes of a dataset in its file type.
std::vector<unsigned char> dataset_bytes(const std::string& file, const std::string& name) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(f >= 0);
  const hid_t d = H5Dopen2(f, name.c_str(), H5P_DEFAULT);
  REQUIRE(d >= 0);
  const hid_t type = H5Dget_type(d);
  const hid_t space = H5Dget_space(d);
  const auto n = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space));
  std::vector<unsigned char> bytes(n * H5Tget_size(type));
  if (n > 0)
    REQUIRE(H5Dread(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data()) >= 0);
  H5Sclose(space);
  H5Tclose(type);
  H5Dclose(d);
  H5Fclose(f);
  return bytes;
}

bool has_temporaries(const std::string& path) {
  const std::string prefix = fs::path(path).filename().string() + ".tmp-";
  for (const auto& entry : fs::directory_iterator(fs::path(path).parent_path()))
    if (entry.path().filename().string().rfind(prefix, 0) == 0)
      return true;
  return false;
}

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

} // namespace

TEST_CASE("diagrams written into a store read back unchanged and leave the medusa readable",
          "[persistence][store]") {
  CAPTURE(store_seed);
  const std::string store = temp_path("roundtrip.h5");
  make_store(store);
  const medusa::Medusa before = medusa::read_store(store);
  const std::vector<Diagram> diagrams = diagrams_of(store);
  REQUIRE(diagrams.size() == 6);
  write_diagrams(store, diagrams);
  CHECK(!has_temporaries(store));

  const std::vector<Diagram> back = read_diagrams(store);
  REQUIRE(back.size() == diagrams.size());
  std::size_t pairs = 0, essential = 0;
  for (std::size_t i = 0; i < diagrams.size(); ++i) {
    CAPTURE(i, diagram_group_name(diagrams[i]));
    CHECK(back[i].direction == diagrams[i].direction);
    CHECK(back[i].cell_type == diagrams[i].cell_type);
    REQUIRE(back[i].pairs.size() == diagrams[i].pairs.size());
    for (std::size_t j = 0; j < diagrams[i].pairs.size(); ++j) {
      CAPTURE(j);
      CHECK(same_stored_pair(back[i].pairs[j], diagrams[i].pairs[j]));
      essential += diagrams[i].pairs[j].essential;
    }
    pairs += diagrams[i].pairs.size();
  }
  REQUIRE(pairs > 0);
  REQUIRE(essential > 0);
  CHECK(diagram_group_name(diagrams[0]) == "forward_all");
  CHECK(diagram_group_name(diagrams[3]) == "reverse_type1");
  // One diagram by its group name: the same pairs; a name the store does not list: none.
  for (std::size_t i = 0; i < diagrams.size(); ++i) {
    CAPTURE(i);
    const std::vector<Diagram> one = read_diagrams(store, diagram_group_name(diagrams[i]));
    REQUIRE(one.size() == 1);
    CHECK(diagram_group_name(one[0]) == diagram_group_name(diagrams[i]));
    REQUIRE(one[0].pairs.size() == diagrams[i].pairs.size());
    for (std::size_t j = 0; j < diagrams[i].pairs.size(); ++j)
      CHECK(same_stored_pair(one[0].pairs[j], diagrams[i].pairs[j]));
  }
  CHECK(read_diagrams(store, "forward_type7").empty());

  // The medusa itself is untouched, and writing again replaces the group.
  const medusa::Medusa after = medusa::read_store(store);
  CHECK(after.cells.size() == before.cells.size());
  CHECK(after.batches.size() == before.batches.size());
  write_diagrams(store, {diagrams[0]});
  CHECK(read_diagrams(store).size() == 1);
  std::remove(store.c_str());
}

TEST_CASE("h5py reads the stored diagrams with their attributes and infinite deaths",
          "[persistence][store][h5py]") {
  CAPTURE(store_seed);
  const std::string store = temp_path("h5py.h5");
  make_store(store);
  const std::vector<Diagram> diagrams = diagrams_of(store);
  write_diagrams(store, diagrams);
  const std::string script = temp_path("read.py");
  std::ofstream(script) << R"PY(
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r") as f:
    p = f["persistence"]
    assert p.attrs["format"] == b"medusa-persistence", p.attrs["format"]
    for name in p.attrs["diagram_order"].decode().split(","):
        g = p[name]
        birth, death = g["birth"][...], g["death"][...]
        ess = g["essential"][...].astype(bool)
        inf = np.isinf(death)
        assert (inf == ess).all()
        print(name, g.attrs["direction"].decode(), int(g.attrs["type"]), len(birth), int(ess.sum()),
              int(g["zero_length"][...].sum()), int(g["dimension"][...].sum()),
              int(np.sum(np.sign(death[inf]))), "%.17g" % float(birth.min(initial=0)))
)PY";
  const std::string out = command_output(std::string(MEDUSA_PYTHON) + " " + script + " " + store);
  std::ostringstream expected;
  expected.precision(17);
  for (const Diagram& d : diagrams) {
    std::size_t essential = 0, zero = 0;
    long dims = 0, signs = 0;
    double first_birth = 0;
    for (const PersistencePair& p : d.pairs) {
      essential += p.essential;
      zero += p.zero_length;
      dims += p.dim;
      signs += p.essential ? (p.death > 0 ? 1 : -1) : 0;
      first_birth = std::min(first_birth, p.birth);
    }
    expected << diagram_group_name(d) << ' ' << (d.direction == Direction::forward ? "forward" : "reverse")
             << ' ' << d.cell_type << ' ' << d.pairs.size() << ' ' << essential << ' ' << zero << ' ' << dims
             << ' ' << signs << ' ' << first_birth << '\n';
  }
  CHECK(out == expected.str());
  std::remove(script.c_str());
  std::remove(store.c_str());
}

TEST_CASE("the same store gives byte-identical diagram datasets", "[persistence][store]") {
  CAPTURE(store_seed);
  const std::string a = temp_path("determinism-a.h5"), b = temp_path("determinism-b.h5");
  make_store(a);
  fs::copy_file(a, b, fs::copy_options::overwrite_existing);
  write_diagrams(a, diagrams_of(a));
  write_diagrams(b, diagrams_of(b));
  std::size_t compared = 0;
  for (const Diagram& d : read_diagrams(a))
    for (const char* column :
         {"birth", "death", "dimension", "birth_cell", "death_cell", "essential", "zero_length"}) {
      const std::string name = "/persistence/" + diagram_group_name(d) + "/" + column;
      CAPTURE(name);
      CHECK(dataset_bytes(a, name) == dataset_bytes(b, name));
      ++compared;
    }
  REQUIRE(compared == 6 * 7);
  std::remove(a.c_str());
  std::remove(b.c_str());
}

TEST_CASE("a failed diagram write leaves the original file intact and no temporary file",
          "[persistence][store]") {
  const std::string path = temp_path("not-a-store.h5");
  std::ofstream(path) << "not an HDF5 file\n";
  const std::string before = file_text(path);
  Diagram d;
  CHECK_THROWS_AS(write_diagrams(path, {d}), StoreError);
  CHECK(file_text(path) == before);
  CHECK(!has_temporaries(path));
  CHECK_THROWS_AS(write_diagrams(path, {d, d}), StoreError); // two groups named forward_all
  CHECK_THROWS_AS(read_diagrams(path), StoreError);
  std::remove(path.c_str());
}

TEST_CASE("reading diagrams from a store without them is a store error", "[persistence][store]") {
  const std::string store = temp_path("no-diagrams.h5");
  make_store(store);
  CHECK_THROWS_WITH(read_diagrams(store), Catch::Contains("no group /persistence"));
  std::remove(store.c_str());
}

TEST_CASE("diagrams written one at a time in any order give the datasets and order of write_diagrams",
          "[persistence][store]") {
  CAPTURE(store_seed);
  medusa::test::TempDir dir("diagram-writer");
  const std::string whole = dir.file("whole.h5"), one_by_one = dir.file("one-by-one.h5");
  make_store(whole);
  fs::copy_file(whole, one_by_one);
  const std::vector<Diagram> diagrams = diagrams_of(whole);
  write_diagrams(whole, diagrams);
  const std::vector<std::string> names = medusa_diagram_names({1, 2});
  REQUIRE(names.size() == diagrams.size());
  {
    DiagramStoreWriter writer(one_by_one, names);
    for (std::size_t i = diagrams.size(); i-- > 0;) // last first
      writer.write(diagrams[i]);
    writer.close();
  }
  const std::vector<Diagram> back = read_diagrams(one_by_one);
  REQUIRE(back.size() == diagrams.size());
  std::size_t compared = 0;
  for (std::size_t i = 0; i < back.size(); ++i) {
    CHECK(diagram_group_name(back[i]) == names[i]); // in the announced order, not the written one
    for (const char* column :
         {"birth", "death", "dimension", "birth_cell", "death_cell", "essential", "zero_length"}) {
      const std::string name = "/persistence/" + names[i] + "/" + column;
      CAPTURE(name);
      CHECK(dataset_bytes(whole, name) == dataset_bytes(one_by_one, name));
      ++compared;
    }
  }
  REQUIRE(compared == 6 * 7);
}

TEST_CASE("a diagram writer refuses a diagram it was not told of, one written twice and a close with one "
          "missing",
          "[persistence][store]") {
  medusa::test::TempDir dir("diagram-writer");
  const std::string store = dir.file("store.h5");
  make_store(store);
  Diagram forward, reverse, typed;
  reverse.direction = Direction::reverse;
  typed.cell_type = 3;
  DiagramStoreWriter writer(store, {diagram_group_name(forward), diagram_group_name(reverse)});
  CHECK_THROWS_WITH(writer.write(typed), Catch::Contains("forward_type3") && Catch::Contains(store));
  writer.write(forward);
  CHECK_THROWS_WITH(writer.write(forward), Catch::Contains("written twice"));
  CHECK_THROWS_WITH(writer.close(), Catch::Contains("reverse_all was not written"));
  CHECK_THROWS_AS(DiagramStoreWriter(store, {"forward_all", "forward_all"}), StoreError);
  CHECK_THROWS_AS(DiagramStoreWriter(dir.file("missing.h5"), {"forward_all"}), StoreError);
}
