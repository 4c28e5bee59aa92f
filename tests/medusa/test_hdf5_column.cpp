// Datasets of known size written a piece at a time (SizedColumn, write_column_of) against the same
// values written in one go.
#include "medusa/core/error.h"
#include "medusa/medusa/internal/hdf5_column.h"
#include "medusa/medusa/internal/hdf5_errors.h"
#include "medusa/medusa/internal/hdf5_handle.h"
#include "medusa/medusa/internal/hdf5_read.h"
#include "support/temp_files.h"

#include <catch2/catch.hpp>
#include <hdf5.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

using namespace medusa;

namespace {

struct Layout {
  hsize_t chunk = 0;
  hsize_t storage = 0;
};

Layout layout_of(hid_t group, const std::string& name) {
  h5::Handle dataset = h5::dataset_handle(H5Dopen2(group, name.c_str(), H5P_DEFAULT));
  REQUIRE(dataset.valid());
  h5::Handle dcpl = h5::plist_handle(H5Dget_create_plist(dataset.get()));
  Layout layout;
  REQUIRE(H5Pget_chunk(dcpl.get(), 1, &layout.chunk) == 1);
  layout.storage = H5Dget_storage_size(dataset.get());
  return layout;
}

} // namespace

TEST_CASE("A column written a chunk at a time reads back as its values, stored as if written in one go") {
  // 8,192 eight-byte values fill a chunk: a count that ends inside, one that ends on and one past a
  // chunk boundary, a single value and none.
  const medusa::test::TempDir dir("hdf5-column");
  const std::string path = dir.file("pieces.h5");
  h5::Handle file = h5::file_handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
  REQUIRE(file.valid());
  for (std::size_t count :
       {std::size_t{0}, std::size_t{1}, std::size_t{8191}, std::size_t{16384}, std::size_t{20000}}) {
    INFO("count " << count);
    std::vector<std::uint64_t> values;
    std::uint64_t next = 7 + count;
    for (std::size_t k = 0; k < count; ++k) {
      next = next * 6364136223846793005u + 1442695040888963407u;
      values.push_back(next >> 20);
    }
    const std::string name = "pieces" + std::to_string(count), whole = "whole" + std::to_string(count);
    h5::write_column_of<std::uint64_t>(
        file.get(), name, count, [&](std::size_t i) { return values[i]; }, path);
    h5::write_column(file.get(), whole, values, path);
    CHECK(h5::read_column<std::uint64_t>(file.get(), "", name, path) == values);
    const Layout pieces = layout_of(file.get(), name), one_go = layout_of(file.get(), whole);
    CHECK(pieces.chunk == std::max<std::size_t>(1, std::min<std::size_t>(count, 8192)));
    CHECK(pieces.chunk == one_go.chunk);
    CHECK(pieces.storage == one_go.storage);
  }
}

TEST_CASE("A sized column refuses values past the size it was created with") {
  const medusa::test::TempDir dir("hdf5-column");
  const std::string path = dir.file("sized.h5");
  h5::Handle file = h5::file_handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
  REQUIRE(file.valid());
  const std::vector<std::uint64_t> values = {1, 2, 3, 4};
  h5::SizedColumnBase column(file.get(), "sized", H5T_STD_U64LE, H5T_NATIVE_UINT64, 3, path);
  column.write(values.data(), 2);
  CHECK_THROWS_AS(column.check_complete(), StoreError);
  CHECK_THROWS_AS(column.write(values.data() + 2, 2), StoreError);
  column.write(values.data() + 2, 1);
  CHECK(column.written() == 3);
  CHECK_NOTHROW(column.check_complete());
  CHECK_THROWS_AS(column.write(values.data(), 1), StoreError);
  CHECK(h5::read_column<std::uint64_t>(file.get(), "", "sized", path) == std::vector<std::uint64_t>{1, 2, 3});
}

TEST_CASE("A sized column finished short of its size is a store error, not a column padded with zeros") {
  const medusa::test::TempDir dir("hdf5-column");
  const std::string path = dir.file("short.h5");
  h5::Handle file = h5::file_handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
  REQUIRE(file.valid());
  h5::SizedColumn<std::uint64_t> short_column(file.get(), "short", 3, path);
  short_column.push(1);
  short_column.push(2);
  CHECK_THROWS_AS(short_column.finish(), StoreError);
}
