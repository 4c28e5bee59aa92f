// Running an external command (an oracle: /usr/bin/python3 with GUDHI or h5py, h5dump) and
// capturing its standard output.
#pragma once

#include <catch2/catch.hpp>

#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace medusa::test {

struct CommandOutput {
  int status = -1; // the exit code, or -1 if the command did not exit normally
  std::string output;
};

inline CommandOutput run_command(const std::string& command) {
  INFO("command: " << command);
  FILE* pipe = ::popen(command.c_str(), "r");
  REQUIRE(pipe != nullptr);
  CommandOutput result;
  char buffer[4096];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0)
    result.output.append(buffer, n);
  const int status = ::pclose(pipe);
  result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

// The standard output of a command that must succeed.
inline std::string command_output(const std::string& command) {
  CommandOutput result = run_command(command);
  INFO("command: " << command << "\noutput: " << result.output);
  REQUIRE(result.status == 0);
  return std::move(result.output);
}

} // namespace medusa::test
