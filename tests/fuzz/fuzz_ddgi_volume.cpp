// libFuzzer target: DDGIVolume extras (issue 45). The input's first line is a node's
// scale (three numbers, the volume's half extents; anything else keeps 1 m), the rest the
// JSON of its "DDGIVolume" object. The node is loaded as glTF with the DDGI plugin's
// volume kind, and the plugin's volume specs are made from it at several r.DDGI.ProbeSpacing
// values and probe limits. Every volume they keep must have a grid the plugin can use
// (validate() says ""), finite spacings, and, where the spacing came from a setting and not
// from ProbeCounts, no more probes than the limit.

#include "bounce/scene/gltf_loader.h"
#include "fuzz_support.h"
#include "volume_specs.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view input = bounce::fuzz::text(data, size);
  const size_t newline = input.find('\n');
  const std::string_view scaleLine = input.substr(0, newline);
  const std::string_view body = newline == std::string_view::npos ? "{}" : input.substr(newline + 1);
  double scale[3] = {1.0, 1.0, 1.0};
  std::istringstream numbers{std::string(scaleLine)};
  for (double& s : scale)
    if (!(numbers >> s) || !std::isfinite(s)) s = 1.0;
  std::ostringstream doc;
  doc.precision(17);
  doc << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"name": "V", "scale": [)"
      << scale[0] << ", " << scale[1] << ", " << scale[2] << R"(], "extras": {"DDGIVolume": )" << body
      << "}}]}";
  const std::string path = bounce::fuzz::scratchFile(doc.str(), ".gltf");
  bounce::SceneExtrasSchema schema;
  schema.volumeKinds.push_back({bounce::ddgi::kVolumeKind, "", bounce::ddgi::volumeFields()});
  const bounce::GltfLoadResult loaded = bounce::loadGltf(path, &schema);
  if (!loaded.scene) return 0;
  const bool ownCounts = body.find("ProbeCounts") != std::string_view::npos;
  for (const float spacing : {0.0f, 0.001f, 1.0f, -1.0f, NAN})
    for (const uint64_t limit : {uint64_t(8), uint64_t(4096), bounce::ddgi::maxProbes(~0ull, 1432, 256)}) {
      std::vector<std::string> problems;
      for (const bounce::ddgi::VolumeSpec& v :
           bounce::ddgi::volumeSpecs(*loaded.scene, spacing, 8, 10, problems, limit)) {
        const std::string why = v.grid.validate(8, 10);
        if (!why.empty()) {
          fprintf(stderr, "fuzz_ddgi_volume: volume '%s' kept with an unusable grid: %s\n", v.name.c_str(),
                  why.c_str());
          std::abort();
        }
        if (!ownCounts && v.grid.probeCount() > limit) {
          fprintf(stderr, "fuzz_ddgi_volume: %u probes beyond the limit of %llu\n", v.grid.probeCount(),
                  static_cast<unsigned long long>(limit));
          std::abort();
        }
      }
    }
  return 0;
}
