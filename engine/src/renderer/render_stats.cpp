#include "renderer/render_stats.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

namespace bounce {

RenderStats::RenderStats(std::string device, uint32_t width, uint32_t height, std::string technique)
    : device_(std::move(device)), technique_(std::move(technique)), width_(width), height_(height) {}

double RenderStats::median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double RenderStats::passMedian(const std::string& pass) const {
  auto it = passMs_.find(pass);
  return it == passMs_.end() ? 0.0 : median(it->second);
}

std::array<double, kWorkUnitCount> RenderStats::passRecordedWork(const std::string& pass) const {
  std::array<double, kWorkUnitCount> medians{};
  auto it = passWork_.find(pass);
  if (it == passWork_.end()) return medians;
  for (size_t u = 0; u < kWorkUnitCount; ++u) {
    std::vector<double> values;
    for (const PassWork& w : it->second) values.push_back(double(w.recorded[u]));
    medians[u] = median(std::move(values));
  }
  return medians;
}

void RenderStats::addFrame(const gpu::FrameResult& frame, const std::vector<Engine::HookTiming>& cpu) {
  double total = 0.0;
  for (const Engine::HookTiming& h : cpu) {
    if (!cpuHookMs_.count(h.hook)) cpuOrder_.push_back(h.hook);
    cpuHookMs_[h.hook].push_back(h.milliseconds);
    total += h.milliseconds;
  }
  cpuMs_.push_back(total);
  for (const gpu::PassTiming& p : frame.passes) {
    if (!passMs_.count(p.name)) order_.push_back(p.name);
    passMs_[p.name].push_back(p.milliseconds);
    passWork_[p.name].push_back(p.work);
  }
  frameMs_.push_back(frame.frameMilliseconds);
}

void RenderStats::setGraph(const CompiledGraph& graph, const gpu::MemoryReport& memory) {
  culled_.clear();
  runReasons_.clear();
  for (const CompiledPass& p : graph.passes)
    (p.executed ? runReasons_ : culled_).emplace_back(p.name, p.reason);
  memory_ = memory;
  persistentBytes_ = graph.persistentBytes();
}

std::string RenderStats::table() const {
  size_t w = 10;
  for (const std::string& n : order_) w = std::max(w, n.size());
  std::string out = fmt::format("{} {}x{}, GI {}: GPU ms per pass (median of {} frames)\n", device_, width_,
                                height_, technique_, frameMs_.size());
  for (const std::string& n : order_) out += fmt::format("  {:<{}}  {:>9.3f}\n", n, w, median(passMs_.at(n)));
  out += fmt::format("  {:<{}}  {:>9.3f}\n", "frame", w, median(frameMs_));
  // CPU work techniques do while setting up their passes (e.g. path tracing); hooks
  // that only declare passes take microseconds and are not listed.
  for (const std::string& n : cpuOrder_)
    if (median(cpuHookMs_.at(n)) >= 0.05)
      out += fmt::format("  cpu: {} {:.3f} ms\n", n, median(cpuHookMs_.at(n)));
  for (const auto& [name, reason] : culled_) out += fmt::format("  culled: {} ({})\n", name, reason);
  return out;
}

void RenderStats::setFrames(uint32_t rendered, std::vector<std::string> settling) {
  framesRendered_ = rendered;
  settling_ = std::move(settling);
}

bool RenderStats::writeJson(const std::string& path, std::string* error) const {
  nlohmann::json j;
  j["device"] = device_;
  j["width"] = width_;
  j["height"] = height_;
  j["technique"] = technique_;
  j["frames"] = framesRendered_;
  j["settling"] = settling_;
  j["timedFrames"] = frameMs_.size();
  j["frameMs"] = median(frameMs_);
  j["passes"] = nlohmann::json::array();
  for (const std::string& n : order_) {
    std::string reason;
    for (const auto& [name, why] : runReasons_)
      if (name == n) reason = why;
    nlohmann::json pass = {
        {"name", n}, {"medianMs", median(passMs_.at(n))}, {"samplesMs", passMs_.at(n)}, {"reason", reason}};
    // What the pass reported doing while recording (median per unit), where it did.
    const std::array<double, kWorkUnitCount> work = passRecordedWork(n);
    for (size_t u = 0; u < kWorkUnitCount; ++u)
      if (work[u] > 0.0) pass["work"][std::string(workUnitName(WorkUnit(u)))] = work[u];
    j["passes"].push_back(std::move(pass));
  }
  j["cpuMs"] = median(cpuMs_);
  j["cpuHooks"] = nlohmann::json::array();
  for (const std::string& n : cpuOrder_)
    j["cpuHooks"].push_back({{"name", n}, {"medianMs", median(cpuHookMs_.at(n))}});
  j["culled"] = nlohmann::json::array();
  for (const auto& [name, reason] : culled_) j["culled"].push_back({{"name", name}, {"reason", reason}});
  j["resources"] = nlohmann::json::array();
  for (const auto& r : memory_.resources)
    j["resources"].push_back({{"name", r.name}, {"bytes", r.bytes}, {"persistent", r.persistent}});
  j["memory"] = {{"transientPoolBytes", memory_.transientPoolBytes}, {"persistentBytes", persistentBytes_}};
  std::ofstream out(path);
  if (!(out << j.dump(2) << '\n')) {
    if (error) *error = fmt::format("cannot write {}", path);
    return false;
  }
  return true;
}

}  // namespace bounce
