#include "appendix_b.h"
#include "medusa/core/error.h"
#include "medusa/medusa/complex_index.h"
#include "medusa/medusa/store_reader.h"
#include "medusa/medusa/store_writer.h"
#include "medusa_fixtures.h"
#include "random_stream.h"
#include "support/command_output.h"
#include "support/store_corruption.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

using namespace medusa;
using namespace medusa::test;
namespace fs = std::filesystem;

namespace {

constexpr std::uint64_t store_seed = 7919;

// Writes the stream to a store at `path` and returns the medusa collected alongside.
Medusa write_stream(const Stream& stream, const std::string& path, std::size_t vertices, std::size_t frames) {
  MedusaCollector collector;
  StoreWriter writer(path);
  TeeSink tee({&writer, &collector});
  play_into(stream, tee, vertices, frames);
  return collector.take();
}

} // namespace

TEST_CASE("a store read back is identical to the medusa written", "[medusa][store]") {
  const std::string path = temp_path("roundtrip.h5");
  RemoveFiles cleanup{{path}};
  CAPTURE(store_seed);
  const Medusa written = write_stream(random_stream(store_seed), path, 8, 5);
  REQUIRE(fs::exists(path));
  const Medusa read = read_store(path);
  REQUIRE(read.cells.size() == written.cells.size());
  REQUIRE(same_medusa(read, written));

  // Writing the read medusa again gives the same content.
  const std::string again = temp_path("roundtrip-again.h5");
  cleanup.paths.push_back(again);
  write_store(again, read);
  REQUIRE(same_medusa(read_store(again), written));
}

TEST_CASE("K_t from the store equals the complex replayed from the stream at every frame and batch",
          "[medusa][store][query]") {
  const std::string path = temp_path("replay.h5");
  RemoveFiles cleanup{{path}};
  for (std::uint64_t seed = store_seed; seed < store_seed + 5; ++seed) {
    CAPTURE(seed);
    const Stream stream = random_stream(seed);
    write_stream(stream, path, 8, 5);
    const Medusa m = read_store(path);
    const ComplexIndex index(m);
    const auto expected = replay(stream);
    for (const auto& [batch, k] : expected)
      CHECK(tuples(m, index.after(batch)) == k);
    for (const RecordedBatch& b : stream.batches)
      for (std::size_t k : b.frames_after)
        CHECK(tuples(m, index.at_frame(k)) == expected.at(b.time.batch));
    CHECK(tuples(m, index.at_frame(4)) == expected.rbegin()->second);
  }
}

TEST_CASE("h5py reads the store with the documented layout", "[medusa][store][python]") {
  const std::string path = temp_path("h5py.h5");
  RemoveFiles cleanup{{path}};
  write_stream(appendix_b_stream(), path, 5, 2);
  const std::string script = R"PY(
import sys, h5py, numpy as np
if not __debug__:
    sys.exit("the checks are assert statements: run without -O")
f = h5py.File(sys.argv[1], "r")
a = f.attrs
assert a["format"] == b"medusa-store", a["format"]
assert int(a["format_version"]) == 1
assert int(a["complete"]) == 1
assert float(a["radius"]) == 1.05
assert a["radius_text"] == b"1.05"
assert int(a["grid_scale"]) == 1000 and int(a["dimension"]) == 3
assert [s.decode() for s in a["source_files"]] == ["run/Step_0000.vtk.gz", "run/Step_0010.vtk.gz"]
assert [s.decode() for s in a["input_warnings"]] == [
    "run: the last frame read is MCS 10, but run.xml runs to MCS 100",
    "run/Step_0005.vtk.gz: snapshot truncated; left out"]
assert int(a["cell_count"]) == 31 and int(a["end_batch"]) == 2
c = f["cells"]
for name in c:
    assert c[name].fletcher32 and c[name].compression == "gzip" and c[name].maxshape[0] is None, name
off = c["vertex_offset"][:]
sizes = np.diff(off).astype(np.int64)
dims = np.bincount(sizes - 1)
assert list(dims) == [5, 10, 10, 5, 1], dims
ids = c["id"][:]
flip = int(np.nonzero(sizes == 5)[0][0])
assert int(c["kind"][flip]) == 1
assert list(c["vertices"][off[flip]:off[flip + 1]]) == [0, 1, 2, 3, 4]
assert c["birth_batch"][flip] == 1 and c["birth_rank"][flip] == 1 and c["death_batch"][flip] == 1
facets = c["facets"][c["facet_offset"][flip]:c["facet_offset"][flip + 1]]
row = {int(i): k for k, i in enumerate(ids)}
verts = lambda i: list(c["vertices"][off[row[i]]:off[row[i] + 1]])
assert [verts(int(x)) for x in facets] == [[1, 2, 3, 4], [0, 2, 3, 4], [0, 1, 3, 4], [0, 1, 2, 4], [0, 1, 2, 3]]
i = f["input"]
assert list(i["cell_id"][:]) == [100, 101, 102, 103, 104]
assert list(i["frame_times"][:]) == [0, 10]
assert i["positions"].shape == (10, 3) and list(i["positions"][3]) == [1, 1, -1]
assert list(f["events"]["batch_index"][:]) == [0, 1]
print("ok", len(ids))
)PY";
  const std::string script_path = temp_path("check_store.py");
  cleanup.paths.push_back(script_path);
  std::ofstream(script_path) << script;
  const auto [status, output] =
      run_command(std::string(MEDUSA_PYTHON) + " " + script_path + " " + path + " 2>&1");
  INFO(output);
  CHECK(status == 0);
  CHECK(output == "ok 31\n");
}

