// Streams a medusa into an HDF5 store (docs/FORMAT.md) while the builder runs (docs/MATH.md §6.5).
#pragma once

#include "medusa/medusa/cell_sink.h"
#include "medusa/medusa/medusa.h"

#include <memory>
#include <string>

namespace medusa {

// The version written into every store; read_store accepts exactly this version.
inline constexpr std::int64_t store_format_version = 1;

// Writes to `<path>.tmp-<pid>` and renames to `path` only in finish(), after the attribute `complete`
// (written last). Destroying an unfinished writer deletes the temporary file; a killed writer leaves
// at most the temporary file, which the reader rejects. Every failure (cannot create, disk full)
// throws StoreError naming the path; after one the writer is unusable.
class StoreWriter : public CellSink {
public:
  // on_finish: finish() renames the complete file to `path`. later: finish() leaves it complete at
  // temporary_path() and the caller publishes it (with the run's other outputs, or not at all) and
  // removes it on failure.
  enum class Publish { on_finish, later };
  explicit StoreWriter(const std::string& path, Publish publish = Publish::on_finish);
  ~StoreWriter() override;
  StoreWriter(const StoreWriter&) = delete;
  StoreWriter& operator=(const StoreWriter&) = delete;

  void run(const RunInfo& info, const kinetic::Trajectories& input) override;
  void batch(const BatchRecord& batch) override;
  void frame(const FrameRecord& frame) override;
  void cell(const Cell& cell) override;
  void finish(const VirtualTime& end) override;

  const std::string& path() const;
  const std::string& temporary_path() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Writes a whole in-memory medusa (e.g. one read back) as a store at `path`.
void write_store(const std::string& path, const Medusa& medusa);

// Keeps the HDF5 library from closing, at process exit, the files still open in it. When the final
// flush of a store fails (a full disk, a file size limit), HDF5 keeps the file after its close
// failed, and its exit handler then crashes on it: a segfault after the one-line error, instead of
// the store error's exit code. Every store is closed, or deleted, by its own writer or reader, so a
// program calls this first, before any other use of HDF5 (later it has no effect).
void skip_hdf5_cleanup_at_exit();

} // namespace medusa
