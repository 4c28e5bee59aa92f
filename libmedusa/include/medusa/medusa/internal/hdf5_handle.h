// RAII ownership of an HDF5 identifier (file, group, dataset, dataspace, type, property list).
#pragma once

#include <hdf5.h>

#include <utility>

namespace medusa::h5 {

class Handle {
public:
  using Closer = herr_t (*)(hid_t);

  Handle() = default;
  Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, -1)), closer_(other.closer_) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, -1);
      closer_ = other.closer_;
    }
    return *this;
  }
  ~Handle() { reset(); }

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  // Closes now; returns false when HDF5 reports an error (e.g. the final flush of a file failed).
  bool reset() {
    bool ok = true;
    if (id_ >= 0 && closer_)
      ok = closer_(id_) >= 0;
    id_ = -1;
    return ok;
  }

private:
  hid_t id_ = -1;
  Closer closer_ = nullptr;
};

inline Handle file_handle(hid_t id) { return Handle(id, H5Fclose); }
inline Handle group_handle(hid_t id) { return Handle(id, H5Gclose); }
inline Handle dataset_handle(hid_t id) { return Handle(id, H5Dclose); }
inline Handle space_handle(hid_t id) { return Handle(id, H5Sclose); }
inline Handle type_handle(hid_t id) { return Handle(id, H5Tclose); }
inline Handle plist_handle(hid_t id) { return Handle(id, H5Pclose); }
inline Handle attribute_handle(hid_t id) { return Handle(id, H5Aclose); }

} // namespace medusa::h5
