// The files one `medusa run` produces (store, diagrams CSV, barcode SVG, timings JSON), made one
// atomic result (docs/FORMAT.md, "One result per run"): each is written complete under a temporary
// name in its destination folder, and all are renamed into place together at the end, the store
// first; a lock file beside the store keeps a second run off the same names meanwhile. Every
// output is stamped with the run's random id, so that a set mixed by a kill during the renames is
// refused by its readers.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace medusa::cli {

// A bad command-line value found after parsing (an output that cannot be written safely): exit 2.
class UsageError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// The name to write the output `path` under: itself when new or a regular file, or the regular file
// a symbolic link there leads to. A device, FIFO, socket, folder or dangling link (or a link to one of
// them) is a UsageError: renaming over it would replace a device node such as /dev/stdout, and opening
// a FIFO waits for a reader.
std::string regular_output_name(const std::string& path);

// 128 random bits as 32 lowercase hex digits.
std::string new_run_id();

class RunOutputs {
public:
  // `store`, then the side outputs. Each must be a new name or a regular file (a symbolic link to
  // one is written through); a device, FIFO, socket, folder, dangling link, or the input itself (or
  // a file the input folder's reader would read) is a UsageError. Then takes `<store>.lock`;
  // StoreError if another run holds it or it cannot be created.
  RunOutputs(const std::string& store, const std::vector<std::string>& side_outputs,
             const std::string& input);
  // Removes every temporary not yet published, and the lock file.
  ~RunOutputs();
  RunOutputs(const RunOutputs&) = delete;
  RunOutputs& operator=(const RunOutputs&) = delete;

  // UsageError if an output is one of the files the reader read (same device and inode).
  void check_not_read(const std::vector<std::string>& sources) const;

  // The final names after links are resolved (index 0 is the store), and their temporaries.
  const std::string& final_name(std::size_t i) const { return finals_[i]; }
  const std::string& temporary(std::size_t i) const { return temporaries_[i]; }
  const std::string& store_temporary() const { return temporaries_[0]; }

  // Renames every temporary to its final name, the store first. StoreError on failure (the outputs
  // not yet renamed are removed).
  void publish();

private:
  std::vector<std::string> finals_;
  std::vector<std::string> temporaries_;
  std::string lock_path_;
  int lock_fd_ = -1;
  bool published_ = false;
};

} // namespace medusa::cli
