#include "appendix_b.h"
#include "medusa/core/error.h"
#include "medusa/medusa/store_reader.h"
#include "medusa/medusa/store_writer.h"
#include "medusa_fixtures.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>

using namespace medusa;
using namespace medusa::test;
namespace fs = std::filesystem;

TEST_CASE("the Appendix B medusa survives a store round trip with its boundaries", "[medusa][store]") {
  const std::string path = temp_path("appendix-b.h5");
  MedusaCollector collector;
  {
    StoreWriter writer(path);
    TeeSink tee({&writer, &collector});
    play_into(appendix_b_stream(), tee, 5, 2);
  }
  const Medusa written = collector.take();
  const Medusa read = read_store(path);
  std::remove(path.c_str());
  REQUIRE(same_medusa(read, written));
  REQUIRE(read.cells_of_dimension(4).size() == 1);
  const CellId flip = read.cells_of_dimension(4).front();
  std::vector<std::vector<VertexId>> boundary;
  for (CellId f : read.boundary(flip))
    boundary.push_back(read.cell(f).vertices.to_vector());
  CHECK(boundary == std::vector<std::vector<VertexId>>{
                        {1, 2, 3, 4}, {0, 2, 3, 4}, {0, 1, 3, 4}, {0, 1, 2, 4}, {0, 1, 2, 3}});
  CHECK(read.cells_of_dimension(0).size() == 5);
  CHECK(read.cells_of_dimension(3).size() == 5);
}

TEST_CASE("a store read without its events has the same cells and no batch or frame records",
          "[medusa][store]") {
  const std::string path = temp_path("appendix-b-cells.h5");
  {
    StoreWriter writer(path);
    play_into(appendix_b_stream(), writer, 5, 2);
  }
  const Medusa whole = read_store(path);
  StoreReadOptions cells_only;
  cells_only.events = false;
  const Medusa cells = read_store(path, cells_only);
  std::remove(path.c_str());
  REQUIRE(!whole.batches.empty());
  REQUIRE(!whole.frames.empty());
  CHECK(cells.batches.empty());
  CHECK(cells.frames.empty());
  REQUIRE(cells.cells.size() == whole.cells.size());
  for (std::size_t i = 0; i < whole.cells.size(); ++i) {
    CHECK(cells.cells[i].vertices == whole.cells[i].vertices);
    CHECK(cells.cells[i].facets == whole.cells[i].facets);
    CHECK(cells.cells[i].birth == whole.cells[i].birth);
    CHECK(cells.cells[i].death == whole.cells[i].death);
  }
  CHECK(cells.end == whole.end);
}

TEST_CASE("an unfinished writer leaves no file at the final name", "[medusa][store][sanitize]") {
  const std::string path = temp_path("unfinished.h5");
  std::string temporary;
  {
    StoreWriter writer(path);
    temporary = writer.temporary_path();
    MedusaBuilder builder(writer);
    builder.set_run(test_run_info(), dummy_input(5, 2));
    const Stream s = appendix_b_stream();
    builder.initial(s.t0, s.initial);
    CHECK(fs::exists(temporary));
    CHECK_FALSE(fs::exists(path));
  }
  CHECK_FALSE(fs::exists(path));
  CHECK_FALSE(fs::exists(temporary));
}

TEST_CASE("a store that cannot be created raises a StoreError naming the path", "[medusa][store][sanitize]") {
  const std::string path = temp_path("no-such-dir") + "/out.h5";
  try {
    StoreWriter writer(path);
    FAIL("created a store in a missing directory");
  } catch (const medusa::StoreError& e) {
    CHECK(std::string(e.what()).find(path) != std::string::npos);
  }
}
