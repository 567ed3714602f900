#pragma once
// One check, shared by the writers and the comparisons, that an ImageBuffer's fields
// agree with its pixel vector: the struct is public and filled by hand, and indexing a
// buffer whose size does not match would read out of bounds instead of failing.

#include "bounce/image/image_buffer.h"

#include <string>

namespace bounce::image {

/// Empty when `image` is consistent (1..4 channels, pixels.size() == w·h·c), otherwise
/// why not, phrased to follow "image ...".
std::string shapeProblem(const ImageBuffer& image);

/// Whether two images can be compared pixel for pixel: both consistent, same size
/// (channel counts may differ; see ComparedPixels).
bool comparable(const ImageBuffer& image, const ImageBuffer& reference);

}  // namespace bounce::image
