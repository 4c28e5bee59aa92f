// An extendible, chunked, compressed and checksummed dataset written by appending rows (docs/FORMAT.md:
// every dataset of the store is one of these). Rows are buffered and written a chunk at a time, so a
// store is written while the medusa streams.
#pragma once

#include "medusa/medusa/internal/hdf5_handle.h"
#include "medusa/medusa/internal/hdf5_types.h"

#include <cstddef>
#include <string>
#include <vector>

namespace medusa::h5 {

class ColumnBase {
public:
  // Creates the dataset `name` under `location`, of shape (0) or (0, width), unlimited rows.
  ColumnBase(hid_t location, const std::string& name, hid_t file_type, hid_t memory_type, std::size_t width,
             const std::string& path);
  std::size_t rows() const { return written_; }
  const std::string& name() const { return name_; }

protected:
  void write(const void* data, std::size_t rows);
  std::size_t width_ = 1;
  std::size_t chunk_rows_ = 0;

private:
  Handle dataset_;
  hid_t memory_type_ = -1;
  std::string name_;
  std::string path_;
  std::size_t written_ = 0;
};

template <class T> class Column : public ColumnBase {
public:
  Column(hid_t location, const std::string& name, const std::string& path, std::size_t width = 1)
      : ColumnBase(location, name, TypeOf<T>::file(), TypeOf<T>::memory(), width, path) {}

  void push(T value) {
    buffer_.push_back(value);
    if (buffer_.size() >= chunk_rows_ * width_)
      flush();
  }
  void flush() {
    if (buffer_.empty())
      return;
    write(buffer_.data(), buffer_.size() / width_);
    buffer_.clear();
  }
  std::size_t size() const { return rows() + buffer_.size() / width_; }

private:
  std::vector<T> buffer_;
};

// A dataset of `count` values known in advance, with Column's layout and without object timestamps, so
// that the same values give byte-identical objects however they are handed over. Values are written in
// order, a piece at a time, so that a caller need not gather them into one buffer first.
class SizedColumn {
public:
  SizedColumn(hid_t location, const std::string& name, hid_t file_type, hid_t memory_type, std::size_t count,
              const std::string& path);
  // Writes the next `count` values. Throws StoreError past the size given at creation.
  void write(const void* data, std::size_t count);
  // Values per chunk: pieces of this many values each fill whole chunks.
  std::size_t chunk_values() const { return chunk_; }
  std::size_t written() const { return written_; }

private:
  Handle dataset_;
  hid_t memory_type_ = -1;
  std::string name_;
  std::string path_;
  std::size_t size_ = 0;
  std::size_t chunk_ = 1;
  std::size_t written_ = 0;
};

// Writes `count` values as the dataset `name` of `location` in one go (a SizedColumn).
void write_whole_column(hid_t location, const std::string& name, hid_t file_type, hid_t memory_type,
                        const void* data, std::size_t count, const std::string& path);

template <class T>
void write_column(hid_t location, const std::string& name, const std::vector<T>& values,
                  const std::string& path) {
  write_whole_column(location, name, TypeOf<T>::file(), TypeOf<T>::memory(), values.data(), values.size(),
                     path);
}

// Writes lists of values as two datasets of `location`: `offsets_name`, where list i is values
// [offsets[i], offsets[i + 1]), then `values_name`, the lists one after another converted to T a chunk
// at a time, so that their concatenation is never held in memory.
template <class T, class Lists>
void write_list_columns(hid_t location, const std::string& offsets_name, const std::string& values_name,
                        const Lists& lists, const std::string& path) {
  std::vector<T> offsets;
  offsets.reserve(lists.size() + 1);
  offsets.push_back(0);
  for (const auto& list : lists)
    offsets.push_back(offsets.back() + static_cast<T>(list.size()));
  write_column(location, offsets_name, offsets, path);
  SizedColumn values(location, values_name, TypeOf<T>::file(), TypeOf<T>::memory(),
                     static_cast<std::size_t>(offsets.back()), path);
  std::vector<T>().swap(offsets);
  std::vector<T> piece;
  piece.reserve(values.chunk_values());
  for (const auto& list : lists)
    for (const auto& value : list) {
      piece.push_back(static_cast<T>(value));
      if (piece.size() == values.chunk_values()) {
        values.write(piece.data(), piece.size());
        piece.clear();
      }
    }
  values.write(piece.data(), piece.size());
}

// Creates the group `name` under `parent`, without object timestamps.
Handle create_group(hid_t parent, const std::string& name, const std::string& path);

} // namespace medusa::h5
