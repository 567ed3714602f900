#include "gltf_accessors.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <span>

namespace bounce::gltf {
namespace {

// glTF stores everything little-endian; the components are copied byte for byte.
static_assert(std::endian::native == std::endian::little, "the glTF reader assumes a little-endian host");

/// Where an accessor is read from, for messages: "mesh 'Box' primitive 0: POSITION accessor 3".
struct AccessorSite {
  const LoadContext& ctx;
  std::string name;

  [[noreturn]] void fail(std::string_view message) const { ctx.fail(name, message); }
};

AccessorSite site(const LoadContext& ctx, int accessor, std::string_view element, std::string_view semantic) {
  return {ctx, fmt::format("{}: {} accessor {}", element, semantic, accessor)};
}

const tinygltf::Accessor& accessorAt(const AccessorSite& s, int accessor) {
  const auto& accessors = s.ctx.model.accessors;
  if (accessor < 0 || size_t(accessor) >= accessors.size()) {
    s.fail(fmt::format("does not exist (the file has {})", accessors.size()));
  }
  return accessors[size_t(accessor)];
}

/// True when `count` elements of `elementSize` bytes, `stride` apart, starting at
/// `offset`, end within `available` bytes. Written so that no step can overflow, since
/// every one of these numbers comes from the file.
bool rangeFits(size_t offset, size_t stride, size_t count, size_t elementSize, size_t available) {
  if (count == 0) return offset <= available;
  if (offset > available || elementSize > available - offset) return false;
  const size_t roomForSteps = available - offset - elementSize;
  return stride == 0 || (count - 1) <= roomForSteps / stride;
}

/// The bytes of buffer view `view`, after checking that it lies inside its buffer.
std::span<const uint8_t> viewBytes(const AccessorSite& s, int view, std::string_view role) {
  const tinygltf::Model& m = s.ctx.model;
  if (view < 0 || size_t(view) >= m.bufferViews.size()) {
    s.fail(fmt::format("{}bufferView {} does not exist (the file has {})", role, view, m.bufferViews.size()));
  }
  const tinygltf::BufferView& bv = m.bufferViews[size_t(view)];
  if (bv.buffer < 0 || size_t(bv.buffer) >= m.buffers.size()) {
    s.fail(fmt::format("{}bufferView {} refers to buffer {}, which does not exist", role, view, bv.buffer));
  }
  const std::vector<unsigned char>& data = m.buffers[size_t(bv.buffer)].data;
  if (!rangeFits(bv.byteOffset, 0, 1, bv.byteLength, data.size())) {
    s.fail(fmt::format("{}bufferView {} (bytes {}..{}) lies past the end of buffer {} ({} bytes)", role, view,
                       bv.byteOffset, bv.byteOffset + bv.byteLength, bv.buffer, data.size()));
  }
  return {data.data() + bv.byteOffset, bv.byteLength};
}

float decodeComponent(const uint8_t* p, int componentType, bool normalized) {
  // Normalized signed values use max(c / MAX, -1) so that both -MAX and MIN map to -1
  // (glTF 2.0 spec, "Animations" / KHR_mesh_quantization formulas).
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      int8_t v;
      std::memcpy(&v, p, sizeof v);
      return normalized ? std::max(float(v) / 127.0f, -1.0f) : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
      uint8_t v;
      std::memcpy(&v, p, sizeof v);
      return normalized ? float(v) / 255.0f : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t v;
      std::memcpy(&v, p, sizeof v);
      return normalized ? std::max(float(v) / 32767.0f, -1.0f) : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, p, sizeof v);
      return normalized ? float(v) / 65535.0f : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      uint32_t v;
      std::memcpy(&v, p, sizeof v);
      return normalized ? float(double(v) / 4294967295.0) : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float v;
      std::memcpy(&v, p, sizeof v);
      return v;
    }
  }
  return 0.0f;  // unreachable: component types are checked before decoding
}

