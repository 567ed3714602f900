#include "gltf_images.h"

#include "core/file_kind.h"

#include <fmt/format.h>

#include <filesystem>

#include <cstdint>
#include <cstring>
#include <functional>

namespace bounce::gltf {

bool decodeImageInsideBuffers(tinygltf::Image* image, int imageIndex, std::string* err, std::string* warn,
                              int requiredWidth, int requiredHeight, const unsigned char* bytes, int size,
                              void* userData) {
  if (image->bufferView >= 0) {
    const auto* model = static_cast<const tinygltf::Model*>(userData);
    // std::less gives a total order over pointers into different arrays.
    std::less<const unsigned char*> before;
    bool inside = false;
    for (const tinygltf::Buffer& buffer : model->buffers) {
      if (buffer.data.empty()) continue;
      const unsigned char* begin = buffer.data.data();
      const unsigned char* end = begin + buffer.data.size();
      if (!before(bytes, begin) && before(bytes, end) && size >= 0 && size_t(size) <= size_t(end - bytes)) {
        inside = true;
      }
    }
    if (!inside) {
      if (err) {
        *err +=
            fmt::format("image[{}] bufferView {} lies outside its buffer\n", imageIndex, image->bufferView);
      }
      return false;
    }
  }
  // tinygltf's own stb_image decoder; a null option means "expand to RGBA".
  return tinygltf::LoadImageData(image, imageIndex, err, warn, requiredWidth, requiredHeight, bytes, size,
                                 nullptr);
}

Texture convertImage(const LoadContext& ctx, int index) {
  const tinygltf::Image& image = ctx.model.images[size_t(index)];
  // A data URI is no name for a message; a file name is.
  const bool external = !image.uri.empty() && image.uri.rfind("data:", 0) != 0;
  const std::string element = elementName("image", index, image.name);
  if (image.image.empty() || image.width <= 0 || image.height <= 0) {
    // A URI naming a FIFO, a device or a folder was refused unopened (gltf_file.cpp): say what it is.
    if (external) {
      const std::filesystem::path file =
          std::filesystem::path(ctx.file).parent_path() / image.uri;  // percent-escapes: the generic message
      if (const std::optional<std::string> kind = notARegularFile(file))
        ctx.fail(element, fmt::format("'{}' is {}, not a regular file", image.uri, *kind));
    }
    ctx.fail(element, external ? fmt::format("could not be loaded or decoded from '{}'", image.uri)
                               : "could not be loaded or decoded");
  }
  const int channels = image.component;
  const int bytesPerChannel = image.bits / 8;
  if (channels < 1 || channels > 4 || (image.bits != 8 && image.bits != 16)) {
    ctx.fail(element,
             fmt::format("has an unsupported layout ({} channels of {} bits)", channels, image.bits));
  }
  const size_t pixels = size_t(image.width) * size_t(image.height);
  if (image.image.size() < pixels * size_t(channels) * size_t(bytesPerChannel)) {
    ctx.fail(element, "decoded data is shorter than its size says");
  }

  Texture texture;
  texture.name = !image.name.empty() || !external ? image.name : image.uri;
  texture.width = uint32_t(image.width);
  texture.height = uint32_t(image.height);
  texture.rgba8.resize(pixels * 4);
  auto channel = [&](size_t pixel, int c) -> uint8_t {
    const size_t at = (pixel * size_t(channels) + size_t(c)) * size_t(bytesPerChannel);
    if (bytesPerChannel == 1) return image.image[at];
    uint16_t v;  // stb_image returns 16-bit channels in native byte order
    std::memcpy(&v, &image.image[at], sizeof v);
    return uint8_t(v >> 8);
  };
  for (size_t p = 0; p < pixels; ++p) {
    uint8_t* out = &texture.rgba8[p * 4];
    if (channels <= 2) {  // grey, grey + alpha
      out[0] = out[1] = out[2] = channel(p, 0);
      out[3] = channels == 2 ? channel(p, 1) : 255;
    } else {
      for (int c = 0; c < 3; ++c) out[c] = channel(p, c);
      out[3] = channels == 4 ? channel(p, 3) : 255;
    }
  }
  return texture;
}

}  // namespace bounce::gltf