TEST_CASE("h5dump reads the store header and shows checksums and compression", "[medusa][store]") {
  const std::string path = temp_path("h5dump.h5");
  RemoveFiles cleanup{{path}};
  write_stream(appendix_b_stream(), path, 5, 2);
  const auto [status, output] = run_command("h5dump -H -p " + path + " 2>&1");
  INFO(output);
  CHECK(status == 0);
  CHECK(output.find("DATASET \"vertices\"") != std::string::npos);
  CHECK(output.find("CHECKSUM FLETCHER32") != std::string::npos);
  CHECK(output.find("COMPRESSION DEFLATE") != std::string::npos);
  CHECK(output.find("ATTRIBUTE \"complete\"") != std::string::npos);
}

TEST_CASE("a truncated store is rejected with a StoreError naming it", "[medusa][store][sanitize]") {
  const std::string path = temp_path("truncate.h5");
  const std::string cut = temp_path("truncated.h5");
  RemoveFiles cleanup{{path, cut}};
  write_stream(random_stream(store_seed), path, 8, 5);
  const std::vector<char> bytes = file_bytes(path);
  REQUIRE(bytes.size() > 1000);
  for (std::size_t keep : {std::size_t{0}, std::size_t{100}, bytes.size() / 4, bytes.size() / 2,
                           bytes.size() - 100, bytes.size() - 1}) {
    CAPTURE(keep);
    write_truncated(cut, bytes, keep);
    try {
      read_store(cut);
      FAIL("a truncated store was read");
    } catch (const medusa::StoreError& e) {
      CHECK(std::string(e.what()).find(cut) != std::string::npos);
    }
  }
}

TEST_CASE("a store with flipped bytes is rejected or read unchanged and never read wrong",
          "[medusa][store]") {
  const std::string path = temp_path("flip.h5");
  const std::string bad = temp_path("flipped.h5");
  RemoveFiles cleanup{{path, bad}};
  CAPTURE(store_seed);
  const Medusa original = write_stream(random_stream(store_seed), path, 8, 5);
  const std::vector<char> bytes = file_bytes(path);
  // The reads run in a child process that ends with _exit: HDF5 1.10 leaks free-list blocks on some
  // corrupt-metadata error paths and then prints "infinite loop closing library" at normal exit.
  int fds[2];
  REQUIRE(::pipe(fds) == 0);
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    ::close(fds[0]);
    long long rejected = 0, unchanged = 0, wrong = -1;
    const std::size_t step = std::max<std::size_t>(1, bytes.size() / 400);
    for (std::size_t at = 0; at < bytes.size(); at += step) {
      write_flipped(bad, bytes, at, 0x5A);
      try {
        if (same_medusa(read_store(bad), original))
          ++unchanged;
        else if (wrong < 0)
          wrong = static_cast<long long>(at);
      } catch (const medusa::StoreError&) {
        ++rejected;
      }
    }
    const std::string report =
        std::to_string(rejected) + " " + std::to_string(unchanged) + " " + std::to_string(wrong) + "\n";
    if (::write(fds[1], report.data(), report.size()) < 0)
      ::_exit(2);
    ::_exit(0);
  }
  ::close(fds[1]);
  std::string report;
  char buffer[256];
  ssize_t n;
  while ((n = ::read(fds[0], buffer, sizeof buffer)) > 0)
    report.append(buffer, static_cast<std::size_t>(n));
  ::close(fds[0]);
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == 0);
  long long rejected = 0, unchanged = 0, wrong = 0;
  std::istringstream(report) >> rejected >> unchanged >> wrong;
  INFO("rejected " << rejected << ", unchanged " << unchanged << ", first wrong read at byte " << wrong);
  CHECK(wrong == -1);
  CHECK(rejected > unchanged);
}

