// Shader hot reload as the viewer uses it (PipelineCache::reloadChanged, twice a second):
// an edited shader file, or a file it includes, rebuilds the pipelines that use it; an
// edit that does not compile is one "file:line: message" error and the last good
// pipeline stays in use; a later fix is picked up. Runs on the test device (lavapipe)
// with validation on.

#include "bounce/gpu/barriers.h"
#include "bounce/gpu/buffer.h"
#include "bounce/gpu/device.h"
#include "bounce/gpu/pipeline.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

namespace bounce::gpu {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

/// A compute shader that writes `value` (a GLSL expression) to its one buffer; the
/// statement is on line 4, where a bad expression's error points.
std::string writer(const std::string& value, const std::string& include = {}) {
  return "#version 460\n" + (include.empty() ? "\n" : "#include \"" + include + "\"\n") +
         "layout(local_size_x = 1) in; layout(binding = 0, std430) buffer Out { uint value; };\n"
         "void main() { value = " +
         value + "; }\n";
}

class ShaderHotReloadTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string error;
    device = Device::create({.validation = true}, &error);
    ASSERT_TRUE(device) << error;
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    root_ = fs::temp_directory_path() /
            (std::string("bounce_hot_reload_") + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(root_);
    fs::create_directories(root_ / "shaders");
    // With a SPIR-V cache, as the viewer runs: an edit must miss it (new source, new hash).
    compiler = std::make_unique<ShaderCompiler>(root_, std::vector<fs::path>{}, root_ / "cache");
    cache = std::make_unique<PipelineCache>(*device, *compiler);
  }
  void TearDown() override {
    cache.reset();
    compiler.reset();
    if (device) {
      EXPECT_EQ(device->validationErrorCount(), 0u) << [&] {
        std::string all;
        for (const auto& m : device->validationMessages()) all += m + "\n";
        return all;
      }();
    }
    std::error_code ec;
    fs::remove_all(root_, ec);
  }

  /// Writes `text` to shaders/`name`. A file that existed gets a modification time
  /// later than its last one, so the edit is seen however coarse the file system's
  /// clock is and however quickly the test edits.
  void edit(const std::string& name, const std::string& text) {
    const fs::path path = root_ / "shaders" / name;
    const bool existed = fs::exists(path);
    const fs::file_time_type before = existed ? fs::last_write_time(path) : fs::file_time_type();
    std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
    if (existed) fs::last_write_time(path, before + std::chrono::seconds(2));
  }

  /// Runs `pipeline` once and returns the value it wrote.
  uint32_t run(const Pipeline& pipeline) {
    Buffer out(*device, sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUsage::Readback, "out");
    device->submitAndWait([&](VkCommandBuffer cmd) {
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.handle());
      DescriptorWrites(pipeline).buffer("Out", out.handle()).push(*device, cmd);
      vkCmdDispatch(cmd, 1, 1, 1);
      memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                    VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    });
    return *static_cast<const uint32_t*>(out.mapped());
  }

  std::unique_ptr<Device> device;
  std::unique_ptr<ShaderCompiler> compiler;
  std::unique_ptr<PipelineCache> cache;
  fs::path root_;
};

TEST_F(ShaderHotReloadTest, ABrokenEditKeepsTheLastGoodPipelineAndAFixReplacesIt) {
  const ShaderSource source{"shaders/reload.comp", {}};
  edit("reload.comp", writer("1u"));
  const Pipeline& good = cache->compute(source);
  ASSERT_EQ(run(good), 1u);

  // Nothing changed: nothing is rebuilt (a rebuilt pipeline is a new object).
  const uint64_t generation = cache->generation();
  EXPECT_TRUE(cache->reloadChanged().empty());
  EXPECT_EQ(&cache->compute(source), &good);
  EXPECT_EQ(cache->generation(), generation);

  // A syntax error: one error, one line, naming the file and line...
  edit("reload.comp", writer("2u +"));
  const std::vector<std::string> errors = cache->reloadChanged();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_THAT(errors[0], StartsWith("shaders/reload.comp:4: "));
  EXPECT_THAT(errors[0], HasSubstr("syntax error"));
  EXPECT_THAT(errors[0], Not(HasSubstr("\n")));
  // ...while the last good pipeline stays in the cache and still runs.
  EXPECT_EQ(&cache->compute(source), &good);
  EXPECT_EQ(run(cache->compute(source)), 1u);
  // The broken file is not retried until it changes again; nothing was rebuilt.
  EXPECT_TRUE(cache->reloadChanged().empty());
  EXPECT_EQ(cache->generation(), generation);

  // The fix is picked up: a new pipeline that writes the new value, and the generation
  // moves (what was rendered before may look different now).
  edit("reload.comp", writer("3u"));
  EXPECT_TRUE(cache->reloadChanged().empty());
  EXPECT_EQ(run(cache->compute(source)), 3u);
  EXPECT_EQ(cache->generation(), generation + 1);
}

TEST_F(ShaderHotReloadTest, AnEditToAnIncludedFileRebuildsThePipelinesThatIncludeIt) {
  edit("value.glsl", "const uint kValue = 5u;\n");
  edit("includes.comp", writer("kValue", "value.glsl"));
  edit("standalone.comp", writer("7u"));
  const ShaderSource includes{"shaders/includes.comp", {}}, standalone{"shaders/standalone.comp", {}};
  ASSERT_EQ(run(cache->compute(includes)), 5u);
  const Pipeline& untouched = cache->compute(standalone);
  ASSERT_EQ(run(untouched), 7u);

  edit("value.glsl", "const uint kValue = 6u;\n");
  EXPECT_TRUE(cache->reloadChanged().empty());
  EXPECT_EQ(run(cache->compute(includes)), 6u);
  // A pipeline that does not include the file is left alone.
  EXPECT_EQ(&cache->compute(standalone), &untouched);
  EXPECT_EQ(run(untouched), 7u);

  // An error in the included file names the included file.
  edit("value.glsl", "const uint kValue = noSuchConstant;\n");
  const std::vector<std::string> errors = cache->reloadChanged();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_THAT(errors[0], StartsWith("shaders/value.glsl:1: "));
  EXPECT_EQ(run(cache->compute(includes)), 6u);
}

}  // namespace
}  // namespace bounce::gpu
