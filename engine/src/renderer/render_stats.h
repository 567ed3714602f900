#pragma once
// Per-pass GPU timings over several frames, with the medians, the culled passes and
// memory, printed as a table and written as JSON (bounce-render --stats).

#include "bounce/engine.h"
#include "bounce/graph/compiled_graph.h"
#include "gpu/graph_executor.h"

#include <array>
#include <map>
#include <string>
#include <vector>

namespace bounce {

class RenderStats {
 public:
  RenderStats(std::string device, uint32_t width, uint32_t height, std::string technique);
  void addFrame(const gpu::FrameResult& frame, const std::vector<Engine::HookTiming>& cpu = {});
  void setGraph(const CompiledGraph& graph, const gpu::MemoryReport& memory);
  /// Frames rendered in all, and the last one's settling notes (bounce/frame/settling.h;
  /// empty: its results had settled).
  void setFrames(uint32_t rendered, std::vector<std::string> settling);

  std::string table() const;
  /// Passes in execution order, and their medians.
  const std::vector<std::string>& passes() const { return order_; }
  double passMedian(const std::string& pass) const;
  /// The median of each unit of the work the pass reported while recording, over the
  /// frames that ran it (zeros for a pass that reported none).
  std::array<double, kWorkUnitCount> passRecordedWork(const std::string& pass) const;
  double frameMedian() const { return median(frameMs_); }
  /// Median CPU milliseconds of the pass hooks' setup per frame, in total.
  double cpuMedian() const { return median(cpuMs_); }
  bool writeJson(const std::string& path, std::string* error) const;

  static double median(std::vector<double> values);

 private:
  std::string device_, technique_;
  uint32_t width_, height_;
  uint32_t framesRendered_ = 0;
  std::vector<std::string> settling_;
  std::vector<std::string> order_;  // passes in execution order
  std::map<std::string, std::vector<double>> passMs_;
  std::map<std::string, std::vector<PassWork>> passWork_;
  std::vector<double> frameMs_;
  std::vector<double> cpuMs_;  // all hooks, per frame
  std::vector<std::string> cpuOrder_;
  std::map<std::string, std::vector<double>> cpuHookMs_;
  std::vector<std::pair<std::string, std::string>> culled_;
  std::vector<std::pair<std::string, std::string>> runReasons_;
  gpu::MemoryReport memory_;
  uint64_t persistentBytes_ = 0;
};

}  // namespace bounce
