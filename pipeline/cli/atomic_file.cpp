#include "atomic_file.h"

#include "run_outputs.h"

#include "medusa/core/error.h"

#include <array>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace medusa::cli {

namespace {

// The HDF5 format signature, found at the start of the superblock, which lies at byte 0 or, after a
// user block, at byte 512, 1024, 2048, ... of the file (HDF5 File Format Specification, II.A).
bool is_hdf5(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return false;
  constexpr std::array<char, 8> signature{'\x89', 'H', 'D', 'F', '\r', '\n', '\x1a', '\n'};
  for (std::uint64_t at = 0; at <= (std::uint64_t{1} << 30); at = at == 0 ? 512 : 2 * at) {
    std::array<char, 8> bytes{};
    in.seekg(static_cast<std::streamoff>(at));
    if (!in.read(bytes.data(), bytes.size()))
      return false;
    if (bytes == signature)
      return true;
  }
  return false;
}

} // namespace

void refuse_to_replace_hdf5(const std::string& path) {
  if (is_hdf5(path))
    throw UsageError("output " + path +
                     " is an HDF5 file (a medusa store?); it is not replaced: choose another name");
}

void check_output_folder(const std::string& path) {
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::error_code ec;
  if (!folder.empty() && !std::filesystem::is_directory(folder, ec))
    throw StoreError("output " + path + ": the folder " + folder.string() +
                     (std::filesystem::exists(folder, ec) ? " is not a folder" : " does not exist"));
}

void check_output_prefix(const std::string& prefix, const std::string& first_output) {
  const std::string hint = "; -o takes the start of the output names, such as results/run1";
  if (!prefix.empty() && prefix.back() == '/')
    throw UsageError("output prefix " + prefix + " ends in '/': the outputs would be hidden files such as " +
                     first_output + hint);
  std::error_code ec;
  const std::filesystem::file_type type = std::filesystem::status(prefix, ec).type();
  const char* kind =
      type == std::filesystem::file_type::character || type == std::filesystem::file_type::block ? "a device"
      : type == std::filesystem::file_type::fifo                                                 ? "a FIFO"
      : type == std::filesystem::file_type::socket                                               ? "a socket"
                                                                                                 : nullptr;
  if (kind != nullptr)
    throw UsageError("output prefix " + prefix + " is " + kind +
                     ": the outputs would be written beside it, as " + first_output + " and the others" +
                     hint);
  check_output_folder(first_output);
}

void check_output_path(const std::string& path) {
  check_output_folder(path);
  refuse_to_replace_hdf5(regular_output_name(path));
}

void write_file_atomically(const std::string& output, const std::function<void(std::ostream&)>& write) {
  const std::string path = regular_output_name(output);
  refuse_to_replace_hdf5(path);
  const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
  try {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out)
      throw StoreError("cannot create " + path + " (" + std::strerror(errno) + ")");
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