uint32_t decodeIndex(const uint8_t* p, int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return *p;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, p, sizeof v);
      return v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      uint32_t v;
      std::memcpy(&v, p, sizeof v);
      return v;
    }
  }
  return 0;  // unreachable: component types are checked before decoding
}

bool isVertexComponentType(int t) {
  return t == TINYGLTF_COMPONENT_TYPE_BYTE || t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
         t == TINYGLTF_COMPONENT_TYPE_SHORT || t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
         t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT || t == TINYGLTF_COMPONENT_TYPE_FLOAT;
}

bool isIndexComponentType(int t) {
  return t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
         t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

/// Where an accessor's bytes are, after every range has been checked.
struct AccessorLayout {
  std::span<const uint8_t> dense;  ///< empty when the accessor has no buffer view
  size_t stride = 0;
  size_t sparseCount = 0;
  std::span<const uint8_t> sparseIndices;
  std::span<const uint8_t> sparseValues;
};

AccessorLayout checkLayout(const AccessorSite& s, const tinygltf::Accessor& a, size_t elementSize) {
  AccessorLayout layout;
  if (a.bufferView >= 0) {
    std::span<const uint8_t> bytes = viewBytes(s, a.bufferView, "");
    const tinygltf::BufferView& bv = s.ctx.model.bufferViews[size_t(a.bufferView)];
    layout.stride = bv.byteStride != 0 ? bv.byteStride : elementSize;
    if (layout.stride < elementSize) {
      s.fail(fmt::format("byteStride {} of bufferView {} is smaller than one element ({} bytes)",
                         layout.stride, a.bufferView, elementSize));
    }
    if (!rangeFits(a.byteOffset, layout.stride, a.count, elementSize, bytes.size())) {
      s.fail(
          fmt::format("{} elements of {} bytes (stride {}) from byteOffset {} run past the end of "
                      "bufferView {} ({} bytes)",
                      a.count, elementSize, layout.stride, a.byteOffset, a.bufferView, bytes.size()));
    }
    layout.dense = bytes.subspan(a.byteOffset);
  } else {
    // Without data nothing in the accessor bounds its count but memory (it is all zeros,
    // plus any sparse values). A real mesh's vertices are described by data somewhere in
    // the file (another attribute, or the indices), so a data-less accessor has no more
    // elements than the file has bytes of buffers; 4096 more allow small ones in files
    // with none. A fuzzed 2 kB file asked for 2³¹ (24 GB of floats, zero-filled).
    size_t bufferBytes = 0;
    for (const tinygltf::Buffer& b : s.ctx.model.buffers) bufferBytes += b.data.size();
    const size_t limit = std::min<size_t>(bufferBytes + 4096, UINT32_MAX);
    if (a.count > limit) {
      s.fail(
          fmt::format("count {} without a bufferView is more than the file's {} bytes of buffers can "
                      "describe (at most {})",
                      a.count, bufferBytes, limit));
    }
  }

  if (!a.sparse.isSparse) return layout;
  const auto& sp = a.sparse;
  if (sp.count < 0 || size_t(sp.count) > a.count) {
    s.fail(fmt::format("sparse count {} is not within 0..{}", sp.count, a.count));
  }
  if (!isIndexComponentType(sp.indices.componentType)) {
    s.fail(fmt::format("sparse indices have component type {}; expected unsigned byte, short or int",
                       sp.indices.componentType));
  }
  layout.sparseCount = size_t(sp.count);
  const size_t indexSize = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(sp.indices.componentType)));
  std::span<const uint8_t> indexBytes = viewBytes(s, sp.indices.bufferView, "sparse indices ");
  std::span<const uint8_t> valueBytes = viewBytes(s, sp.values.bufferView, "sparse values ");
  if (sp.indices.byteOffset < 0 || !rangeFits(size_t(sp.indices.byteOffset), indexSize, layout.sparseCount,
                                              indexSize, indexBytes.size())) {
    s.fail(fmt::format("{} sparse indices run past the end of bufferView {}", layout.sparseCount,
                       sp.indices.bufferView));
  }
  if (sp.values.byteOffset < 0 || !rangeFits(size_t(sp.values.byteOffset), elementSize, layout.sparseCount,
                                             elementSize, valueBytes.size())) {
    s.fail(fmt::format("{} sparse values run past the end of bufferView {}", layout.sparseCount,
                       sp.values.bufferView));
  }
  layout.sparseIndices = indexBytes.subspan(size_t(sp.indices.byteOffset));
  layout.sparseValues = valueBytes.subspan(size_t(sp.values.byteOffset));
  return layout;
}

