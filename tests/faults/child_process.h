// Runs a piece of a fault test in a forked child with an alarm, so that a crash or a hang of the code
// under test fails the test case instead of killing or blocking the test executable.
#pragma once

#include <functional>
#include <string>

namespace medusa::test {

struct ChildResult {
  enum class End { exited, signalled, timed_out } end = End::exited;
  int code = 0;        // exit status, or the signal number
  std::string message; // what the child wrote on its report pipe
  std::string describe() const;
};

// Forks; the child runs `body` (which returns the child's exit status and may write to `report`)
// under alarm(`seconds`) and ends with _exit, so HDF5's atexit handlers never run in it (HDF5 1.10
// prints "infinite loop closing library" after some corrupt-metadata error paths).
ChildResult run_in_child(const std::function<int(std::string& report)>& body, unsigned seconds = 10);

// Exit statuses used by the bodies of the fault tests.
inline constexpr int child_threw_expected = 12; // not 0: a clean exit of any other kind is no pass
inline constexpr int child_returned = 10;
inline constexpr int child_threw_other = 11;

} // namespace medusa::test
