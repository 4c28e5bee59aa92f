// An extendible, chunked, compressed and checksummed dataset written by appending rows (docs/FORMAT.md:
// every dataset of the store is one of these). Rows are buffered and written a chunk at a time, so a
// store is written while the medusa streams.
#pragma once

#include "medusa/medusa/internal/hdf5_handle.h"
#include "medusa/medusa/internal/hdf5_types.h"

#include <algorithm>
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
// that the same values give the same stored chunks however they are handed over. Values are written
// in order, a piece at a time, so that a caller need not gather them into one buffer first.
class SizedColumnBase {
public:
  SizedColumnBase(hid_t location, const std::string& name, hid_t file_type, hid_t memory_type,
                  std::size_t count, const std::string& path);
  // Writes the next `count` values. Throws StoreError past the size given at creation.
  void write(const void* data, std::size_t count);
  // Throws StoreError unless every value has been written: a column cut short must not look complete.
  void check_complete() const;
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

// A SizedColumnBase of T taking values one at a time, buffered a chunk at a time, so that each chunk is
// written whole.
template <class T> class SizedColumn : public SizedColumnBase {
public:
  SizedColumn(hid_t location, const std::string& name, std::size_t count, const std::string& path)
      : SizedColumnBase(location, name, TypeOf<T>::file(), TypeOf<T>::memory(), count, path) {
    piece_.reserve(std::min(count, chunk_values()));
  }
  void push(T value) {
    piece_.push_back(value);
    if (piece_.size() == chunk_values()) {
      write(piece_.data(), piece_.size());
      piece_.clear();
    }
  }
  // Writes what is buffered; throws StoreError unless the column is then complete.
  void finish() {
    write(piece_.data(), piece_.size());
    piece_.clear();
    check_complete();
  }

private:
  std::vector<T> piece_;
};

// Writes `count` values as the dataset `name` of `location` in one go (a SizedColumnBase).
void write_whole_column(hid_t location, const std::string& name, hid_t file_type, hid_t memory_type,
                        const void* data, std::size_t count, const std::string& path);

template <class T>
void write_column(hid_t location, const std::string& name, const std::vector<T>& values,
                  const std::string& path) {
  write_whole_column(location, name, TypeOf<T>::file(), TypeOf<T>::memory(), values.data(), values.size(),
                     path);
}

// Writes value(0), ..., value(count - 1) as the dataset `name` of `location`, converted to T a chunk at
// a time, so that a column of a large structure is never held whole beside it.
template <class T, class Value>
void write_column_of(hid_t location, const std::string& name, std::size_t count, Value value,
                     const std::string& path) {
  SizedColumn<T> column(location, name, count, path);
  for (std::size_t i = 0; i < count; ++i)
    column.push(static_cast<T>(value(i)));
  column.finish();
}

// Creates the group `name` under `parent`, without object timestamps.
Handle create_group(hid_t parent, const std::string& name, const std::string& path);

} // namespace medusa::h5
