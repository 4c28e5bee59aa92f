// Datasets of known size written a piece at a time (SizedColumn, write_list_columns) against the same
// values written in one go.
#include "medusa/core/error.h"
#include "medusa/medusa/internal/hdf5_column.h"
#include "medusa/medusa/internal/hdf5_errors.h"
#include "medusa/medusa/internal/hdf5_handle.h"
#include "medusa/medusa/internal/hdf5_read.h"
#include "support/temp_files.h"

#include <catch2/catch.hpp>
#include <hdf5.h>

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

TEST_CASE("Lists written a chunk at a time read back as their concatenation, stored as written in one go") {
  // 8,192 eight-byte values fill a chunk: lists that end inside, on and across chunk boundaries, and
  // empty ones, including an empty last list.
  const std::vector<std::size_t> sizes = {0, 8191, 1, 8193, 0, 20000, 3, 0};
  std::vector<std::vector<std::uint64_t>> lists;
  std::vector<std::uint64_t> flat, offsets = {0};
  std::uint64_t next = 7;
  for (std::size_t size : sizes) {
    lists.emplace_back();
    for (std::size_t k = 0; k < size; ++k) {
      next = next * 6364136223846793005u + 1442695040888963407u;
      lists.back().push_back(next >> 20);
      flat.push_back(next >> 20);
    }
    offsets.push_back(flat.size());
  }
  const medusa::test::TempDir dir("hdf5-column");
  const std::string path = dir.file("lists.h5");
  h5::Handle file = h5::file_handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
  REQUIRE(file.valid());
  h5::write_list_columns<std::uint64_t>(file.get(), "offset", "value", lists, path);
  h5::write_column(file.get(), "whole", flat, path);
  CHECK(h5::read_column<std::uint64_t>(file.get(), "", "offset", path) == offsets);
  CHECK(h5::read_column<std::uint64_t>(file.get(), "", "value", path) == flat);
  const Layout pieces = layout_of(file.get(), "value"), whole = layout_of(file.get(), "whole");
  CHECK(pieces.chunk == 8192);
  CHECK(pieces.chunk == whole.chunk);
  CHECK(pieces.storage == whole.storage);
}

TEST_CASE("A sized column refuses values past the size it was created with") {
  const medusa::test::TempDir dir("hdf5-column");
  const std::string path = dir.file("sized.h5");
  h5::Handle file = h5::file_handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
  REQUIRE(file.valid());
  const std::vector<std::uint64_t> values = {1, 2, 3, 4};
  h5::SizedColumn column(file.get(), "sized", H5T_STD_U64LE, H5T_NATIVE_UINT64, 3, path);
  column.write(values.data(), 2);
  CHECK_THROWS_AS(column.write(values.data() + 2, 2), StoreError);
  column.write(values.data() + 2, 1);
  CHECK(column.written() == 3);
  CHECK_THROWS_AS(column.write(values.data(), 1), StoreError);
  CHECK(h5::read_column<std::uint64_t>(file.get(), "", "sized", path) == std::vector<std::uint64_t>{1, 2, 3});
}
