#include "image/image_shape.h"

#include <fmt/format.h>

namespace bounce::image {

std::string shapeProblem(const ImageBuffer& image) {
  if (image.channels < 1 || image.channels > 4)
    return fmt::format("has {} channels (1 to 4 are supported)", image.channels);
  const size_t expected = size_t(image.width) * image.height * image.channels;
  if (image.pixels.size() != expected)
    return fmt::format("holds {} values but {}x{}x{} needs {}", image.pixels.size(), image.width,
                       image.height, image.channels, expected);
  return {};
}

bool comparable(const ImageBuffer& image, const ImageBuffer& reference) {
  return shapeProblem(image).empty() && shapeProblem(reference).empty() && image.width == reference.width &&
         image.height == reference.height;
}

}  // namespace bounce::image
