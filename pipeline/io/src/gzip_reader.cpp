#include "medusa/io/gzip_reader.h"

#include "medusa/core/error.h"

#include <cstdio>
#include <cstring>
#include <zlib.h>

namespace medusa::io {

namespace {
constexpr std::size_t chunk = 1 << 16;
gzFile gz(void* f) { return static_cast<gzFile>(f); }
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
} // namespace

GzipReader::GzipReader(std::string path) : path_(std::move(path)), buf_(2 * chunk) {
  // zlib reads a file that is not gzip as plain text; one named .gz must be gzip, else its bytes
  // would be taken for the data.
  if (path_.size() > 3 && path_.compare(path_.size() - 3, 3, ".gz") == 0) {
    std::FILE* raw = std::fopen(path_.c_str(), "rb");
    if (raw == nullptr)
      throw InputError(path_ + ": cannot open file (" + std::strerror(errno) + ")");
    unsigned char magic[2] = {0, 0};
    const std::size_t got = std::fread(magic, 1, 2, raw);
    std::fclose(raw);
    if (got == 2 && (magic[0] != 0x1F || magic[1] != 0x8B))
      throw InputError(path_ + ": not a gzip file (its name ends in .gz but its first bytes are not gzip's)");
  }
  file_ = gzopen(path_.c_str(), "rb");
  if (file_ == nullptr)
    throw InputError(path_ + ": cannot open file (" + std::strerror(errno) + ")");
  gzbuffer(gz(file_), chunk);
}

GzipReader::~GzipReader() {
  if (file_ != nullptr)
    gzclose_r(gz(file_));
}

void GzipReader::fail(const std::string& why) const {
  throw InputError(path_ + ": " + why + " near line " + std::to_string(line_));
}

bool GzipReader::fill() {
  if (!pending_error_.empty())
    fail(pending_error_);
  if (eof_)
    return false;
  if (pos_ > 0) {
    std::memmove(buf_.data(), buf_.data() + pos_, end_ - pos_);
    end_ -= pos_;
    pos_ = 0;
  }
  if (buf_.size() - end_ < chunk)
    buf_.resize(buf_.size() + chunk);
  const int got = gzread(gz(file_), buf_.data() + end_, static_cast<unsigned>(buf_.size() - end_));
  int err = Z_OK;
  const char* message = gzerror(gz(file_), &err);
  // zlib reports a truncated stream as Z_BUF_ERROR ("unexpected end of file") and a corrupt one as
  // Z_DATA_ERROR; both must stop the reader rather than pass as an early end of file. The bytes
  // decoded before the damage are handed out first, so the error names the line where the data stop,
  // not the first line of the last block read.
  if (got < 0 || (err != Z_OK && err != Z_STREAM_END)) {
    const std::string why = std::string("corrupt or truncated gzip data (") +
                            (err == Z_ERRNO ? std::strerror(errno) : message) + ")";
    if (got <= 0)
      fail(why);
    pending_error_ = why;
  }
  if (got == 0) {
    eof_ = true;
    return false;
  }
  end_ += static_cast<std::size_t>(got);
  return true;
}

bool GzipReader::next_line(std::string& out) {
  out.clear();
  std::size_t scanned = pos_;
  for (;;) {
    const void* nl = std::memchr(buf_.data() + scanned, '\n', end_ - scanned);
    if (nl != nullptr) {
      const std::size_t at = static_cast<const char*>(nl) - buf_.data();
      out.assign(buf_.data() + pos_, at - pos_);
      pos_ = at + 1;
      break;
    }
    const std::size_t before = end_ - pos_;
    if (before > max_line_bytes)
      throw InputError(path_ + ":" + std::to_string(line_) + ": line longer than " +
                       std::to_string(max_line_bytes >> 20) + " MiB (not a text file of the expected kind?)");
    if (!fill()) {
      if (pos_ == end_)
        return false;
      out.assign(buf_.data() + pos_, end_ - pos_);
      pos_ = end_;
      break;
    }
    scanned = pos_ + before;
  }
  if (!out.empty() && out.back() == '\r')
    out.pop_back();
  last_line_ = line_++;
  return true;
}

bool GzipReader::next_token(std::string_view& out) {
  for (;;) {
    while (pos_ < end_ && is_space(buf_[pos_])) {
      if (buf_[pos_] == '\n')
        ++line_;
      ++pos_;
    }
    if (pos_ < end_)
      break;
    if (!fill())
      return false;
  }
  std::size_t stop = pos_;
  for (;;) {
    while (stop < end_ && !is_space(buf_[stop]))
      ++stop;
    if (stop < end_)
      break;
    const std::size_t length = stop - pos_;
    if (length > max_line_bytes)
      throw InputError(path_ + ":" + std::to_string(line_) + ": a value longer than " +
                       std::to_string(max_line_bytes >> 20) + " MiB (not a text file of the expected kind?)");
    if (!fill()) {
      stop = pos_ + length;
      break;
    }
    stop = pos_ + length;
  }
  out = std::string_view(buf_.data() + pos_, stop - pos_);
  pos_ = stop;
  last_line_ = line_;
  return true;
}

void GzipReader::read_bytes(char* out, std::size_t n) {
  while (n > 0) {
    if (pos_ == end_ && !fill())
      fail("file ends inside binary data (" + std::to_string(n) + " bytes missing)");
    const std::size_t take = std::min(n, end_ - pos_);
    std::memcpy(out, buf_.data() + pos_, take);
    out += take;
    pos_ += take;
    n -= take;
  }
}

} // namespace medusa::io
