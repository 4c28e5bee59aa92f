#include "run_outputs.h"

#include "medusa/core/error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <random>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace medusa::cli {

namespace fs = std::filesystem;

namespace {

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode))
    return "a folder";
  if (S_ISCHR(mode) || S_ISBLK(mode))
    return "a device";
  if (S_ISFIFO(mode))
    return "a FIFO";
  if (S_ISSOCK(mode))
    return "a socket";
  return "not a regular file";
}

bool same_file(const std::string& a, const std::string& b) {
  struct stat sa {
  }, sb{};
  return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
         sa.st_ino == sb.st_ino;
}

// The absolute, normalised form of a path whose last component may not exist yet.
fs::path absolute_of(const std::string& path) {
  std::error_code ec;
  const fs::path p = fs::absolute(path, ec);
  const fs::path parent = fs::weakly_canonical(p.parent_path(), ec);
  return (ec ? p.parent_path() : parent) / p.filename();
}

bool inside(const fs::path& path, const fs::path& folder) {
  auto f = folder.begin(), p = path.begin();
  for (; f != folder.end(); ++f, ++p)
    if (p == path.end() || *p != *f)
      return false;
  return true;
}

// An output inside the input folder at a name its reader reads (docs/FORMAT.md: cells.csv[.gz],
// LatticeData/, Simulation/) would replace the input, or be read by the next run of the folder.
void check_input_folder(const std::string& output, const std::string& input) {
  std::error_code ec;
  if (!fs::is_directory(input, ec))
    return;
  const fs::path folder = fs::weakly_canonical(fs::absolute(input, ec), ec);
  const fs::path out = absolute_of(output);
  const bool read_there = out == folder / "cells.csv.gz" || out == folder / "cells.csv" ||
                          inside(out, folder / "LatticeData") || inside(out, folder / "Simulation");
  if (read_there)
    throw UsageError("output " + output + " is inside the input folder " + input +
                     " where its files are read; write it elsewhere");
}

} // namespace

std::string regular_output_name(const std::string& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0)
    return path; // a new file
  if (S_ISLNK(st.st_mode)) {
    struct stat target {};
    if (::stat(path.c_str(), &target) != 0)
      throw UsageError("output " + path + " is a symbolic link to nothing; medusa writes regular files only");
    if (!S_ISREG(target.st_mode))
      throw UsageError("output " + path + " is a symbolic link to " + kind_of(target.st_mode) +
                       "; medusa writes regular files only");
    std::error_code ec;
    const fs::path resolved = fs::canonical(path, ec);
    if (ec)
      throw UsageError("output " + path + ": cannot resolve the symbolic link (" + ec.message() + ")");
    return resolved.string();
  }
  if (!S_ISREG(st.st_mode))
    throw UsageError("output " + path + " is " + kind_of(st.st_mode) + "; medusa writes regular files only");
  return path;
}

std::string new_run_id() {
  std::random_device device;
  std::string id;
  static const char* digits = "0123456789abcdef";
  for (int word = 0; word < 4; ++word) {
    const std::uint32_t bits = device();
    for (int k = 7; k >= 0; --k)
      id += digits[(bits >> (4 * k)) & 0xF];
  }
  return id;
}

RunOutputs::RunOutputs(const std::string& store, const std::vector<std::string>& side_outputs,
                       const std::string& input) {
  std::vector<std::string> given = {store};
  given.insert(given.end(), side_outputs.begin(), side_outputs.end());
  const std::string pid = std::to_string(static_cast<long long>(::getpid()));
  for (const std::string& path : given) {
    const std::string name = regular_output_name(path);
    if (same_file(name, input))
      throw UsageError("output " + path + " is the input " + input + "; write it elsewhere");
    check_input_folder(name, input);
    finals_.push_back(name);
    temporaries_.push_back(name + ".tmp-" + pid);
  }
  for (std::size_t i = 0; i < finals_.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (absolute_of(finals_[i]) == absolute_of(finals_[j]))
        throw UsageError("outputs " + given[j] + " and " + given[i] + " are the same file");

  // flock: released by the kernel when the process ends, however it ends. The file is removed at the
  // end; a run that opened it before then finds, once it holds the lock, that the name now leads to
  // another file (or none) and starts again.
  lock_path_ = finals_[0] + ".lock";
  for (;;) {
    lock_fd_ = ::open(lock_path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (lock_fd_ < 0)
      throw StoreError("store " + store + ": cannot create the lock file " + lock_path_ + " (" +
                       std::strerror(errno) + ")");
    if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
      ::close(lock_fd_);
      lock_fd_ = -1;
      throw StoreError("store " + store + ": another medusa run is writing it (lock file " + lock_path_ +
                       "); wait for it to end or choose another -o");
    }
    struct stat held {
    }, named{};
    if (::fstat(lock_fd_, &held) == 0 && ::stat(lock_path_.c_str(), &named) == 0 &&
        held.st_dev == named.st_dev && held.st_ino == named.st_ino)
      break;
    ::close(lock_fd_);
    lock_fd_ = -1;
  }
}

RunOutputs::~RunOutputs() {
  if (!published_)
    for (const std::string& t : temporaries_)
      std::remove(t.c_str());
  if (lock_fd_ >= 0) {
    ::unlink(lock_path_.c_str());
    ::close(lock_fd_);
  }
}

void RunOutputs::check_not_read(const std::vector<std::string>& sources) const {
  for (const std::string& out : finals_)
    for (const std::string& source : sources)
      if (same_file(out, source))
        throw UsageError("output " + out + " is the input file " + source + "; write it elsewhere");
}

void RunOutputs::publish() {
  for (std::size_t i = 0; i < finals_.size(); ++i)
    if (std::rename(temporaries_[i].c_str(), finals_[i].c_str()) != 0) {
      const std::string why = std::strerror(errno);
      for (std::size_t j = i; j < finals_.size(); ++j)
        std::remove(temporaries_[j].c_str());
      published_ = true;
      throw StoreError("store " + finals_[0] + ": cannot rename " + temporaries_[i] + " to " + finals_[i] +
                       " (" + why + ")");
    }
  published_ = true;
}

} // namespace medusa::cli
