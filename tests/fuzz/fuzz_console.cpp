// libFuzzer target: console lines. Each input line is executed on one engine's console
// (the engine's and the built plugins' variables and commands), at console priority, and
// Tab completion runs on it as typed. Variables written here stay written for later
// inputs, as in a long console session.

#include "bounce/config/console.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  bounce::Engine& engine = bounce::fuzz::engine();
  for (std::string_view line : bounce::fuzz::split(bounce::fuzz::text(data, size), "\n")) {
    (void)bounce::Console::split(line);
    (void)engine.console().complete(line);
    (void)engine.console().execute(line);
  }
  return 0;
}
