// Sequential reader of plain or gzip-compressed files (zlib's gzopen reads both), by lines, by
// whitespace-separated tokens, or as raw bytes (binary legacy VTK). Truncated or corrupt gzip data
// is an InputError naming the file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace medusa::io {

// No line or token of a CompuCell3D text file comes near this; a longer one is refused (naming its
// line) before it takes memory in proportion to a decompressed size that can be 1000 times the file's.
inline constexpr std::size_t max_line_bytes = std::size_t(1) << 20;

class GzipReader {
public:
  explicit GzipReader(std::string path); // InputError if the file cannot be opened
  ~GzipReader();
  GzipReader(const GzipReader&) = delete;
  GzipReader& operator=(const GzipReader&) = delete;

  const std::string& path() const { return path_; }
  // 1-based number of the line that holds the last line or token returned.
  std::int64_t line() const { return last_line_; }

  // Next line without its end-of-line characters ("\n" or "\r\n"); false at end of file.
  bool next_line(std::string& out);
  // Next whitespace-separated token, valid until the next call; false at end of file.
  bool next_token(std::string_view& out);
  // Exactly n raw bytes; InputError if the file ends first.
  void read_bytes(char* out, std::size_t n);

private:
  bool fill(); // appends data after end_; false at end of file; InputError on a zlib error
  [[noreturn]] void fail(const std::string& why) const;

  std::string path_;
  void* file_ = nullptr; // gzFile, kept opaque so that zlib stays a private dependency
  std::vector<char> buf_;
  std::size_t pos_ = 0, end_ = 0;
  std::int64_t line_ = 1;      // line of the cursor
  std::int64_t last_line_ = 0; // line of the last item returned
  bool eof_ = false;
  std::string pending_error_; // a zlib error met after some bytes were decoded: raised at the next fill
};

} // namespace medusa::io
