#pragma once
// An X display for window tests: the one in $DISPLAY if it accepts connections, else a
// private Xvfb started for the test run (Debian package xvfb) and stopped afterwards.
// available() is false, with a reason, only when neither works.
//
// Xvfb picks a free display number itself and reports it through -displayfd once it
// accepts connections. Choosing the number here raced: two tests started at once both
// saw :90 free, the second's Xvfb exited on the first's lock while the second, seeing the
// socket appear, took the first's server for its own, and lost its window when the first
// test ended and stopped it (SwapchainTest.RecreatesForANewWindowSize: "XIO: fatal IO
// error ... on X server :90").

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <poll.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace bounce::test {

class XDisplay {
public:
  XDisplay() {
    if (const char* d = std::getenv("DISPLAY"); d && *d && socketFor(d)) {
      available_ = true;
      return;
    }
    int fds[2];
    if (pipe(fds) != 0) {
      reason_ = "no X server: $DISPLAY is unusable and a pipe for Xvfb could not be made";
      return;
    }
    pid_t pid = fork();
    if (pid == 0) {
      close(fds[0]);
      const std::string fd = std::to_string(fds[1]);
      execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1280x720x24", "-nolisten", "tcp",
             nullptr);
      _exit(127);
    }
    close(fds[1]);
    if (pid > 0) {
      // Up to 10 s for Xvfb to write its display number (a line) and accept connections.
      std::string number;
      pollfd p{fds[0], POLLIN, 0};
      while (number.find('\n') == std::string::npos) {
        const int ready = poll(&p, 1, 10000);
        if (ready < 0 && errno == EINTR) continue;
        char buffer[16];
        const ssize_t n = ready > 0 ? read(fds[0], buffer, sizeof buffer) : 0;
        if (n <= 0) break;  // timed out, or Xvfb exited (not installed) and closed the pipe
        number.append(buffer, size_t(n));
      }
      if (const size_t end = number.find('\n'); end != std::string::npos && end > 0) {
        pid_ = pid;
        available_ = true;
        setenv("DISPLAY", (":" + number.substr(0, end)).c_str(), 1);
      } else {
        kill(pid, SIGTERM);
        waitpid(pid, nullptr, 0);
      }
    }
    close(fds[0]);
    if (!available_)
      reason_ = "no X server: $DISPLAY is unusable and Xvfb could not be started (Debian package xvfb)";
  }
  ~XDisplay() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
  }
  XDisplay(const XDisplay&) = delete;
  XDisplay& operator=(const XDisplay&) = delete;

  bool available() const { return available_; }
  const std::string& reason() const { return reason_; }

private:
  static std::filesystem::path socketPath(int n) { return "/tmp/.X11-unix/X" + std::to_string(n); }
  static bool socketFor(const char* display) {
    std::string d(display);
    size_t colon = d.find(':');
    if (colon == std::string::npos) return false;
    if (colon > 0) return true;  // a remote display: let the client try
    return std::filesystem::exists(socketPath(std::atoi(d.c_str() + colon + 1)));
  }
  bool available_ = false;
  pid_t pid_ = -1;
  std::string reason_;
};

}  // namespace bounce::test
