#include "medusa/medusa/internal/hdf5_column.h"

#include "medusa/medusa/internal/hdf5_errors.h"

#include <algorithm>

namespace medusa::h5 {

namespace {
// About 64 KiB per chunk for 8-byte values: large enough for good compression, small enough that a
// streaming writer's buffers stay small (docs/MATH.md §6.5).
constexpr std::size_t chunk_bytes = 65536;

// Every column of a store is a chunked dataset, shuffled, deflated and checksummed, growable along
// its rows. track_times: whether it records its times (HDF5's default); sized columns do not, as
// groups do not.
Handle create_column(hid_t location, const std::string& name, hid_t file_type, int rank, const hsize_t* dims,
                     const hsize_t* max_dims, const hsize_t* chunk, bool track_times,
                     const std::string& path) {
  Handle space = space_handle(H5Screate_simple(rank, dims, max_dims));
  Handle dcpl = plist_handle(H5Pcreate(H5P_DATASET_CREATE));
  if (!space.valid() || !dcpl.valid() || H5Pset_chunk(dcpl.get(), rank, chunk) < 0 ||
      H5Pset_shuffle(dcpl.get()) < 0 || H5Pset_deflate(dcpl.get(), 6) < 0 ||
      H5Pset_fletcher32(dcpl.get()) < 0 || (!track_times && H5Pset_obj_track_times(dcpl.get(), 0) < 0))
    fail(path, "cannot set up dataset " + name);
  Handle dataset = dataset_handle(
      H5Dcreate2(location, name.c_str(), file_type, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT));
  if (!dataset.valid())
    fail(path, "cannot create dataset " + name);
  return dataset;
}
} // namespace

ColumnBase::ColumnBase(hid_t location, const std::string& name, hid_t file_type, hid_t memory_type,
                       std::size_t width, const std::string& path)
    : width_(width), memory_type_(memory_type), name_(name), path_(path) {
  chunk_rows_ = std::max<std::size_t>(1, chunk_bytes / (H5Tget_size(file_type) * width));
  const int rank = width == 1 ? 1 : 2;
  hsize_t dims[2] = {0, width};
  hsize_t max_dims[2] = {H5S_UNLIMITED, width};
  hsize_t chunk[2] = {chunk_rows_, width};
  dataset_ = create_column(location, name, file_type, rank, dims, max_dims, chunk, true, path_);
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

SizedColumnBase::SizedColumnBase(hid_t location, const std::string& name, hid_t file_type, hid_t memory_type,
                                 std::size_t count, const std::string& path)
    : memory_type_(memory_type), name_(name), path_(path), size_(count) {
  const hsize_t size = count;
  const hsize_t max_size = H5S_UNLIMITED;
  const hsize_t chunk = std::max<hsize_t>(1, std::min<hsize_t>(size, chunk_bytes / H5Tget_size(file_type)));
  chunk_ = static_cast<std::size_t>(chunk);
  dataset_ = create_column(location, name, file_type, 1, &size, &max_size, &chunk, false, path_);
}

void SizedColumnBase::write(const void* data, std::size_t count) {
  if (count > size_ - written_)
    fail(path_, "cannot write " + std::to_string(count) + " more values to dataset " + name_ + " of " +
                    std::to_string(size_));
  if (count == 0)
    return;
  Handle file_space = space_handle(H5Dget_space(dataset_.get()));
  const hsize_t start = written_, rows = count;
  Handle memory_space = space_handle(H5Screate_simple(1, &rows, nullptr));
  if (!file_space.valid() || !memory_space.valid() ||
      H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, &start, nullptr, &rows, nullptr) < 0 ||
      H5Dwrite(dataset_.get(), memory_type_, memory_space.get(), file_space.get(), H5P_DEFAULT, data) < 0)
    fail(path_, "cannot write dataset " + name_);
  written_ += count;
}

void SizedColumnBase::check_complete() const {
  if (written_ != size_)
    fail(path_, "dataset " + name_ + " has " + std::to_string(written_) + " of its " + std::to_string(size_) +
                    " values");
}

void write_whole_column(hid_t location, const std::string& name, hid_t file_type, hid_t memory_type,
                        const void* data, std::size_t count, const std::string& path) {
  SizedColumnBase(location, name, file_type, memory_type, count, path).write(data, count);
}

Handle create_group(hid_t parent, const std::string& name, const std::string& path) {
  Handle gcpl = plist_handle(H5Pcreate(H5P_GROUP_CREATE));
  if (!gcpl.valid() || H5Pset_obj_track_times(gcpl.get(), 0) < 0)
    fail(path, "cannot set up group " + name);
  Handle group = group_handle(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, gcpl.get(), H5P_DEFAULT));
  if (!group.valid())
    fail(path, "cannot create group " + name);
  return group;
}

} // namespace medusa::h5
