#pragma once
// Turns glslang's info log ("ERROR: <name>:<line>: '<token>' : <message>") into the
// "file:line: message" lines a ShaderError carries, so editors and terminals can jump
// to the line.

#include <string>
#include <string_view>
#include <vector>

namespace bounce::gpu {

struct ShaderLogLines {
  std::vector<std::string> errors;
  std::vector<std::string> warnings;
};

/// `fallbackName` names messages that carry no file (link errors, the defines preamble).
ShaderLogLines parseShaderLog(std::string_view infoLog, std::string_view fallbackName);

}  // namespace bounce::gpu
