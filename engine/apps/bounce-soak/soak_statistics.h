#pragma once
// Numbers a soak run reports per technique, and the table it prints.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace bounce::soak {

/// The process's resident set size in bytes (/proc/self/statm); nullopt where unreadable.
std::optional<uint64_t> residentSetBytes();

/// Slope of the least-squares line through (x, y); 0 with fewer than two distinct x.
double leastSquaresSlope(std::span<const double> x, std::span<const double> y);

/// Samples of one run, one per frame.
struct SoakSamples {
  std::vector<double> frame;
  std::vector<double> rssBytes;
  std::vector<double> deviceBytes;
  /// Allocates and writes the room for `frames` samples in all, so that adding them up to
  /// there allocates nothing. Samples that grew as they were added grew the resident set
  /// they measured: each doubling moved the vectors into blocks twice the size (three of
  /// 128 KiB at frame 8,192 of a 10,000-frame run), which the following frames then wrote
  /// page by page. 24 bytes a frame.
  void reserve(size_t frames);
  void add(uint64_t frameIndex, uint64_t rss, uint64_t device);
  /// RSS slope in KiB per 1000 frames over the samples from `from` on.
  double rssSlopeKiBPerThousand(size_t from) const;
};

struct TechniqueSoak {
  std::string technique;
  uint32_t frames = 0;
  double seconds = 0.0;
  uint64_t nonFinite = 0;         ///< NaN/Inf values over all outputs and frames
  std::string firstNonFinite;     ///< where the first was seen ("frame 12 radiance: 3 values")
  uint64_t deviceBytesStart = 0;  ///< after the first frame
  /// Largest over the first half. Not the value at the half: the executor's transient pool
  /// frees what went unused for a few frames and takes it again when a rarer frame (several
  /// voxelizations in one, say) comes back, so its size dips and recovers within the
  /// animation's cycle; a leak instead raises the high-water mark.
  uint64_t deviceBytesFirstPeak = 0;
  uint64_t deviceBytesPeak = 0;  ///< largest over the second half
  uint64_t deviceBytesEnd = 0;
  uint64_t rssStart = 0;  ///< after the first frame
  uint64_t rssHalf = 0;
  uint64_t rssEnd = 0;
  double rssSlope = 0.0;  ///< KiB per 1000 frames, least squares over the second half
  size_t validationErrors = 0;
  std::vector<std::string> errors;  ///< frames that failed (passes that did not record)
};

/// What makes a run fail; each check names the limit it broke.
struct SoakLimits {
  double maxRssSlope = 0.0;      ///< KiB per 1000 frames over the second half
  double maxRssGrowthMiB = 0.0;  ///< RSS at the end over RSS at half-time; < 0: not checked
  uint64_t maxDeviceGrowth = 0;  ///< bytes: peak of the second half over its start
};

/// The reasons `r` fails `limits` (empty: it passed).
std::vector<std::string> failures(const TechniqueSoak& r, const SoakLimits& limits);

/// A Markdown table, one row per technique.
std::string soakTable(const std::vector<TechniqueSoak>& results);

}  // namespace bounce::soak
