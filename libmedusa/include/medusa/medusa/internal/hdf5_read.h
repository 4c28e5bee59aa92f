// Reading whole datasets of the store (docs/FORMAT.md).
#pragma once

#include "medusa/medusa/internal/hdf5_errors.h"
#include "medusa/medusa/internal/hdf5_handle.h"
#include "medusa/medusa/internal/hdf5_types.h"

#include "medusa/core/error.h"

#include <string>
#include <vector>

namespace medusa::h5 {

// Reads dataset `name` of `group` (shape (n) when width is 1, else (n, width)) as T. The HDF5 class
// (integer or float) must match T's; values are converted to T's width by HDF5, which fails on overflow
// rather than wrapping. Throws StoreError naming the store and the dataset.
template <class T>
std::vector<T> read_column(hid_t group, const std::string& group_name, const std::string& name,
                           const std::string& path, std::size_t width = 1) {
  const std::string full = "/" + group_name + "/" + name;
  if (H5Lexists(group, name.c_str(), H5P_DEFAULT) <= 0)
    throw StoreError("store " + path + ": dataset " + full + " is missing");
  Handle dataset = dataset_handle(H5Dopen2(group, name.c_str(), H5P_DEFAULT));
  if (!dataset.valid())
    fail(path, "cannot open dataset " + full);
  Handle type = type_handle(H5Dget_type(dataset.get()));
  Handle space = space_handle(H5Dget_space(dataset.get()));
  if (!type.valid() || !space.valid())
    fail(path, "cannot inspect dataset " + full);
  const H5T_class_t expected = TypeOf<T>::file() == H5T_IEEE_F64LE ? H5T_FLOAT : H5T_INTEGER;
  const int rank = H5Sget_simple_extent_ndims(space.get());
  hsize_t dims[2] = {0, 0};
  if (H5Tget_class(type.get()) != expected || rank != (width == 1 ? 1 : 2) ||
      H5Sget_simple_extent_dims(space.get(), dims, nullptr) < 0 || (width != 1 && dims[1] != width))
    throw StoreError("store " + path + ": dataset " + full + " has the wrong type or shape");
  std::vector<T> values(static_cast<std::size_t>(dims[0]) * width);
  if (!values.empty() &&
      H5Dread(dataset.get(), TypeOf<T>::memory(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
    fail(path, "cannot read dataset " + full);
  return values;
}

} // namespace medusa::h5
