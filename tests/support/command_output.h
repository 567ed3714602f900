#pragma once
// Running one of the built programs from a test: its output and exit status.

#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <string>

namespace bounce::test {

/// A shell command's standard output and error together, and its exit status (-1 when it
/// did not start or did not exit normally).
struct CommandResult {
  int status = -1;
  std::string output;
};

/// Runs `command` with /bin/sh, its standard error joined to its output.
inline CommandResult runCommand(const std::string& command) {
  CommandResult r;
  FILE* p = popen((command + " 2>&1").c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buffer;
  while (fgets(buffer.data(), int(buffer.size()), p)) r.output += buffer.data();
  const int status = pclose(p);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace bounce::test
