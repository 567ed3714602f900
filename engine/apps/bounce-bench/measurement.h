#pragma once
// What the accuracy-versus-time benchmark measures for one configuration of a GI
// technique, and the report it writes (bounce-bench).

#include "bounce/image/image_buffer.h"
#include "bounce/image/reference_noise.h"

#include <cmath>
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
  /// Against the reference's two halves (bounce/image/reference_noise.h): the whole
  /// radiance, the direct light alone (`direct` AOVs), and the indirect light alone (each
  /// image's radiance less its own direct light), which isolates what a GI technique does.
  NoisyReferenceError total, direct, indirect;
  /// Temporal behaviour (bounce-bench's temporal_measure.h); `temporal` false when it was
  /// not measured (the path tracer, --no-temporal).
  bool temporal = false;
  double flickerMean = 0, flickerP95 = 0;
  int responseFramesOff = -1, responseFramesOn = -1, responseFramesMove = -1;  ///< -1: never settled
  double responseMsOff = -1;  ///< responseFramesOff × the median frame time
  double peakOvershoot = 0;   ///< the largest of the three responses' overshoots
  double offResidue = 0;      ///< what remains of a switched-off light, relative to the scene's light
  bool reachesZero = false;   ///< offResidue at most 1e-3
  /// The images scored (accumulated still), kept to score them again against a reference
  /// with more samples.
  ImageBuffer radianceImage, directImage, irradianceImage;
  /// Milliseconds the path tracer needs to reach this configuration's radiance relative
  /// RMSE (interpolated on its own error-versus-time curve); < 0 when outside the range
  /// the benchmark measured.
  double pathTracerEquivalentMs = -1;
  std::string image;           ///< tone-mapped image, relative to the report folder
  std::string heatMap;         ///< relative radiance error heat map, relative to the report folder
  bool onParetoFront = false;  ///< no configuration of the same technique is both faster and more accurate
};

/// The error the report ranks by and plots: the indirect light's relative RMSE when it was
/// measured, else the radiance's.
inline double primaryError(const Measurement& m) {
  return std::isnan(m.indirect.relativeRmse) ? m.radiance.relativeRmse : m.indirect.relativeRmse;
}

struct Report {
  std::string scene;
  uint32_t width = 0, height = 0;
  std::string device;
  std::string command;            ///< the command line that reproduces the report
  uint32_t referenceSamples = 0;  ///< both halves together
  double referenceNoise = 0;      ///< the reference's indirect noise floor (relative RMSE)
  std::string referenceStop;      ///< why the reference stopped at its sample count
  int32_t referenceBounces = -1;
  double referenceSeconds = 0;  ///< how long the cached reference took to render
  uint32_t timedFrames = 0;
  std::vector<Measurement> measurements;
  std::vector<std::string> notes;       ///< e.g. "MyGI's defaults are not on its Pareto front: ..."
  std::string plotFile = "pareto.png";  ///< the Pareto plot, relative to the report folder
  /// Lines the Markdown report puts under its command (the first report's), e.g. image credits.
  std::vector<std::string> preamble;
};

/// Marks each measurement on its technique's Pareto front (minimal totalMs and
/// radiance relative RMSE).
void markParetoFronts(std::vector<Measurement>& measurements);

/// report.csv: one row per measurement (scene, technique, label, settings, times, memory,
/// errors, temporal behaviour), the scenes' reports one after the other.
bool writeCsv(const std::vector<Report>& reports, const std::string& path, std::string* error);
bool writeCsv(const Report& report, const std::string& path, std::string* error);
/// report.md: the command, the columns' meaning, then for each scene its setup, a table
/// per technique, the notes and its plot.
bool writeMarkdown(const std::vector<Report>& reports, const std::string& path, std::string* error);
bool writeMarkdown(const Report& report, const std::string& path, std::string* error);
/// report.json: every scene's setup and measurements (what the CSV holds, nested).
bool writeJson(const std::vector<Report>& reports, const std::string& path, std::string* error);
/// pareto.png: relative RMSE of radiance against milliseconds per frame, both on log
/// scales, one series per technique (the path tracer as a line), defaults marked,
/// labelled axes and a legend.
bool writeParetoPlot(const Report& report, const std::string& path, std::string* error);

}  // namespace bounce::bench
