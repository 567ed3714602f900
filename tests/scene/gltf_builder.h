#pragma once
// Builds small glTF files inside tests, so that every loader variant has its own
// fixture without committing binary files: JSON from nlohmann::json, binary data
// appended to one buffer, written as .gltf (embedded or external buffer) or .glb.

#include "bounce/scene/gltf_loader.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace bounce::test {

inline constexpr int kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123,
                     kUnsignedInt = 5125, kFloat = 5126;

/// A fresh folder under the system temp folder, removed with everything in it.
class TempDir {
 public:
  TempDir() {
    std::random_device random;
    path_ = std::filesystem::temp_directory_path() /
            ("bounce-scene-test-" + std::to_string(random()) + "-" + std::to_string(random()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::string file(std::string_view name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

inline std::string base64(const std::vector<uint8_t>& bytes) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t chunk = uint32_t(bytes[i]) << 16;
    if (i + 1 < bytes.size()) chunk |= uint32_t(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) chunk |= bytes[i + 2];
    out += kDigits[(chunk >> 18) & 63];
    out += kDigits[(chunk >> 12) & 63];
    out += i + 1 < bytes.size() ? kDigits[(chunk >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kDigits[chunk & 63] : '=';
  }
  return out;
}

inline void writeBytes(const std::string& path, const std::vector<uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

inline void writeText(const std::string& path, std::string_view text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

/// Raw little-endian bytes of a vector of plain values.
template <class T>
std::vector<uint8_t> bytesOf(const std::vector<T>& values) {
  std::vector<uint8_t> out(values.size() * sizeof(T));
  if (!out.empty()) std::memcpy(out.data(), values.data(), out.size());
  return out;
}

class GltfBuilder {
 public:
  nlohmann::json doc;
  std::vector<uint8_t> bin;

  GltfBuilder() {
    // Tests state light intensities radiometrically (W/sr, W/m²), as the scene model
    // holds them; a test of KHR_lights_punctual's photometric units erases this key.
    doc["asset"] = {{"version", "2.0"}, {"extras", {{"BounceLightUnits", "radiometric"}}}};
    doc["scene"] = 0;
    doc["scenes"] = nlohmann::json::array({{{"nodes", nlohmann::json::array()}}});
  }

  /// Appends `bytes` (4-byte aligned) as a new buffer view.
  int view(const std::vector<uint8_t>& bytes, size_t byteStride = 0) {
    while (bin.size() % 4) bin.push_back(0);
    nlohmann::json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes.size()}};
    if (byteStride) v["byteStride"] = byteStride;
    bin.insert(bin.end(), bytes.begin(), bytes.end());
    return append("bufferViews", v);
  }

  int accessor(int bufferView, int componentType, size_t count, const char* type, size_t byteOffset = 0,
               bool normalized = false) {
    nlohmann::json a = {{"componentType", componentType}, {"count", count}, {"type", type}};
    if (bufferView >= 0) a["bufferView"] = bufferView;
    if (byteOffset) a["byteOffset"] = byteOffset;
    if (normalized) a["normalized"] = true;
    return append("accessors", a);
  }

  int positions(const std::vector<glm::vec3>& p) {
    int a = accessor(view(bytesOf(p)), kFloat, p.size(), "VEC3");
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& v : p) lo = glm::min(lo, v), hi = glm::max(hi, v);
    doc["accessors"][a]["min"] = {lo.x, lo.y, lo.z};
    doc["accessors"][a]["max"] = {hi.x, hi.y, hi.z};
    return a;
  }
  int vec3s(const std::vector<glm::vec3>& v) { return accessor(view(bytesOf(v)), kFloat, v.size(), "VEC3"); }
  int vec2s(const std::vector<glm::vec2>& v) { return accessor(view(bytesOf(v)), kFloat, v.size(), "VEC2"); }
  int indices16(const std::vector<uint16_t>& i) {
    return accessor(view(bytesOf(i)), kUnsignedShort, i.size(), "SCALAR");
  }
  int indices32(const std::vector<uint32_t>& i) {
    return accessor(view(bytesOf(i)), kUnsignedInt, i.size(), "SCALAR");
  }

  static nlohmann::json primitive(int position, int indices = -1, int normal = -1, int material = -1) {
    nlohmann::json p = {{"attributes", {{"POSITION", position}}}};
    if (normal >= 0) p["attributes"]["NORMAL"] = normal;
    if (indices >= 0) p["indices"] = indices;
    if (material >= 0) p["material"] = material;
    return p;
  }

  int mesh(const std::string& name, std::vector<nlohmann::json> primitives) {
    return append("meshes", {{"name", name}, {"primitives", primitives}});
  }
  int material(const nlohmann::json& m) { return append("materials", m); }
  int camera(const nlohmann::json& c) { return append("cameras", c); }
  int light(const nlohmann::json& l) {
    doc["extensions"]["KHR_lights_punctual"]["lights"].push_back(l);
    return int(doc["extensions"]["KHR_lights_punctual"]["lights"].size()) - 1;
  }
  /// Adds a node; root nodes are listed in scene 0.
  int node(const nlohmann::json& n, bool root = true) {
    int index = append("nodes", n);
    if (root) doc["scenes"][0]["nodes"].push_back(index);
    return index;
  }
  /// An embedded image (PNG bytes) in a buffer view, and a texture using it.
  int pngTexture(const std::vector<uint8_t>& png, const std::string& name = "") {
    nlohmann::json image = {{"bufferView", view(png)}, {"mimeType", "image/png"}};
    if (!name.empty()) image["name"] = name;
    int source = append("images", image);
    return append("textures", {{"source", source}});
  }

  /// One triangle mesh (positions, optional normals, 16-bit indices) placed by a root node
  /// named like the mesh.
  int triangleMesh(const std::string& name, const std::vector<glm::vec3>& p, const std::vector<uint16_t>& idx,
                   const std::vector<glm::vec3>& normals = {}, int material = -1) {
    // Accessors in a fixed order (tests refer to them): POSITION, NORMAL, indices.
    const int position = positions(p);
    const int normal = normals.empty() ? -1 : vec3s(normals);
    const int indices = indices16(idx);
    int m = mesh(name, {primitive(position, indices, normal, material)});
    node({{"name", name}, {"mesh", m}});
    return m;
  }

  enum class Buffer { Embedded, External };

  /// Writes `path` (.gltf); an external buffer goes to `<stem>.bin` beside it.
  void writeGltf(const std::string& path, Buffer storage = Buffer::Embedded) const {
    writeText(path, json(storage, std::filesystem::path(path).stem().string() + ".bin").dump(1));
    if (storage == Buffer::External) {
      writeBytes(
          (std::filesystem::path(path).parent_path() / (std::filesystem::path(path).stem().string() + ".bin"))
              .string(),
          bin);
    }
  }

  /// The .glb bytes: header, JSON chunk, BIN chunk.
  std::vector<uint8_t> glb() const {
    nlohmann::json d = doc;
    if (!bin.empty()) d["buffers"] = nlohmann::json::array({{{"byteLength", bin.size()}}});
    std::string text = d.dump();
    while (text.size() % 4) text += ' ';
    std::vector<uint8_t> body = bin;
    while (body.size() % 4) body.push_back(0);
    std::vector<uint8_t> out = {'g', 'l', 'T', 'F'};
    auto u32 = [&](uint32_t v) {
      for (int i = 0; i < 4; ++i) out.push_back(uint8_t(v >> (8 * i)));
    };
    u32(2);
    const size_t binChunk = body.empty() ? 0 : 8 + body.size();  // omitted when empty
    u32(uint32_t(12 + 8 + text.size() + binChunk));
    u32(uint32_t(text.size()));
    u32(0x4E4F534A);  // "JSON"
    out.insert(out.end(), text.begin(), text.end());
    if (body.empty()) return out;
    u32(uint32_t(body.size()));
    u32(0x004E4942);  // "BIN\0"
    out.insert(out.end(), body.begin(), body.end());
    return out;
  }

  nlohmann::json json(Buffer storage = Buffer::Embedded, const std::string& binName = "buffer.bin") const {
    nlohmann::json d = doc;
    std::string uri =
        storage == Buffer::Embedded ? "data:application/octet-stream;base64," + base64(bin) : binName;
    // A buffer must have at least one byte; scenes without geometry have none.
    if (!bin.empty()) d["buffers"] = nlohmann::json::array({{{"byteLength", bin.size()}, {"uri", uri}}});
    return d;
  }

 private:
  int append(const char* array, const nlohmann::json& value) {
    doc[array].push_back(value);
    return int(doc[array].size()) - 1;
  }
};

/// A unit right triangle in the z = 0 plane facing +z, and its normals.
inline const std::vector<glm::vec3> kTriangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
inline const std::vector<glm::vec3> kUpNormals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};

/// Writes `builder` as `name` in `dir` (.glb when the name says so) and loads it.
inline GltfLoadResult loadBuilt(const GltfBuilder& builder, const TempDir& dir,
                                std::string_view name = "scene.gltf",
                                const SceneExtrasSchema* schema = nullptr) {
  const std::string path = dir.file(name);
  if (name.ends_with(".glb")) {
    writeBytes(path, builder.glb());
  } else {
    builder.writeGltf(path);
  }
  return loadGltf(path, schema);
}

/// The warnings containing every one of `needles`, joined; empty when none.
inline std::string warningsWith(const GltfLoadResult& result,
                                std::initializer_list<std::string_view> needles) {
  std::string out;
  for (const std::string& w : result.warnings) {
    if (std::all_of(needles.begin(), needles.end(),
                    [&](std::string_view n) { return w.find(n) != w.npos; })) {
      out += w + "\n";
    }
  }
  return out;
}

}  // namespace bounce::test
