#include "atomic_file.h"

#include "medusa/core/error.h"

#include <cstdio>
#include <fstream>
#include <unistd.h>

namespace medusa::cli {

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
  try {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out)
      throw StoreError("cannot create " + temporary);
    write(out);
    out.flush();
    if (!out)
      throw StoreError("cannot write " + path + " (disk full?)");
    out.close();
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
      throw StoreError("cannot rename " + temporary + " to " + path);
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
}

} // namespace medusa::cli
