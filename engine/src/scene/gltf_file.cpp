#include "gltf_file.h"

#include "image/file_bytes.h"

#include "gltf_context.h"
#include "gltf_images.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string_view>

namespace bounce::gltf {
namespace {

/// tinygltf reports several problems as "\n"-separated text; messages here are one line.
std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (!line.empty()) out.push_back(std::move(line));
  }
  return out;
}

std::string oneLine(const std::string& text) {
  std::string out;
  for (const std::string& line : lines(text)) out += (out.empty() ? "" : "; ") + line;
  return out.empty() ? "unknown error" : out;
}

/// tinygltf's wording for the failures users meet most, rephrased to name what failed.
std::string describeFailure(const std::string& error, bool binary) {
  const std::string text = oneLine(error);
  // A required external file that is missing or short can only be a buffer: tinygltf
  // treats external images as optional and only warns about them.
  if (text.find("File not found") != std::string::npos ||
      text.find("File size mismatch") != std::string::npos ||
      text.find("File read error") != std::string::npos || text.find("File is empty") != std::string::npos) {
    return "buffer could not be loaded: " + text;
  }
  if (text.find("[json.exception") != std::string::npos) return "malformed JSON: " + text;
  if (binary) return "invalid or truncated GLB: " + text;
  return "invalid glTF: " + text;
}

/// Deepest nesting of arrays and objects in `json` (brackets inside strings do not count).
/// tinygltf converts JSON values recursively, so a deep one overflows the stack.
size_t jsonNestingDepth(std::string_view json) {
  size_t depth = 0, deepest = 0;
  bool inString = false;
  for (size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (inString) {
      if (c == '\\')
        ++i;  // skips the escaped character, a quote among them
      else if (c == '"')
        inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return deepest;
}

/// A glTF document nests about six levels deep and extras a few more; 512 leaves room for
/// any real content while a recursion that deep uses well under 1 MiB of stack, even
/// under AddressSanitizer. Found by tests/hostile (JSON nested 100,000 deep).
constexpr size_t kMaxJsonDepth = 512;

/// The JSON text of a .gltf, or of a .glb's first chunk (whose length is at byte 12).
std::string_view jsonText(const std::vector<unsigned char>& bytes, bool binary) {
  const char* data = reinterpret_cast<const char*>(bytes.data());
  if (!binary) return {data, bytes.size()};
  if (bytes.size() < 20) return {};
  const uint32_t length =
      uint32_t(bytes[12]) | uint32_t(bytes[13]) << 8 | uint32_t(bytes[14]) << 16 | uint32_t(bytes[15]) << 24;
  return {data + 20, std::min<size_t>(length, bytes.size() - 20)};
}

// tinygltf's file access for external buffers and images, refusing what is not a regular
// file before opening it: its defaults open a file to see whether it exists and read it
// with a stream, so a URI naming a FIFO blocked the loader forever, and one naming a
// folder read as std::bad_alloc.
bool fileExists(const std::string& path, void*) {
  std::error_code ec;
  return std::filesystem::exists(path, ec);
}

bool readWholeFile(std::vector<unsigned char>* out, std::string* error, const std::string& path, void*) {
  std::string reason;
  std::optional<std::vector<uint8_t>> bytes = image::readFileBytes(path, reason);
  if (!bytes) {
    if (error) *error += fmt::format("'{}' {}", path, reason);
    return false;
  }
  *out = std::move(*bytes);
  return true;
}

}  // namespace

void readGltfFile(const std::string& path, tinygltf::Model& model,
                  std::vector<std::string>& tinygltfWarnings) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw LoadError(fmt::format("{}: file not found", path));
  const uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw LoadError(fmt::format("{}: could not be read: {}", path, ec.message()));
  if (size == 0) throw LoadError(fmt::format("{}: file is empty", path));
  // tinygltf takes the size as unsigned int (and GLB lengths are 32-bit).
  if (size > std::numeric_limits<unsigned int>::max()) {
    throw LoadError(fmt::format("{}: larger than 4 GiB, which glTF loading does not support", path));
  }
  std::vector<unsigned char> bytes(size);
  std::ifstream in(path, std::ios::binary);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size))) {
    throw LoadError(fmt::format("{}: could not be read", path));
  }

  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&decodeImageInsideBuffers, &model);
  loader.SetFsCallbacks(
      {&fileExists, &tinygltf::ExpandFilePath, &readWholeFile, &tinygltf::WriteWholeFile, nullptr});
  const std::string baseDir = std::filesystem::path(path).parent_path().string();
  const bool binary =
      bytes.size() >= 4 && bytes[0] == 'g' && bytes[1] == 'l' && bytes[2] == 'T' && bytes[3] == 'F';
  if (const size_t depth = jsonNestingDepth(jsonText(bytes, binary)); depth > kMaxJsonDepth) {
    throw LoadError(fmt::format("{}: malformed JSON: nested {} levels deep (at most {} are read)", path,
                                depth, kMaxJsonDepth));
  }
  std::string error, warning;
  bool ok = false;
  try {
    ok = binary ? loader.LoadBinaryFromMemory(&model, &error, &warning, bytes.data(), unsigned(bytes.size()),
                                              baseDir)
                : loader.LoadASCIIFromString(&model, &error, &warning,
                                             reinterpret_cast<const char*>(bytes.data()),
                                             unsigned(bytes.size()), baseDir);
  } catch (const std::exception& e) {  // tinygltf's JSON parser may throw on odd input
    ok = false;
    error = e.what();
  }
  for (std::string& line : lines(warning)) tinygltfWarnings.push_back(std::move(line));
  if (ok) {  // tinygltf also reports some problems it survived as errors
    for (std::string& line : lines(error)) tinygltfWarnings.push_back(std::move(line));
  }
  if (!ok) throw LoadError(fmt::format("{}: {}", path, describeFailure(error, binary)));
}

}  // namespace bounce::gltf
