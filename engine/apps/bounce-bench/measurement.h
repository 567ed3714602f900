#pragma once
// What the accuracy-versus-time benchmark measures for one configuration of a GI
// technique, and the report it writes (bounce-bench).

#include "bounce/image/image_buffer.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace bounce::bench {

/// A technique with some of its quality knobs set away from their defaults.
struct Configuration {
  std::string technique;  ///< plugin name, e.g. "MyGI"; "Reference" is the path tracer
  std::vector<std::pair<std::string, std::string>> settings;  ///< console variable → value
  bool isDefault = false;  ///< the technique's own defaults (no settings changed)
  std::string label;       ///< e.g. "MyGI cones=16" (knob labels, as declared)
};

struct Measurement {
  Configuration config;
  double gpuMs = 0;    ///< GPU milliseconds per frame, median over timed frames
  double cpuMs = 0;    ///< CPU milliseconds per frame spent in pass hooks (path tracing...)
  double totalMs = 0;  ///< gpuMs + cpuMs: the cost the Pareto front uses
  /// Untimed frames before its results settled (bounce/frame/settling.h): a probe volume's
  /// warm-up; 0 for a technique whose first frame is what it settles to.
  uint64_t settlingFrames = 0;
  std::vector<std::pair<std::string, double>> passMs;  ///< GPU median per pass
  uint64_t persistentBytes = 0;
  uint64_t transientBytes = 0;
  ImageErrorStats radiance;    ///< radiance AOV against the reference
  ImageErrorStats irradiance;  ///< indirect-irradiance AOV against the reference
  /// Milliseconds the path tracer needs to reach this configuration's radiance relative
  /// RMSE (interpolated on its own error-versus-time curve); < 0 when outside the range
  /// the benchmark measured.
  double pathTracerEquivalentMs = -1;
  std::string image;           ///< tone-mapped image, relative to the report folder
  std::string heatMap;         ///< relative radiance error heat map, relative to the report folder
  bool onParetoFront = false;  ///< no configuration of the same technique is both faster and more accurate
};

struct Report {
  std::string scene;
  uint32_t width = 0, height = 0;
  std::string device;
  std::string command;  ///< the command line that reproduces the report
  uint32_t referenceSamples = 0;
  int32_t referenceBounces = -1;
  double referenceSeconds = 0;  ///< how long the cached reference took to render
  uint32_t timedFrames = 0;
  std::vector<Measurement> measurements;
  std::vector<std::string> notes;  ///< e.g. "MyGI's defaults are not on its Pareto front: ..."
};

/// Marks each measurement on its technique's Pareto front (minimal totalMs and
/// radiance relative RMSE).
void markParetoFronts(std::vector<Measurement>& measurements);

/// report.csv: one row per measurement (technique, label, settings, times, memory, errors).
bool writeCsv(const Report& report, const std::string& path, std::string* error);
/// report.md: the command, the setup, a table per technique and the notes.
bool writeMarkdown(const Report& report, const std::string& path, std::string* error);
/// pareto.png: relative RMSE of radiance against milliseconds per frame, both on log
/// scales, one series per technique (the path tracer as a line), defaults marked,
/// labelled axes and a legend.
bool writeParetoPlot(const Report& report, const std::string& path, std::string* error);

}  // namespace bounce::bench
