// Writing an output file under a temporary name and renaming it when complete (CONVENTIONS.md).
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace medusa::cli {

// Calls `write` on a stream to `<path>.tmp-<pid>`, then renames it to `path`. On any failure the
// temporary file is removed and StoreError names `path`.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

} // namespace medusa::cli