/// Calls `visit(elementIndex, bytes)` for each stored element: first the dense ones
/// (none without a buffer view: those stay zero, as the spec says), then the sparse
/// substitutions in file order.
template <class Visit>
void visitElements(const AccessorSite& s, const tinygltf::Accessor& a, const AccessorLayout& layout,
                   size_t elementSize, Visit&& visit) {
  if (!layout.dense.empty()) {
    for (size_t i = 0; i < a.count; ++i) visit(i, layout.dense.data() + i * layout.stride);
  }
  const int indexType = a.sparse.indices.componentType;
  const size_t indexSize =
      layout.sparseCount ? size_t(tinygltf::GetComponentSizeInBytes(uint32_t(indexType))) : 0;
  for (size_t i = 0; i < layout.sparseCount; ++i) {
    const uint32_t target = decodeIndex(layout.sparseIndices.data() + i * indexSize, indexType);
    if (target >= a.count) {
      s.fail(fmt::format("sparse index {} is out of range (the accessor has {} elements)", target, a.count));
    }
    visit(size_t(target), layout.sparseValues.data() + i * elementSize);
  }
}

}  // namespace

std::vector<float> readFloatAccessor(const LoadContext& ctx, int accessor, int components,
                                     std::string_view element, std::string_view semantic) {
  const AccessorSite s = site(ctx, accessor, element, semantic);
  const tinygltf::Accessor& a = accessorAt(s, accessor);
  const int actual = tinygltf::GetNumComponentsInType(uint32_t(a.type));
  if (actual != components) {
    s.fail(fmt::format("has {} components per element; expected {}", actual, components));
  }
  if (!isVertexComponentType(a.componentType)) {
    s.fail(fmt::format("has unsupported component type {}", a.componentType));
  }
  const size_t componentSize = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType)));
  const size_t elementSize = componentSize * size_t(components);
  // Checked before allocating, so a bogus count in a small file fails instead of
  // asking for gigabytes.
  const AccessorLayout layout = checkLayout(s, a, elementSize);
  std::vector<float> out(a.count * size_t(components), 0.0f);
  visitElements(s, a, layout, elementSize, [&](size_t i, const uint8_t* p) {
    for (int c = 0; c < components; ++c) {
      out[i * size_t(components) + size_t(c)] =
          decodeComponent(p + size_t(c) * componentSize, a.componentType, a.normalized);
    }
  });
  return out;
}

std::vector<uint32_t> readIndexAccessor(const LoadContext& ctx, int accessor, std::string_view element,
                                        std::string_view semantic) {
  const AccessorSite s = site(ctx, accessor, element, semantic);
  const tinygltf::Accessor& a = accessorAt(s, accessor);
  if (a.type != TINYGLTF_TYPE_SCALAR) s.fail("is not SCALAR");
  if (!isIndexComponentType(a.componentType)) {
    s.fail(fmt::format("has component type {}; indices are unsigned byte, short or int", a.componentType));
  }
  const size_t size = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType)));
  const AccessorLayout layout = checkLayout(s, a, size);
  std::vector<uint32_t> out(a.count, 0u);
  visitElements(s, a, layout, size,
                [&](size_t i, const uint8_t* p) { out[i] = decodeIndex(p, a.componentType); });
  return out;
}

}  // namespace bounce::gltf
