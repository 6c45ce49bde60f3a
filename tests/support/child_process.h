#pragma once
// Runs a piece of a test in a child process (fork), for what must not touch
// the test runner itself: a lowered file size limit, a fatal signal.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <functional>

namespace umbra::test {

/// The wait(2) status of a child that ran `body` and exited with its
/// return value (or died of a signal). `body` must not use GoogleTest
/// assertions: report through the exit code.
inline int run_in_child(const std::function<int()>& body) {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(body());
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

}  // namespace umbra::test
