#pragma once
// An X display for window tests: the one in $DISPLAY if it accepts connections, else a
// private Xvfb started for the test run (Debian package xvfb) and stopped afterwards.
// available() is false, with a reason, only when neither works.

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace bounce::test {

class XDisplay {
public:
  XDisplay() {
    if (const char* d = std::getenv("DISPLAY"); d && *d && socketFor(d)) {
      available_ = true;
      return;
    }
    for (int n = 90; n < 100 && !available_; ++n) {
      const std::string name = ":" + std::to_string(n);
      if (std::filesystem::exists(socketPath(n))) continue;  // someone else's server
      pid_t pid = fork();
      if (pid == 0) {
        execlp("Xvfb", "Xvfb", name.c_str(), "-screen", "0", "1280x720x24", "-nolisten", "tcp", nullptr);
        _exit(127);
      }
      if (pid < 0) break;
      for (int i = 0; i < 100; ++i) {  // up to 5 s for the socket to appear
        if (std::filesystem::exists(socketPath(n))) {
          pid_ = pid;
          available_ = true;
          setenv("DISPLAY", name.c_str(), 1);
          return;
        }
        int status = 0;
        if (waitpid(pid, &status, WNOHANG) == pid) break;  // Xvfb exited (not installed, or busy)
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
      }
      if (!available_) kill(pid, SIGTERM), waitpid(pid, nullptr, 0);
    }
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
