#include "measurement.h"
#include "report_file.h"
#include "technique_groups.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string_view>

namespace bounce::bench {
namespace {

constexpr std::string_view kMissing = "—";

// Milliseconds span 0.05 (a cheap pass) to minutes (a converged path tracer): three or
// so significant digits without switching to exponents, which a table reader misreads.
std::string milliseconds(double ms) {
  if (!std::isfinite(ms)) return std::string(kMissing);
  if (ms == 0) return "0";  // no CPU work at all, not "0.000" of it
  const double magnitude = std::abs(ms);
  const int decimals = magnitude >= 100 ? 0 : magnitude >= 10 ? 1 : magnitude >= 1 ? 2 : 3;
  return fmt::format("{:.{}f}", ms, decimals);
}

// Errors are compared by ratio, so significant digits rather than decimals.
std::string errorValue(double value) {
  return std::isfinite(value) ? fmt::format("{:.3g}", value) : std::string(kMissing);
}

// "lowest–highest" of the region ratios (ImageErrorStats), or — without them.
std::string regionRange(const ImageErrorStats& stats) {
  if (!std::isfinite(stats.lowestRegionRatio) || !std::isfinite(stats.highestRegionRatio))
    return std::string(kMissing);
  return fmt::format("{:.2g}–{:.2g}", stats.lowestRegionRatio, stats.highestRegionRatio);
}

std::string mebibytes(uint64_t bytes) { return fmt::format("{:.1f}", double(bytes) / (1024.0 * 1024.0)); }

// How many times longer the path tracer takes for the same radiance error: the speed-up
// the technique buys with its bias.
std::string pathTracerRatio(const Measurement& m) {
  if (m.pathTracerEquivalentMs < 0 || !std::isfinite(m.pathTracerEquivalentMs) || !(m.totalMs > 0) ||
      !std::isfinite(m.totalMs))
    return std::string(kMissing);
  const double ratio = m.pathTracerEquivalentMs / m.totalMs;
  return ratio >= 0.1 ? fmt::format("{:.1f}×", ratio) : fmt::format("{:.2g}×", ratio);
}

// A '|' would split the cell and a line break would end the table row.
std::string cellText(std::string_view text) {
  std::string cell;
  for (char c : text) {
    if (c == '|')
      cell += "\\|";
    else if (c == '\n' || c == '\r')
      cell += ' ';
    else
      cell += c;
  }
  return cell;
}

// Report paths are plain file paths; the characters that would end a Markdown link
// target or a table cell are percent-encoded (and '%' itself, so the path round-trips).
std::string linkTarget(std::string_view path) {
  std::string target;
  for (char c : path) {
    if (c == ' ' || c == '(' || c == ')' || c == '<' || c == '>' || c == '|' || c == '%')
      target += fmt::format("%{:02X}", static_cast<unsigned char>(c));
    else
      target += c;
  }
  return target;
}

std::string link(std::string_view text, std::string_view path) {
  return path.empty() ? std::string() : fmt::format("[{}]({})", text, linkTarget(path));
}

// A fence one backtick longer than any run in the command, so no command can close it.
std::string codeFence(std::string_view code) {
  size_t longest = 0, run = 0;
  for (char c : code) {
    run = c == '`' ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  return std::string(std::max<size_t>(3, longest + 1), '`');
}

std::string bouncesText(int32_t bounces) {
  return bounces < 0 ? std::string("unlimited bounces") : fmt::format("{} bounces", bounces);
}

void appendSetup(std::string& out, const Report& report, const std::string& heading) {
  out += fmt::format("{} Setup\n\n", heading);
  out += fmt::format("- Scene: `{}`\n", report.scene);
  out += fmt::format("- Image: {} × {} pixels\n", report.width, report.height);
  out += fmt::format("- Device: {}\n", report.device.empty() ? std::string(kMissing) : report.device);
  out += fmt::format("- Reference: path tracer, {} samples per pixel, {}, rendered in {:.1f} s\n",
                     report.referenceSamples, bouncesText(report.referenceBounces), report.referenceSeconds);
  if (report.referenceNoise > 0 || !report.referenceStop.empty())
    out += fmt::format("- Reference noise: its indirect light's relative RMSE is {} ({})\n",
                       errorValue(report.referenceNoise),
                       report.referenceStop.empty() ? std::string(kMissing) : report.referenceStop);
  out += fmt::format(
      "- Timed frames: {} per configuration at sub-pixel offsets (times are medians); the path tracer's time "
      "is "
      "its scored still's\n\n",
      report.timedFrames);
}

void appendLegend(std::string& out) {
  out += "## Columns\n\n";
  out += "- **Configuration**: the technique's quality settings; **bold** is the technique's defaults.\n";
  out +=
      "- **GPU ms**, **CPU ms**: median milliseconds per frame on the GPU and in CPU pass hooks; "
      "**total ms** is their sum, the cost the Pareto front uses.\n";
  out += "- **Memory**: persistent + transient GPU memory in MiB.\n";
  out +=
      "- **Settles after**: untimed frames before the technique's results settled (a probe volume's "
      "warm-up), rendered before the timed ones; 0 when the first frame is what it settles to.\n";
  out +=
      "- Errors are measured on a still averaged over sub-pixel offsets, against a reference whose samples "
      "cover each pixel's square, so edges are not error. **Rel. RMSE**: root-mean-square error against the "
      "reference divided by the reference's mean. **Direct**: the `direct` outputs (emission and direct "
      "light); **indirect**: each image's radiance less its own direct light, what a GI technique adds, "
      "against the reference's. The reference is two independent halves: **noise removed** takes their "
      "measured noise out of the squared error (0 when the image is closer than the noise can tell); "
      "**÷ reference**: the mean over the reference's, the bias an RMSE does not show (1.2: 20% too bright "
      "on average).\n";
  out +=
      "- **Radiance** is the final image; **mean rel. error**: per-pixel |error| / (|reference| + ε), "
      "averaged; **irradiance** the indirect-irradiance output; **by region**: its ratio's lowest and "
      "highest "
      "over a 4 × 4 grid of the image, leaving out cells with under 1/64 of the reference's light.\n";
  out +=
      "- **Flicker**: per pixel, luminance's standard deviation over its mean across still frames; the "
      "mean over pixels and the 95th percentile. **Response frames**: frames until the image stays within 5% "
      "(relative MAE) of where it settles after the strongest light is switched off, on again, and moved by "
      "10% of the scene's size (never: not within the frames measured). **Reaches 0**: whether the light "
      "switched off leaves nothing behind (at most 1/1000 of the scene's light; otherwise what is left).\n";
  out +=
      "- **Path tracer needs**: how many times this configuration's time the path tracer needs to reach "
      "the same indirect rel. RMSE (— outside the range the benchmark measured).\n";
  out +=
      "- **Pareto**: ✓ when no configuration of the same technique is both at least as fast and at "
      "least as accurate (indirect rel. RMSE), and better in one.\n";
  out += "- **Image**, **heat map**: the tone-mapped image and its relative radiance error.\n\n";
}

// "mean / p95" of the flicker, "off / on / move" response frames, "yes"/"no": — when the
// configuration's behaviour over time was not measured.
std::string flickerCell(const Measurement& m) {
  if (!m.temporal) return std::string(kMissing);
  return fmt::format("{} / {}", errorValue(m.flickerMean), errorValue(m.flickerP95));
}
std::string responseCell(const Measurement& m) {
  if (!m.temporal) return std::string(kMissing);
  auto frames = [](int f) { return f < 0 ? std::string("never") : std::to_string(f); };
  return fmt::format("{} / {} / {}", frames(m.responseFramesOff), frames(m.responseFramesOn),
                     frames(m.responseFramesMove));
}
std::string zeroCell(const Measurement& m) {
  if (!m.temporal) return std::string(kMissing);
  return m.reachesZero ? "yes" : fmt::format("no ({})", errorValue(m.offResidue));
}

void appendTechniqueTable(std::string& out, const TechniqueGroup& group, const std::string& heading) {
  std::vector<const Measurement*> rows = group.members;
  // Fastest first; a measurement without a time goes last rather than breaking the order.
  std::stable_sort(rows.begin(), rows.end(), [](const Measurement* a, const Measurement* b) {
    if (std::isnan(a->totalMs) || std::isnan(b->totalMs))
      return !std::isnan(a->totalMs) && std::isnan(b->totalMs);
    return a->totalMs < b->totalMs;
  });

  out += fmt::format("{} {}\n\n", heading, cellText(group.technique));
  out +=
      "| Configuration | GPU ms | CPU ms | Total ms | Memory MiB | Settles after | Direct rel. RMSE | "
      "Indirect "
      "rel. RMSE | Indirect, noise removed | Indirect ÷ reference | Radiance rel. RMSE | Radiance mean rel. "
      "error | Irradiance rel. RMSE | Irradiance ÷ reference | By region | Flicker mean / p95 | Response "
      "frames off / on / move | Reaches 0 | Path tracer needs | Pareto | Image | Heat map |\n";
  out += "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|:-:|---|---|\n";
  for (const Measurement* m : rows) {
    const std::string label = cellText(m->config.label.empty() ? m->config.technique : m->config.label);
    out += fmt::format(
        "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} "
        "| {} "
        "| {} |\n",
        m->config.isDefault ? fmt::format("**{}**", label) : label, milliseconds(m->gpuMs),
        milliseconds(m->cpuMs), milliseconds(m->totalMs), mebibytes(m->persistentBytes + m->transientBytes),
        m->settlingFrames, errorValue(m->direct.relativeRmse), errorValue(m->indirect.relativeRmse),
        errorValue(m->indirect.unbiasedRelativeRmse), errorValue(m->indirect.meanRatio),
        errorValue(m->radiance.relativeRmse), errorValue(m->radiance.meanRelativeError),
        errorValue(m->irradiance.relativeRmse), errorValue(m->irradiance.meanRatio),
        regionRange(m->irradiance), flickerCell(*m), responseCell(*m), zeroCell(*m), pathTracerRatio(*m),
        m->onParetoFront ? "✓" : "", link("img", m->image), link("heat map", m->heatMap));
  }
  out += '\n';
}

void appendNotes(std::string& out, const std::vector<std::string>& notes, const std::string& heading) {
  if (notes.empty()) return;
  out += fmt::format("{} Notes\n\n", heading);
  for (const std::string& note : notes) {
    // Continuation lines indented so a multi-line note stays one bullet.
    std::string bullet;
    for (char c : note) {
      bullet += c;
      if (c == '\n') bullet += "  ";
    }
    out += fmt::format("- {}\n", bullet);
  }
  out += '\n';
}

}  // namespace

namespace {

// One scene's setup, tables, notes and plot under `heading` (## for a report of one
// scene, ### below the scene's own heading otherwise).
void appendScene(std::string& out, const Report& report, const std::string& heading) {
  appendSetup(out, report, heading);
  const std::vector<TechniqueGroup> groups = groupByTechnique(report.measurements);
  if (groups.empty()) out += "No configurations were measured.\n\n";
  for (const TechniqueGroup& group : groups) appendTechniqueTable(out, group, heading);
  appendNotes(out, report.notes, heading);
  out += fmt::format("{} Accuracy versus time\n\n", heading);
  out += fmt::format("![Indirect light's relative RMSE against milliseconds per frame, log-log]({})\n\n",
                     linkTarget(report.plotFile));
}

}  // namespace

bool writeMarkdown(const std::vector<Report>& reports, const std::string& path, std::string* error) {
  if (reports.empty())
    return writeReportFile(path, "# Bounce GI benchmark\n\nNo scene was measured.\n", error);
  std::string out = reports.size() == 1 ? fmt::format("# Bounce GI benchmark: {}\n\n", reports[0].scene)
                                        : std::string("# Bounce GI benchmark\n\n");
  const std::string& command = reports[0].command;
  const std::string fence = codeFence(command);
  out += fmt::format("Reproduce with:\n\n{}sh\n{}\n{}\n\n", fence, command, fence);
  for (const std::string& line : reports[0].preamble) out += line + "\n";
  if (!reports[0].preamble.empty()) out += '\n';
  appendLegend(out);
  if (reports.size() == 1) {
    appendScene(out, reports[0], "##");
  } else {
    for (const Report& r : reports) {
      out += fmt::format("## {}\n\n", cellText(r.scene));
      appendScene(out, r, "###");
    }
  }
  return writeReportFile(path, out, error);
}

bool writeMarkdown(const Report& report, const std::string& path, std::string* error) {
  return writeMarkdown(std::vector<Report>{report}, path, error);
}

}  // namespace bounce::bench
