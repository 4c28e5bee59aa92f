// HDF5 error reporting: silence the library's own printing while medusa calls it, and turn its error
// stack into the text of a one-line StoreError.
#pragma once

#include <hdf5.h>

#include <string>

namespace medusa::h5 {

// Switches HDF5's automatic error printing off for the lifetime of the object (restored after).
class Quiet {
public:
  Quiet();
  ~Quiet();
  Quiet(const Quiet&) = delete;
  Quiet& operator=(const Quiet&) = delete;

private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

// The most specific messages of the current HDF5 error stack, on one line ("" when empty).
std::string error_text();

// Whether fail() adds the HDF5 error stack to its message (off by default).
void set_error_details(bool on);

// Throws StoreError("store <path>: <what>"), with " (HDF5: <text>)" when details are on.
[[noreturn]] void fail(const std::string& path, const std::string& what);

} // namespace medusa::h5
