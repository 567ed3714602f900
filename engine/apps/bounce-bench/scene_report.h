#pragma once
// One scene's part of a benchmark report: its configurations measured, the reference
// rendered until it is quiet enough to score them (or its budget runs out), the scores,
// Pareto fronts and notes; and the report files for all scenes.

#include "bench_options.h"
#include "bounce/gpu/device.h"
#include "measurement.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace bounce::bench {

/// Nullopt with a one-line error when the scene, a technique or the reference fails to
/// start (a configuration that fails to render is left out with an error line).
std::optional<Report> measureScene(const std::filesystem::path& scene, const BenchOptions& options,
                                   const gpu::Device& device, std::string* error);

/// report.md, report.csv, report.json and each scene's plot in options.outDir.
bool writeReports(std::vector<Report>& reports, const BenchOptions& options, std::string* error);

/// The line crediting a scene's authors, from the README beside it (its first line, a
/// heading): "Images of `sponza.gltf`: sponza — … by …"; empty without one.
std::string creditLine(const std::filesystem::path& scene);

}  // namespace bounce::bench
