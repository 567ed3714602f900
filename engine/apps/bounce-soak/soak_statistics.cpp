#include "bounce-soak/soak_statistics.h"

#include <fmt/format.h>

#include <unistd.h>

#include <algorithm>
#include <fstream>

namespace bounce::soak {

std::optional<uint64_t> residentSetBytes() {
  std::ifstream statm("/proc/self/statm");
  uint64_t size = 0, resident = 0;
  if (!(statm >> size >> resident)) return std::nullopt;
  const long page = sysconf(_SC_PAGESIZE);
  return resident * uint64_t(page > 0 ? page : 4096);
}

double leastSquaresSlope(std::span<const double> x, std::span<const double> y) {
  const size_t n = std::min(x.size(), y.size());
  if (n < 2) return 0.0;
  // Centred sums: the frame numbers are large and the slope small, so subtract the means
  // before multiplying rather than use the one-pass formula, which cancels catastrophically.
  double mx = 0.0, my = 0.0;
  for (size_t i = 0; i < n; ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= double(n);
  my /= double(n);
  double sxy = 0.0, sxx = 0.0;
  for (size_t i = 0; i < n; ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  return sxx > 0.0 ? sxy / sxx : 0.0;  // all x equal: no line, no slope
}

void SoakSamples::reserve(size_t frames) {
  for (std::vector<double>* v : {&frame, &rssBytes, &deviceBytes}) {
    const size_t kept = v->size();
    v->resize(std::max(frames, kept));  // writes every new page, which reserve() alone would not
    v->resize(kept);                    // keeps the capacity
  }
}

void SoakSamples::add(uint64_t frameIndex, uint64_t rss, uint64_t device) {
  frame.push_back(double(frameIndex));
  rssBytes.push_back(double(rss));
  deviceBytes.push_back(double(device));
}

double SoakSamples::rssSlopeKiBPerThousand(size_t from) const {
  from = std::min(from, frame.size());
  const double bytesPerFrame =
      leastSquaresSlope(std::span(frame).subspan(from), std::span(rssBytes).subspan(from));
  return bytesPerFrame * 1000.0 / 1024.0;
}

std::vector<std::string> failures(const TechniqueSoak& r, const SoakLimits& limits) {
  std::vector<std::string> out;
  if (r.nonFinite > 0)
    out.push_back(fmt::format("{} NaN/Inf values (first: {})", r.nonFinite, r.firstNonFinite));
  if (r.validationErrors > 0) out.push_back(fmt::format("{} Vulkan validation errors", r.validationErrors));
  for (const std::string& e : r.errors) out.push_back(e);
  if (limits.maxRssSlope >= 0.0 && r.rssSlope > limits.maxRssSlope)
    out.push_back(fmt::format("RSS grows {:.1f} KiB per 1000 frames over the second half (limit {:.1f})",
                              r.rssSlope, limits.maxRssSlope));
  const double growthMiB = (double(r.rssEnd) - double(r.rssHalf)) / double(1 << 20);
  if (limits.maxRssGrowthMiB >= 0.0 && growthMiB > limits.maxRssGrowthMiB)
    out.push_back(fmt::format("RSS grew {:.2f} MiB over the second half (limit {:.2f})", growthMiB,
                              limits.maxRssGrowthMiB));
  if (r.deviceBytesPeak > r.deviceBytesFirstPeak + limits.maxDeviceGrowth)
    out.push_back(fmt::format(
        "device memory grew from {} to {} bytes (the first half's peak to the second's; limit +{})",
        r.deviceBytesFirstPeak, r.deviceBytesPeak, limits.maxDeviceGrowth));
  return out;
}

std::string soakTable(const std::vector<TechniqueSoak>& results) {
  auto mib = [](uint64_t bytes) { return double(bytes) / double(1 << 20); };
  std::string t =
      "| technique | frames | time (s) | ms/frame | NaN/Inf | GPU mem start (MiB) | GPU mem end (MiB) | "
      "RSS start (MiB) | RSS end (MiB) | RSS slope, 2nd half (KiB/1000 frames) |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const TechniqueSoak& r : results)
    t += fmt::format("| {} | {} | {:.1f} | {:.2f} | {} | {:.2f} | {:.2f} | {:.1f} | {:.1f} | {:.1f} |\n",
                     r.technique, r.frames, r.seconds, r.frames ? 1000.0 * r.seconds / r.frames : 0.0,
                     r.nonFinite, mib(r.deviceBytesStart), mib(r.deviceBytesEnd), mib(r.rssStart),
                     mib(r.rssEnd), r.rssSlope);
  return t;
}

}  // namespace bounce::soak
