// A store that does not fit on the disk: the writer must throw a StoreError naming the path and leave
// no file at the final name (README: outputs are written under a temporary name, renamed when
// complete). The full disk is a 64 KiB tmpfs when the test may mount one (root with CAP_SYS_ADMIN);
// the file-size limit RLIMIT_FSIZE gives the same failure (EFBIG from write) everywhere else.
#include "child_process.h"
#include "medusa/core/error.h"
#include "medusa/medusa/medusa.h"
#include "medusa/medusa/store_reader.h"
#include "medusa/medusa/store_writer.h"
#include "store_fixture.h"

#include <catch2/catch.hpp>

#include <csignal>
#include <filesystem>
#include <random>
#include <sys/mount.h>
#include <sys/resource.h>

using namespace medusa::test;
namespace fs = std::filesystem;

namespace {

constexpr std::uint64_t positions_seed = 20240611;

// The Appendix B medusa with an input of 5000 cells over 2 frames at random grid positions: some
// 180 KB of incompressible positions after compression, far more than the 64 KiB available.
medusa::Medusa large_medusa() {
  medusa::Medusa m = collect(appendix_b_stream(), 5, 2);
  m.input = dummy_input(5000, 2);
  std::mt19937_64 random(positions_seed);
  std::uniform_int_distribution<std::int64_t> coordinate(0, std::int64_t{1} << 40);
  for (auto& cell : m.input.cells)
    for (auto& p : cell.positions)
      p = {coordinate(random), coordinate(random), coordinate(random)};
  return m;
}

// Writes the large medusa to `path` in a child, after `limit` (run in the child) took effect. The
// child exits with child_threw_expected for a StoreError naming `path` after which neither `path`
// nor the writer's temporary file exists.
ChildResult write_too_large(const std::string& path, const std::function<void()>& limit) {
  return run_in_child([&](std::string& report) {
    limit();
    try {
      medusa::write_store(path, large_medusa());
      report = "the store was written";
      return child_returned;
    } catch (const medusa::StoreError& e) {
      report = e.what();
      const std::string temporary = path + ".tmp-" + std::to_string(static_cast<long long>(::getpid()));
      if (report.find(path) == std::string::npos)
        return child_returned;
      if (fs::exists(path)) {
        report += " (but a file exists at the final name)";
        return child_returned;
      }
      if (fs::exists(temporary)) {
        report += " (but the temporary file was left behind)";
        return child_returned;
      }
      return child_threw_expected;
    } catch (const medusa::Error& e) {
      report = std::string("not a StoreError: ") + e.what();
      return child_threw_other;
    }
  });
}

// A 64 KiB tmpfs mounted at a fresh directory, unmounted and removed at the end of the scope.
struct SmallFilesystem {
  std::string dir = temp_path("faults-tmpfs");
  bool mounted = false;
  SmallFilesystem() {
    fs::create_directories(dir);
    mounted = ::mount("tmpfs", dir.c_str(), "tmpfs", 0, "size=64k") == 0;
  }
  ~SmallFilesystem() {
    if (mounted)
      ::umount(dir.c_str());
    std::error_code ignored;
    fs::remove_all(dir, ignored);
  }
};

} // namespace

TEST_CASE("the store used for the full-disk tests is valid and larger than the space left", "[faults]") {
  const std::string path = temp_path("faults-large.h5");
  RemoveFiles cleanup{{path}};
  CAPTURE(positions_seed);
  const medusa::Medusa m = large_medusa();
  medusa::write_store(path, m);
  CHECK(fs::file_size(path) > 2 * 64 * 1024);
  const medusa::Medusa back = medusa::read_store(path);
  CHECK(back.cells.size() == m.cells.size());
  REQUIRE(back.input.cells.size() == m.input.cells.size());
  CHECK(back.input.cells.back().positions == m.input.cells.back().positions);
}

TEST_CASE("a store beyond the file-size limit gives a StoreError naming it and leaves no file", "[faults]") {
  const std::string path = temp_path("faults-fsize.h5");
  RemoveFiles cleanup{{path}};
  CAPTURE(positions_seed);
  const ChildResult r = write_too_large(path, [] {
    // Without SIGXFSZ ignored the kernel kills the writer instead of failing the write with EFBIG.
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{64 * 1024, 64 * 1024};
    ::setrlimit(RLIMIT_FSIZE, &limit);
  });
  INFO(r.describe());
  CHECK(r.end == ChildResult::End::exited);
  CHECK(r.code == child_threw_expected);
  CHECK_FALSE(fs::exists(path));
}

TEST_CASE("a store on a full filesystem gives a StoreError naming it and leaves no file", "[faults]") {
  SmallFilesystem small;
  CAPTURE(positions_seed, small.mounted);
  const std::string path = small.dir + "/full.h5";
  ChildResult r;
  if (small.mounted) {
    r = write_too_large(path, [] {});
  } else {
    WARN("no permission to mount a tmpfs (not root): a full filesystem (ENOSPC) is not tested, only the "
         "file-size limit (EFBIG) again");
    // No permission to mount: the same failure at the write call through the file-size limit.
    r = write_too_large(path, [] {
      std::signal(SIGXFSZ, SIG_IGN);
      const rlimit limit{64 * 1024, 64 * 1024};
      ::setrlimit(RLIMIT_FSIZE, &limit);
    });
  }
  INFO(r.describe());
  CHECK(r.end == ChildResult::End::exited);
  CHECK(r.code == child_threw_expected);
  CHECK_FALSE(fs::exists(path));
}
