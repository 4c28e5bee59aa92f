#include "fuzz_input_file.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <unistd.h>

namespace medusa::fuzz {

namespace {

// Removes the temporary files when the fuzzer exits normally.
struct InputFiles {
  std::map<std::string, std::string> by_suffix;
  ~InputFiles() {
    for (const auto& [suffix, path] : by_suffix)
      std::remove(path.c_str());
  }
};

InputFiles& files() {
  static InputFiles f;
  return f;
}

} // namespace

const std::string& write_input(const std::uint8_t* data, std::size_t size, const std::string& suffix) {
  std::string& path = files().by_suffix[suffix];
  if (path.empty())
    path = (std::filesystem::temp_directory_path() /
            ("medusa-fuzz-" + std::to_string(static_cast<long long>(::getpid())) + suffix))
               .string();
  std::FILE* out = std::fopen(path.c_str(), "wb");
  if (out == nullptr || std::fwrite(data, 1, size, out) != size || std::fclose(out) != 0) {
    std::perror(path.c_str());
    std::abort(); // the harness itself failed: not a finding in the reader
  }
  return path;
}

} // namespace medusa::fuzz
