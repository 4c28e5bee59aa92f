#include "hdf5_column.h"

#include "hdf5_errors.h"

#include <algorithm>

namespace medusa::h5 {

namespace {
// About 64 KiB per chunk for 8-byte values: large enough for good compression, small enough that a
// streaming writer's buffers stay small (docs/MATH.md §6.5).
constexpr std::size_t chunk_bytes = 65536;
} // namespace

ColumnBase::ColumnBase(hid_t location, const std::string& name, hid_t file_type, hid_t memory_type,
                       std::size_t width, const std::string& path)
    : width_(width), memory_type_(memory_type), name_(name), path_(path) {
  chunk_rows_ = std::max<std::size_t>(1, chunk_bytes / (H5Tget_size(file_type) * width));
  const int rank = width == 1 ? 1 : 2;
  hsize_t dims[2] = {0, width};
  hsize_t max_dims[2] = {H5S_UNLIMITED, width};
  hsize_t chunk[2] = {chunk_rows_, width};
  Handle space = space_handle(H5Screate_simple(rank, dims, max_dims));
  Handle dcpl = plist_handle(H5Pcreate(H5P_DATASET_CREATE));
  if (!space.valid() || !dcpl.valid() || H5Pset_chunk(dcpl.get(), rank, chunk) < 0 ||
      H5Pset_shuffle(dcpl.get()) < 0 || H5Pset_deflate(dcpl.get(), 6) < 0 ||
      H5Pset_fletcher32(dcpl.get()) < 0)
    fail(path_, "cannot set up dataset " + name_);
  dataset_ = dataset_handle(
      H5Dcreate2(location, name.c_str(), file_type, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT));
  if (!dataset_.valid())
    fail(path_, "cannot create dataset " + name_);
}

void ColumnBase::write(const void* data, std::size_t rows) {
  const int rank = width_ == 1 ? 1 : 2;
  hsize_t new_dims[2] = {written_ + rows, width_};
  if (H5Dset_extent(dataset_.get(), new_dims) < 0)
    fail(path_, "cannot extend dataset " + name_);
  Handle file_space = space_handle(H5Dget_space(dataset_.get()));
  hsize_t start[2] = {written_, 0};
  hsize_t count[2] = {rows, width_};
  Handle memory_space = space_handle(H5Screate_simple(rank, count, nullptr));
  if (!file_space.valid() || !memory_space.valid() ||
      H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr) < 0 ||
      H5Dwrite(dataset_.get(), memory_type_, memory_space.get(), file_space.get(), H5P_DEFAULT, data) < 0)
    fail(path_, "cannot write dataset " + name_);
  written_ += rows;
}

} // namespace medusa::h5