TEST_CASE("a writer killed mid-write leaves no file at the final name and an unreadable temporary",
          "[medusa][store]") {
  const std::string path = temp_path("killed.h5");
  const std::string temporary_prefix = path + ".tmp-";
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    // The child writes many cells and dies without finishing or running destructors.
    StoreWriter writer(path);
    writer.run(test_run_info(), dummy_input(100, 2));
    for (CellId id = 0; id < 50000; ++id) {
      Cell c;
      c.id = id;
      c.vertices = {static_cast<VertexId>(id % 100)};
      writer.cell(c);
    }
    ::_exit(0);
  }
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  REQUIRE(WIFEXITED(status));
  CHECK_FALSE(fs::exists(path));
  const std::string temporary = temporary_prefix + std::to_string(static_cast<long long>(child));
  RemoveFiles cleanup{{temporary}};
  REQUIRE(fs::exists(temporary));
  CHECK_THROWS_AS(read_store(temporary), medusa::StoreError);
}

TEST_CASE("a store written before input warnings were recorded reads as one without any",
          "[medusa][store][python]") {
  const std::string path = temp_path("no_warnings.h5");
  RemoveFiles cleanup{{path}};
  write_stream(appendix_b_stream(), path, 5, 2);
  REQUIRE(read_store(path).run.input_warnings.size() == 2);
  const std::string python = MEDUSA_PYTHON;
  REQUIRE(run_command(
              python +
              " -c 'import sys, h5py; del h5py.File(sys.argv[1], \"r+\").attrs[\"input_warnings\"]' " + path)
              .status == 0);
  const Medusa read = read_store(path);
  CHECK(read.run.input_warnings.empty());
  CHECK(read.run.source_files.size() == 2);
}

TEST_CASE("stores of another format version or without the complete flag are rejected",
          "[medusa][store][python]") {
  const std::string path = temp_path("edit.h5");
  RemoveFiles cleanup{{path}};
  write_stream(appendix_b_stream(), path, 5, 2);
  REQUIRE_NOTHROW(read_store(path));
  const std::string python = MEDUSA_PYTHON;
  REQUIRE(run_command(
              python +
              " -c 'import sys, h5py; h5py.File(sys.argv[1], \"r+\").attrs[\"format_version\"] = 2' " + path)
              .status == 0);
  CHECK_THROWS_WITH(read_store(path), Catch::Contains("format version 2"));
  REQUIRE(run_command(
              python +
              " -c 'import sys, h5py; f = h5py.File(sys.argv[1], \"r+\"); f.attrs[\"format_version\"] = 1; "
              "del f.attrs[\"complete\"]' " +
              path)
              .status == 0);
  CHECK_THROWS_WITH(read_store(path), Catch::Contains("incomplete"));
}

TEST_CASE("a store whose batch indices exceed 32 bits is rejected as corrupt", "[medusa][store][python]") {
  const std::string path = temp_path("batch.h5");
  RemoveFiles cleanup{{path}};
  const std::string python = MEDUSA_PYTHON;
  const std::string edit = python + " -c 'import sys, h5py, numpy; f = h5py.File(sys.argv[1], \"r+\"); ";
  write_stream(appendix_b_stream(), path, 5, 2);
  REQUIRE(run_command(edit + "f.attrs[\"end_batch\"] = numpy.uint64(2**32)' " + path).status == 0);
  CHECK_THROWS_AS(read_store(path), StoreError);
  CHECK_THROWS_WITH(read_store(path), Catch::Contains("end_batch 4294967296 is above 4294967295"));

  write_stream(appendix_b_stream(), path, 5, 2);
  REQUIRE(run_command(edit +
                      "row = list(f[\"cells/id\"][:]).index(3); f[\"cells/death_batch\"][row] = 2**32' " +
                      path)
              .status == 0);
  CHECK_THROWS_WITH(read_store(path), Catch::Contains("cell 3 has a batch index above 4294967295"));
}

TEST_CASE("a store whose facet ids name no cell of it is rejected as corrupt, even past 32 bits",
          "[medusa][store][python]") {
  const std::string path = temp_path("facets.h5");
  RemoveFiles cleanup{{path}};
  const std::string python = MEDUSA_PYTHON;
  const std::string edit = python + " -c 'import sys, h5py; f = h5py.File(sys.argv[1], \"r+\"); ";
  // 2^32 + 1 would be cell 1 if the id were cut to the 32 bits a cell's facet list holds.
  for (const std::string value : {"31", "2**32 + 1"}) {
    INFO("facet id " << value);
    write_stream(appendix_b_stream(), path, 5, 2);
    REQUIRE(read_store(path).cells.size() == 31);
    REQUIRE(run_command(edit + "f[\"cells/facets\"][0] = " + value + "' " + path).status == 0);
    CHECK_THROWS_AS(read_store(path), StoreError);
    CHECK_THROWS_WITH(read_store(path), Catch::Contains("/cells/facets entry 0 names cell") &&
                                            Catch::Contains("but the store has 31 cells"));
  }
}
