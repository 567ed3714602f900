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

void appendSetup(std::string& out, const Report& report) {
  out += "## Setup\n\n";
  out += fmt::format("- Scene: `{}`\n", report.scene);
  out += fmt::format("- Image: {} × {} pixels\n", report.width, report.height);
  out += fmt::format("- Device: {}\n", report.device.empty() ? std::string(kMissing) : report.device);
  out += fmt::format("- Reference: path tracer, {} samples per pixel, {}, rendered in {:.1f} s\n",
                     report.referenceSamples, bouncesText(report.referenceBounces), report.referenceSeconds);
  out += fmt::format("- Timed frames: {} per configuration (times are medians)\n\n", report.timedFrames);
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
      "- **Rel. RMSE**: root-mean-square error against the reference divided by the reference's mean; "
      "**mean rel. error**: per-pixel |error| / (|reference| + ε), averaged. Radiance is the final image, "
      "irradiance the indirect-irradiance output; **irradiance ÷ reference**: its mean over the reference's, "
      "the bias an RMSE does not show (1.2: 20% too bright on average); **by region**: the same ratio's "
      "lowest and highest over a 4 × 4 grid of the image, leaving out cells with under 1/64 of the "
      "reference's light (a mean of 1.2 can be 0.1 in one place and 2 in another).\n";
  out +=
      "- **Path tracer needs**: how many times this configuration's time the path tracer needs to reach "
      "the same radiance rel. RMSE (— outside the range the benchmark measured).\n";
  out +=
      "- **Pareto**: ✓ when no configuration of the same technique is both at least as fast and at "
      "least as accurate, and better in one.\n";
  out += "- **Image**, **heat map**: the tone-mapped image and its relative radiance error.\n\n";
}

void appendTechniqueTable(std::string& out, const TechniqueGroup& group) {
  std::vector<const Measurement*> rows = group.members;
  // Fastest first; a measurement without a time goes last rather than breaking the order.
  std::stable_sort(rows.begin(), rows.end(), [](const Measurement* a, const Measurement* b) {
    if (std::isnan(a->totalMs) || std::isnan(b->totalMs))
      return !std::isnan(a->totalMs) && std::isnan(b->totalMs);
    return a->totalMs < b->totalMs;
  });

  out += fmt::format("## {}\n\n", cellText(group.technique));
  out +=
      "| Configuration | GPU ms | CPU ms | Total ms | Memory MiB | Settles after | Radiance rel. RMSE | "
      "Radiance mean rel. error | Irradiance rel. RMSE | Irradiance ÷ reference | By region | Path tracer "
      "needs | Pareto | Image | Heat map |\n";
  out += "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|:-:|---|---|\n";
  for (const Measurement* m : rows) {
    const std::string label = cellText(m->config.label.empty() ? m->config.technique : m->config.label);
    out += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
                       m->config.isDefault ? fmt::format("**{}**", label) : label, milliseconds(m->gpuMs),
                       milliseconds(m->cpuMs), milliseconds(m->totalMs),
                       mebibytes(m->persistentBytes + m->transientBytes), m->settlingFrames,
                       errorValue(m->radiance.relativeRmse), errorValue(m->radiance.meanRelativeError),
                       errorValue(m->irradiance.relativeRmse), errorValue(m->irradiance.meanRatio),
                       regionRange(m->irradiance), pathTracerRatio(*m), m->onParetoFront ? "✓" : "",
                       link("img", m->image), link("heat map", m->heatMap));
  }
  out += '\n';
}

void appendNotes(std::string& out, const std::vector<std::string>& notes) {
  if (notes.empty()) return;
  out += "## Notes\n\n";
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

bool writeMarkdown(const Report& report, const std::string& path, std::string* error) {
  std::string out = fmt::format("# Bounce GI benchmark: {}\n\n", report.scene);
  const std::string fence = codeFence(report.command);
  out += fmt::format("Reproduce with:\n\n{}sh\n{}\n{}\n\n", fence, report.command, fence);
  appendSetup(out, report);
  appendLegend(out);
  const std::vector<TechniqueGroup> groups = groupByTechnique(report.measurements);
  if (groups.empty()) out += "No configurations were measured.\n\n";
  for (const TechniqueGroup& group : groups) appendTechniqueTable(out, group);
  appendNotes(out, report.notes);
  out += "## Accuracy versus time\n\n";
  out += "![Radiance relative RMSE against milliseconds per frame, log-log](pareto.png)\n";
  return writeReportFile(path, out, error);
}

}  // namespace bounce::bench
