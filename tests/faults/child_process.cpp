#include "child_process.h"

#include <csignal>
#include <exception>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

namespace medusa::test {

std::string ChildResult::describe() const {
  switch (end) {
  case End::exited:
    return "exited with status " + std::to_string(code) + (message.empty() ? "" : ": " + message);
  case End::signalled:
    return "killed by signal " + std::to_string(code) + (message.empty() ? "" : " after: " + message);
  case End::timed_out: return "hung (alarm after the time limit)";
  }
  return "";
}

ChildResult run_in_child(const std::function<int(std::string& report)>& body, unsigned seconds) {
  int fds[2];
  if (::pipe(fds) != 0)
    throw std::runtime_error("pipe failed");
  const pid_t child = ::fork();
  if (child < 0)
    throw std::runtime_error("fork failed");
  if (child == 0) {
    ::close(fds[0]);
    std::signal(SIGALRM, SIG_DFL);
    ::alarm(seconds);
    std::string report;
    int status = 0;
    try {
      status = body(report);
    } catch (const std::exception& e) {
      report = std::string("unexpected exception: ") + e.what();
      status = child_threw_other;
    }
    std::size_t done = 0;
    while (done < report.size()) {
      const ssize_t n = ::write(fds[1], report.data() + done, report.size() - done);
      if (n <= 0)
        break;
      done += static_cast<std::size_t>(n);
    }
    ::_exit(status);
  }
  ::close(fds[1]);
  ChildResult result;
  char buffer[4096];
  ssize_t n;
  while ((n = ::read(fds[0], buffer, sizeof buffer)) > 0)
    result.message.append(buffer, static_cast<std::size_t>(n));
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0) {
  }
  if (WIFEXITED(status)) {
    result.code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    result.code = WTERMSIG(status);
    result.end = result.code == SIGALRM ? ChildResult::End::timed_out : ChildResult::End::signalled;
  }
  return result;
}

} // namespace medusa::test
