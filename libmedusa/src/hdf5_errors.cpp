#include "medusa/medusa/internal/hdf5_errors.h"

#include "medusa/core/error.h"
#include "medusa/medusa/store_reader.h"

#include <vector>

namespace medusa::h5 {

Quiet::Quiet() {
  H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

Quiet::~Quiet() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }

namespace {

herr_t collect(unsigned /*n*/, const H5E_error2_t* err, void* data) {
  auto* lines = static_cast<std::vector<std::string>*>(data);
  if (err->desc && *err->desc)
    lines->emplace_back(err->desc);
  return 0;
}

} // namespace

std::string error_text() {
  std::vector<std::string> lines;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, collect, &lines);
  H5Eclear2(H5E_DEFAULT);
  std::string text;
  // The innermost two messages name the cause (e.g. a failed checksum or a system error).
  for (std::size_t i = 0; i < lines.size() && i < 2; ++i) {
    if (!text.empty())
      text += "; ";
    for (char c : lines[i])
      text += (c == '\n' || c == '\r') ? ' ' : c;
  }
  return text.empty() ? "HDF5 error" : text;
}

namespace {
bool details = false;
} // namespace

void set_error_details(bool on) { details = on; }

void fail(const std::string& path, const std::string& what) {
  // HDF5's own messages (errno, open flags, timestamps, internal function names) mean little to a
  // user: they are added only on request (`--verbose`).
  const std::string text = error_text();
  throw StoreError("store " + path + ": " + what + (details ? " (HDF5: " + text + ")" : ""));
}

} // namespace medusa::h5

namespace medusa {
void set_store_error_details(bool on) { h5::set_error_details(on); }
} // namespace medusa
