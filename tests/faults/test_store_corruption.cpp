// Corrupted stores: a flipped byte in the superblock, inside a dataset chunk or inside an attribute
// must be reported as a StoreError naming the store; never read as other data, never a crash or hang.
// The store format (docs/FORMAT.md) makes this possible: 1.10 metadata with checksums everywhere and
// fletcher32 on every chunk.
#include "child_process.h"
#include "medusa/core/error.h"
#include "medusa/medusa/store_reader.h"
#include "store_fixture.h"
#include "support/command_output.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <sstream>

using namespace medusa::test;

namespace {

// Flips every bit of the byte at `offset` in a copy of `bytes` written to `bad`, reads it in a child
// and returns what happened; the child exits with child_threw_expected only for a StoreError whose
// message names `bad`.
ChildResult read_flipped(const std::vector<char>& bytes, std::size_t offset, const std::string& bad) {
  write_flipped(bad, bytes, offset, 0xFF);
  return run_in_child([&](std::string& report) {
    try {
      medusa::read_store(bad);
      report = "read without error";
      return child_returned;
    } catch (const medusa::StoreError& e) {
      report = e.what();
      return std::string(e.what()).find(bad) != std::string::npos ? child_threw_expected : child_returned;
    } catch (const medusa::Error& e) {
      report = std::string("not a StoreError: ") + e.what();
      return child_threw_other;
    }
  });
}

void check_flips(const std::vector<char>& bytes, std::size_t begin, std::size_t end, const std::string& bad) {
  REQUIRE(begin < end);
  REQUIRE(end <= bytes.size());
  for (std::size_t at = begin; at < end; ++at) {
    CAPTURE(at);
    const ChildResult r = read_flipped(bytes, at, bad);
    INFO(r.describe());
    CHECK(r.end == ChildResult::End::exited);
    CHECK(r.code == child_threw_expected);
  }
}

// Runs a Python snippet on `path` and returns its standard output.
std::string python(const std::string& code, const std::string& path) {
  const std::string script = temp_path("offsets.py");
  RemoveFiles cleanup{{script}};
  std::ofstream(script) << code;
  return command_output(std::string(MEDUSA_PYTHON) + " " + script + " " + path + " 2>&1");
}

} // namespace

TEST_CASE("the small valid store used for the fault tests reads back", "[faults]") {
  const std::string path = temp_path("faults-valid.h5");
  RemoveFiles cleanup{{path}};
  write_small_store(path);
  const medusa::Medusa m = medusa::read_store(path);
  CHECK(m.cells.size() == 31);
  CHECK(m.run.radius_text == "1.05");
}

TEST_CASE("every flipped byte of the superblock gives a StoreError naming the store", "[faults]") {
  const std::string path = temp_path("faults-super.h5");
  const std::string bad = temp_path("faults-super-bad.h5");
  RemoveFiles cleanup{{path, bad}};
  write_small_store(path);
  const std::vector<char> bytes = file_bytes(path);
  // Superblock version 3 (format 1.10): signature (8), version, offset and length sizes, flags,
  // four 8-byte addresses and a 4-byte checksum: 48 bytes at offset 0.
  REQUIRE(std::string(bytes.begin(), bytes.begin() + 8) == "\x89HDF\r\n\x1a\n");
  REQUIRE(bytes.at(8) == 3);
  check_flips(bytes, 0, 48, bad);
}

TEST_CASE("a flipped byte inside a dataset chunk gives a StoreError naming the store", "[faults]") {
  const std::string path = temp_path("faults-chunk.h5");
  const std::string bad = temp_path("faults-chunk-bad.h5");
  RemoveFiles cleanup{{path, bad}};
  write_small_store(path);
  const std::vector<char> bytes = file_bytes(path);
  // The byte range of the first chunk of three datasets of different groups, from h5py.
  const std::string out = python(R"PY(
import sys, h5py
f = h5py.File(sys.argv[1], "r")
for name in ["cells/vertices", "cells/birth_time", "input/positions"]:
    info = f[name].id.get_chunk_info(0)
    print(name, info.byte_offset, info.size)
)PY",
                                 path);
  std::istringstream in(out);
  std::string name;
  std::size_t offset = 0, size = 0;
  int datasets = 0;
  while (in >> name >> offset >> size) {
    CAPTURE(name, offset, size);
    REQUIRE(size > 4);
    // First byte, a middle byte, and the last byte (part of the fletcher32 checksum itself).
    check_flips(bytes, offset, offset + 1, bad);
    check_flips(bytes, offset + size / 2, offset + size / 2 + 1, bad);
    check_flips(bytes, offset + size - 1, offset + size, bad);
    ++datasets;
  }
  INFO(out);
  CHECK(datasets == 3);
}

TEST_CASE("a flipped byte inside an attribute gives a StoreError naming the store", "[faults]") {
  const std::string path = temp_path("faults-attr.h5");
  const std::string bad = temp_path("faults-attr-bad.h5");
  RemoveFiles cleanup{{path, bad}};
  write_small_store(path);
  const std::vector<char> bytes = file_bytes(path);
  // Known attribute values (test_run_info() and the format name): each occurs once in the file.
  for (const std::string value : {"medusa run --radius 1.05 run", "medusa-store", "0.1.0-test"}) {
    CAPTURE(value);
    const auto found = std::search(bytes.begin(), bytes.end(), value.begin(), value.end());
    REQUIRE(found != bytes.end());
    REQUIRE(std::search(found + 1, bytes.end(), value.begin(), value.end()) == bytes.end());
    const auto at = static_cast<std::size_t>(found - bytes.begin());
    check_flips(bytes, at, at + 1, bad);
    check_flips(bytes, at + value.size() / 2, at + value.size() / 2 + 1, bad);
  }
  // The name of the attribute written last, `complete`.
  const std::string name = "complete";
  const auto found = std::search(bytes.begin(), bytes.end(), name.begin(), name.end());
  REQUIRE(found != bytes.end());
  const auto at = static_cast<std::size_t>(found - bytes.begin());
  check_flips(bytes, at, at + name.size(), bad);
}
