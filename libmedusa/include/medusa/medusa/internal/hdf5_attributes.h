// Attributes of the store (docs/FORMAT.md). Strings are fixed-length (NUL padded, UTF-8), so they live
// in the checksummed object header rather than the unchecksummed global heap.
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

namespace medusa::h5 {

void write_attribute(hid_t object, const std::string& name, std::int64_t value, const std::string& path);
void write_attribute(hid_t object, const std::string& name, std::uint64_t value, const std::string& path);
void write_attribute(hid_t object, const std::string& name, double value, const std::string& path);
void write_attribute(hid_t object, const std::string& name, const std::string& value,
                     const std::string& path);
void write_attribute(hid_t object, const std::string& name, const std::vector<std::string>& values,
                     const std::string& path);

// Readers throw StoreError naming the store and the attribute when it is missing or of another kind.
std::int64_t read_int_attribute(hid_t object, const std::string& name, const std::string& path);
std::uint64_t read_uint_attribute(hid_t object, const std::string& name, const std::string& path);
double read_double_attribute(hid_t object, const std::string& name, const std::string& path);
std::string read_string_attribute(hid_t object, const std::string& name, const std::string& path);
std::vector<std::string> read_strings_attribute(hid_t object, const std::string& name,
                                                const std::string& path);

} // namespace medusa::h5
