// Writing an output file under a temporary name and renaming it when complete (CONVENTIONS.md).
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace medusa::cli {

// UsageError if `path` (or the file a link there leads to) is an HDF5 file, a medusa store or
// another: a report, plot or table written there would replace it, and a store is what a run
// computed for minutes or hours. Commands call it on their outputs before their work;
// write_file_atomically calls it again.
void refuse_to_replace_hdf5(const std::string& path);

// Before a command's work, what it would otherwise find only when writing: StoreError when the folder
// `path` is to be written in does not exist (or is not a folder).
void check_output_folder(const std::string& path);
// For a command whose -o is a prefix (`curves`, `sweep`, `compare`): UsageError when the prefix ends
// in '/' (the outputs would be hidden files named `.curves.csv`) or is itself a device, FIFO or
// socket, such as /dev/null, a reader's way of asking for no output that would write
// /dev/null.curves.csv and the rest beside it; then check_output_folder on `first_output`.
void check_output_prefix(const std::string& prefix, const std::string& first_output);

// check_output_folder, then regular_output_name (a device, FIFO, socket, folder or a link to one is a
// UsageError), then refuse_to_replace_hdf5.
void check_output_path(const std::string& path);

// Calls `write` on a stream to `<path>.tmp-<pid>`, then renames it to `path` (or to the regular file a
// link at `path` leads to). On any failure the temporary file is removed and StoreError names `path`;
// nothing is written over an HDF5 file (refuse_to_replace_hdf5) or in place of anything but a regular
// file (regular_output_name).
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

} // namespace medusa::cli
