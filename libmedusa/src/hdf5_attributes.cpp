#include "medusa/medusa/internal/hdf5_attributes.h"

#include "medusa/medusa/internal/hdf5_errors.h"
#include "medusa/medusa/internal/hdf5_handle.h"
#include "medusa/medusa/internal/hdf5_types.h"

#include "medusa/core/error.h"

#include <algorithm>

namespace medusa::h5 {

namespace {

Handle string_type(std::size_t length) {
  Handle type = type_handle(H5Tcopy(H5T_C_S1));
  if (type.valid()) {
    H5Tset_size(type.get(), std::max<std::size_t>(1, length));
    H5Tset_strpad(type.get(), H5T_STR_NULLPAD);
    H5Tset_cset(type.get(), H5T_CSET_UTF8);
  }
  return type;
}

void write_raw(hid_t object, const std::string& name, hid_t file_type, hid_t memory_type, hid_t space,
               const void* data, const std::string& path) {
  if (H5Aexists(object, name.c_str()) > 0)
    H5Adelete(object, name.c_str());
  Handle attr =
      attribute_handle(H5Acreate2(object, name.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT));
  if (!attr.valid() || H5Awrite(attr.get(), memory_type, data) < 0)
    fail(path, "cannot write attribute " + name);
}

template <class T>
void write_scalar(hid_t object, const std::string& name, T value, const std::string& path) {
  Handle space = space_handle(H5Screate(H5S_SCALAR));
  write_raw(object, name, TypeOf<T>::file(), TypeOf<T>::memory(), space.get(), &value, path);
}

Handle open_attribute(hid_t object, const std::string& name, const std::string& path) {
  if (H5Aexists(object, name.c_str()) <= 0)
    throw StoreError("store " + path + ": attribute " + name + " is missing");
  Handle attr = attribute_handle(H5Aopen(object, name.c_str(), H5P_DEFAULT));
  if (!attr.valid())
    fail(path, "cannot open attribute " + name);
  return attr;
}

// Number of elements of the attribute's dataspace (1 for a scalar).
hssize_t element_count(hid_t attr) {
  Handle space = space_handle(H5Aget_space(attr));
  return space.valid() ? H5Sget_simple_extent_npoints(space.get()) : -1;
}

template <class T>
T read_number(hid_t object, const std::string& name, const std::string& path, H5T_class_t cls) {
  Handle attr = open_attribute(object, name, path);
  Handle type = type_handle(H5Aget_type(attr.get()));
  if (!type.valid() || H5Tget_class(type.get()) != cls || element_count(attr.get()) != 1)
    throw StoreError("store " + path + ": attribute " + name + " has the wrong type or shape");
  T value{};
  if (H5Aread(attr.get(), TypeOf<T>::memory(), &value) < 0)
    fail(path, "cannot read attribute " + name);
  return value;
}

} // namespace

void write_attribute(hid_t object, const std::string& name, std::int64_t value, const std::string& path) {
  write_scalar(object, name, value, path);
}
void write_attribute(hid_t object, const std::string& name, std::uint64_t value, const std::string& path) {
  write_scalar(object, name, value, path);
}
void write_attribute(hid_t object, const std::string& name, double value, const std::string& path) {
  write_scalar(object, name, value, path);
}

void write_attribute(hid_t object, const std::string& name, const std::string& value,
                     const std::string& path) {
  Handle type = string_type(value.size());
  Handle space = space_handle(H5Screate(H5S_SCALAR));
  std::string padded = value;
  padded.resize(std::max<std::size_t>(1, value.size()), '\0');
  write_raw(object, name, type.get(), type.get(), space.get(), padded.data(), path);
}

void write_attribute(hid_t object, const std::string& name, const std::vector<std::string>& values,
                     const std::string& path) {
  std::size_t width = 1;
  for (const std::string& v : values)
    width = std::max(width, v.size());
  Handle type = string_type(width);
  hsize_t dims[1] = {values.size()};
  Handle space = space_handle(H5Screate_simple(1, dims, nullptr));
  std::string packed(values.size() * width, '\0');
  for (std::size_t i = 0; i < values.size(); ++i)
    std::copy(values[i].begin(), values[i].end(), packed.begin() + static_cast<std::ptrdiff_t>(i * width));
  write_raw(object, name, type.get(), type.get(), space.get(), packed.data(), path);
}

std::int64_t read_int_attribute(hid_t object, const std::string& name, const std::string& path) {
  return read_number<std::int64_t>(object, name, path, H5T_INTEGER);
}
std::uint64_t read_uint_attribute(hid_t object, const std::string& name, const std::string& path) {
  return read_number<std::uint64_t>(object, name, path, H5T_INTEGER);
}
double read_double_attribute(hid_t object, const std::string& name, const std::string& path) {
  return read_number<double>(object, name, path, H5T_FLOAT);
}

std::vector<std::string> read_strings_attribute(hid_t object, const std::string& name,
                                                const std::string& path) {
  Handle attr = open_attribute(object, name, path);
  Handle type = type_handle(H5Aget_type(attr.get()));
  if (!type.valid() || H5Tget_class(type.get()) != H5T_STRING || H5Tis_variable_str(type.get()) != 0)
    throw StoreError("store " + path + ": attribute " + name + " is not a fixed-length string");
  const std::size_t width = H5Tget_size(type.get());
  const hssize_t count = element_count(attr.get());
  if (width == 0 || count < 0)
    throw StoreError("store " + path + ": attribute " + name + " has an invalid shape");
  std::string packed(static_cast<std::size_t>(count) * width, '\0');
  if (count > 0 && H5Aread(attr.get(), type.get(), packed.data()) < 0)
    fail(path, "cannot read attribute " + name);
  std::vector<std::string> values;
  for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) {
    std::string v = packed.substr(i * width, width);
    v.erase(std::find(v.begin(), v.end(), '\0'), v.end());
    values.push_back(std::move(v));
  }
  return values;
}

std::string read_string_attribute(hid_t object, const std::string& name, const std::string& path) {
  std::vector<std::string> values = read_strings_attribute(object, name, path);
  if (values.size() != 1)
    throw StoreError("store " + path + ": attribute " + name + " is not a single string");
  return values.front();
}

} // namespace medusa::h5
