#pragma once
// Where frames averaged into one still image sample their pixels (bounce-render
// --accumulate, bounce-bench): offsets from the pixel centres that cover each pixel's
// square evenly, so the average is the image box-filtered over its pixels, as the path
// tracer's PixelFilter Box renders it.

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace bounce {

/// Offsets in pixels, each component in [-0.5, 0.5), for `count` frames. A square count
/// (4, 16, 64...) gives the centres of a k × k grid of cells: the very points a k-times
/// larger image samples, so the average equals that image box-downsampled. Any other
/// count n gives a rank-1 lattice (a Fibonacci-like one, as Korobov's): point i at column
/// i and row (i·g mod n) of an n × n grid, with g the integer nearest n/φ that is coprime
/// to n. Every column and every row holds exactly one point, so the mean offset is 0 and
/// the average has no sub-pixel shift (the first points of R2 did: a mean 0.16 px off for
/// 7 frames). One frame samples the centre.
std::vector<glm::vec2> subpixelOffsets(uint32_t count);

}  // namespace bounce
