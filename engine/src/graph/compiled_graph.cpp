#include "bounce/graph/compiled_graph.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <numeric>

namespace bounce {

size_t CompiledGraph::executedCount() const {
  return size_t(
      std::count_if(passes.begin(), passes.end(), [](const CompiledPass& p) { return p.executed; }));
}

const CompiledPass* CompiledGraph::find(std::string_view name) const {
  for (const CompiledPass& p : passes)
    if (p.name == name) return &p;
  return nullptr;
}

bool CompiledGraph::executed(std::string_view name) const {
  const CompiledPass* p = find(name);
  return p && p->executed;
}

uint64_t CompiledGraph::transientBytes() const {
  uint64_t total = 0;
  for (const CompiledResource& r : resources)
    if (!r.imported && r.used()) total += r.bytes;
  return total;
}

uint64_t CompiledGraph::aliasedTransientBytes() const {
  return std::accumulate(aliasSlotBytes.begin(), aliasSlotBytes.end(), uint64_t(0));
}

uint64_t CompiledGraph::persistentBytes() const {
  uint64_t total = 0;
  for (const CompiledResource& r : resources)
    if (r.imported) total += r.bytes;
  return total;
}

namespace {

std::string mib(uint64_t bytes) { return fmt::format("{:.2f} MiB", double(bytes) / (1024.0 * 1024.0)); }

std::string describe(const CompiledResource& r) {
  if (!r.image) return fmt::format("buffer {} B", r.buffer.size);
  const TextureDesc& t = r.texture;
  std::string dims = t.type == TextureType::Tex3D ? fmt::format("{}x{}x{}", t.width, t.height, t.depth)
                                                  : fmt::format("{}x{}", t.width, t.height);
  std::string extra;
  if (t.mips > 1) extra += fmt::format(" {} mips", t.mips);
  if (t.layers > 1) extra += fmt::format(" {} layers", t.layers);
  return fmt::format("{} {}{}", dims, formatName(t.format), extra);
}

}  // namespace

std::string CompiledGraph::reportText() const {
  std::string out =
      fmt::format("Render graph: {} passes, {} run, {} culled; transient {} ({} aliased), persistent {}\n",
                  passes.size(), executedCount(), passes.size() - executedCount(), mib(transientBytes()),
                  mib(aliasedTransientBytes()), mib(persistentBytes()));
  auto pointText = [](const CompiledPass& p) {
    std::string point = p.point ? std::string(extensionPointName(*p.point)) : "-";
    if (p.origin != "engine") point += " (" + p.origin + ")";
    return point;
  };
  size_t nameWidth = 4, pointWidth = 5;
  for (const CompiledPass& p : passes) {
    nameWidth = std::max(nameWidth, p.name.size());
    pointWidth = std::max(pointWidth, pointText(p).size());
  }
  out += fmt::format("  {:>2}  {:<{}}  {:<8}  {:<{}}  {:<8}  {}\n", "#", "pass", nameWidth, "queue", "point",
                     pointWidth, "barriers", "status");
  for (size_t i = 0; i < passes.size(); ++i) {
    const CompiledPass& p = passes[i];
    out += fmt::format("  {:>2}  {:<{}}  {:<8}  {:<{}}  {:<8}  {}: {}\n", i, p.name, nameWidth,
                       queueName(p.queue), pointText(p), pointWidth,
                       p.executed ? fmt::format("{}", p.barriers.size()) : "-",
                       p.executed ? "runs" : "culled", p.reason.empty() ? "-" : p.reason);
  }
  size_t resourceWidth = 8;
  for (const CompiledResource& r : resources) resourceWidth = std::max(resourceWidth, r.name.size());
  out += "  resources:\n";
  for (const CompiledResource& r : resources) {
    if (!r.used() && !r.imported) continue;
    std::string life = r.used() ? fmt::format("passes {}..{}", r.firstPass, r.lastPass) : "unused this frame";
    out += fmt::format("    {:<{}}  {:<10}  {:<26}  {:>10}  {}{}\n", r.name, resourceWidth,
                       r.imported ? "persistent" : "transient", describe(r), mib(r.bytes), life,
                       r.aliasSlot >= 0 ? fmt::format(", memory slot {}", r.aliasSlot) : "");
  }
  for (const std::string& e : errors) out += "  error: " + e + "\n";
  return out;
}

std::string CompiledGraph::reportJson() const {
  nlohmann::json j;
  j["passes"] = nlohmann::json::array();
  for (const CompiledPass& p : passes) {
    nlohmann::json barriers = nlohmann::json::array();
    for (const Barrier& b : p.barriers)
      barriers.push_back({{"resource", resources[b.resource].name},
                          {"srcStages", b.before.stages},
                          {"srcAccess", b.before.access},
                          {"oldLayout", int(b.before.layout)},
                          {"dstStages", b.after.stages},
                          {"dstAccess", b.after.access},
                          {"newLayout", int(b.after.layout)}});
    j["passes"].push_back({{"name", p.name},
                           {"queue", queueName(p.queue)},
                           {"point", p.point ? std::string(extensionPointName(*p.point)) : std::string()},
                           {"origin", p.origin},
                           {"executed", p.executed},
                           {"reason", p.reason},
                           {"barriers", barriers}});
  }
  j["resources"] = nlohmann::json::array();
  for (const CompiledResource& r : resources) {
    j["resources"].push_back({{"name", r.name},
                              {"kind", r.image ? "texture" : "buffer"},
                              {"persistent", r.imported},
                              {"bytes", r.bytes},
                              {"firstPass", r.firstPass},
                              {"lastPass", r.lastPass},
                              {"aliasSlot", r.aliasSlot},
                              {"description", describe(r)}});
  }
  j["transientBytes"] = transientBytes();
  j["aliasedTransientBytes"] = aliasedTransientBytes();
  j["persistentBytes"] = persistentBytes();
  j["errors"] = errors;
  return j.dump(2);
}

}  // namespace bounce
