#include "bounce-render-bench/device_ceilings.h"

#include "bounce-render-bench/timed_dispatch.h"
#include "bounce/gpu/barriers.h"
#include "bounce/gpu/buffer.h"
#include "bounce/gpu/image.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace bounce {

namespace {

constexpr const char* kShaders = "engine/apps/bounce-render-bench/shaders/";

gpu::ShaderSource shader(const char* name) { return {std::string(kShaders) + name, {}}; }

uint32_t groups(uint64_t threads, uint32_t local) { return uint32_t((threads + local - 1) / local); }

template <class T>
void push(VkCommandBuffer cmd, const gpu::Pipeline& p, const T& value) {
  vkCmdPushConstants(cmd, p.layout(), p.stages(), 0, sizeof(T), &value);
}

// A copy run reads and writes what the previous run (or the set-up) wrote: wait for it,
// then bind the pipeline.
void bindAfterPreviousRun(VkCommandBuffer cmd, const gpu::Pipeline& p) {
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT,
                     VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                     VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
  vkCmdBindPipeline(cmd, p.bindPoint(), p.handle());
}

double fmaFlopsPerSecond(const gpu::Device& device, gpu::PipelineCache& pipelines, const TimedDispatch& timer,
                         int runs) {
  constexpr uint32_t kInvocations = 1u << 17, kTrips = 64;
  constexpr double kFlopsPerInvocation = kTrips * 8.0 * 4 * 4 * 2;  // trips × unroll × vec4s × lanes × 2
  gpu::Buffer result(device, kInvocations * 16ull, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                     gpu::MemoryUsage::DeviceLocal, "ceiling.fma");
  const gpu::Pipeline& p = pipelines.compute(shader("ceiling_fma.comp"));
  struct {
    float m, c;
    uint32_t trips;
  } constants{0.999f, 0.001f, kTrips};
  const double s = timer.medianSeconds(
      [&](VkCommandBuffer cmd) {
        vkCmdBindPipeline(cmd, p.bindPoint(), p.handle());
        gpu::DescriptorWrites(p).buffer("Result", result.handle()).push(device, cmd);
        push(cmd, p, constants);
        vkCmdDispatch(cmd, groups(kInvocations, p.localSize()[0]), 1, 1);
      },
      runs);
  return kInvocations * kFlopsPerInvocation / s;
}

double bufferBytesPerSecond(const gpu::Device& device, gpu::PipelineCache& pipelines,
                            const TimedDispatch& timer, int runs) {
  constexpr uint64_t kBytes = 64ull << 20;  // per buffer; under maxStorageBufferRange (128 MiB)
  const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  gpu::Buffer source(device, kBytes, usage, gpu::MemoryUsage::DeviceLocal, "ceiling.source");
  gpu::Buffer destination(device, kBytes, usage, gpu::MemoryUsage::DeviceLocal, "ceiling.destination");
  device.submitAndWait([&](VkCommandBuffer cmd) {  // touch every page before timing
    vkCmdFillBuffer(cmd, source.handle(), 0, VK_WHOLE_SIZE, 0x3f800000u);
    vkCmdFillBuffer(cmd, destination.handle(), 0, VK_WHOLE_SIZE, 0);
  });
  const gpu::Pipeline& p = pipelines.compute(shader("ceiling_buffer_copy.comp"));
  const uint32_t count = uint32_t(kBytes / 16);
  const double s = timer.medianSeconds(
      [&](VkCommandBuffer cmd) {
        bindAfterPreviousRun(cmd, p);
        gpu::DescriptorWrites(p)
            .buffer("Source", source.handle())
            .buffer("Destination", destination.handle())
            .push(device, cmd);
        push(cmd, p, count);
        vkCmdDispatch(cmd, groups(count, p.localSize()[0]), 1, 1);
      },
      runs);
  return 2.0 * double(kBytes) / s;
}

std::vector<uint16_t> halfPattern(uint32_t size) {
  std::vector<uint16_t> texels(size_t(size) * size * size * 4);
  // Half-float bit patterns of values in [0.5, 1): exponent 0x3800, varying mantissa.
  for (size_t i = 0; i < texels.size(); ++i)
    texels[i] = uint16_t(0x3800u | ((i * 2654435761u >> 8) & 0x3ffu));
  return texels;
}

/// A 3D RGBA16F volume of `size`³ holding a smooth pattern (so filtering does real work),
/// left in `layout`. `usage` must include TRANSFER_DST.
gpu::Image makeVolume(const gpu::Device& device, uint32_t size, VkImageUsageFlags usage, VkImageLayout layout,
                      const char* name) {
  gpu::Image volume(device,
                    TextureDesc{.type = TextureType::Tex3D,
                                .format = VK_FORMAT_R16G16B16A16_SFLOAT,
                                .width = size,
                                .height = size,
                                .depth = size},
                    usage, name);
  const std::vector<uint16_t> texels = halfPattern(size);
  gpu::uploadImage(device, volume, texels.data(), texels.size() * 2, layout);
  return volume;
}

double imageBytesPerSecond(const gpu::Device& device, gpu::PipelineCache& pipelines,
                           const TimedDispatch& timer, int runs) {
  constexpr uint32_t kSize = 128;
  const VkImageUsageFlags usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  gpu::Image source = makeVolume(device, kSize, usage, VK_IMAGE_LAYOUT_GENERAL, "ceiling.imageSource");
  gpu::Image destination =
      makeVolume(device, kSize, usage, VK_IMAGE_LAYOUT_GENERAL, "ceiling.imageDestination");
  const gpu::Pipeline& p = pipelines.compute(shader("ceiling_image_copy.comp"));
  const auto local = p.localSize();
  const double s = timer.medianSeconds(
      [&](VkCommandBuffer cmd) {
        bindAfterPreviousRun(cmd, p);
        gpu::DescriptorWrites(p)
            .storageImage("source", source.view())
            .storageImage("destination", destination.view())
            .push(device, cmd);
        vkCmdDispatch(cmd, groups(kSize, local[0]), groups(kSize, local[1]), groups(kSize, local[2]));
      },
      runs);
  return 2.0 * double(kSize) * kSize * kSize * 8.0 / s;
}

// The same volume copied by vkCmdCopyImage: transfer commands (a pass's copies, clears and
// fills) run no shader, and on lavapipe they are memcpy loops several times faster than
// the copy shader, so they are compared with this instead.
double transferBytesPerSecond(const gpu::Device& device, const TimedDispatch& timer, int runs) {
  constexpr uint32_t kSize = 128;
  const VkImageUsageFlags usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  gpu::Image source = makeVolume(device, kSize, usage, VK_IMAGE_LAYOUT_GENERAL, "ceiling.transferSource");
  gpu::Image destination =
      makeVolume(device, kSize, usage, VK_IMAGE_LAYOUT_GENERAL, "ceiling.transferDestination");
  VkImageCopy region{};
  region.srcSubresource = region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.extent = {kSize, kSize, kSize};
  const double s = timer.medianSeconds(
      [&](VkCommandBuffer cmd) {
        vkCmdCopyImage(cmd, source.handle(), VK_IMAGE_LAYOUT_GENERAL, destination.handle(),
                       VK_IMAGE_LAYOUT_GENERAL, 1, &region);
      },
      runs);
  return 2.0 * double(kSize) * kSize * kSize * 8.0 / s;
}

// `scattered`: each invocation marches from its own random place in its own direction
// (ceiling_trilinear.comp); otherwise neighbours march side by side.
double trilinearSamplesPerSecond(const gpu::Device& device, gpu::PipelineCache& pipelines,
                                 const TimedDispatch& timer, int runs, bool scattered) {
  constexpr uint32_t kSize = 128, kSteps = 64;
  constexpr uint32_t kGrid[3] = {64, 64, 16};
  gpu::Image volume = makeVolume(device, kSize, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, "ceiling.volume");
  const uint64_t invocations = uint64_t(kGrid[0]) * kGrid[1] * kGrid[2];
  gpu::Buffer result(device, invocations * 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                     gpu::MemoryUsage::DeviceLocal, "ceiling.trilinear");
  const gpu::Pipeline& p = pipelines.compute(shader("ceiling_trilinear.comp"));
  const auto local = p.localSize();
  struct {
    uint32_t grid[3];
    uint32_t steps;
    uint32_t scattered;
  } constants{{kGrid[0], kGrid[1], kGrid[2]}, kSteps, scattered ? 1u : 0u};
  const double s = timer.medianSeconds(
      [&](VkCommandBuffer cmd) {
        vkCmdBindPipeline(cmd, p.bindPoint(), p.handle());
        gpu::DescriptorWrites(p)
            // Repeat: a scattered lane that marches off one side goes on from the other,
            // rather than reading the clamped edge (cached, so too fast).
            .sampled("volume", volume.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                     device.sampler(gpu::SamplerKind::LinearRepeat))
            .buffer("Result", result.handle())
            .push(device, cmd);
        push(cmd, p, constants);
        vkCmdDispatch(cmd, groups(kGrid[0], local[0]), groups(kGrid[1], local[1]),
                      groups(kGrid[2], local[2]));
      },
      runs);
  return double(invocations) * kSteps / s;
}

// Dispatches of one invocation, each bound and pushed as a pass's are and followed by a
// barrier (TimedDispatch puts one between repeats): what a dispatch costs however little it
// computes: 22–27 µs on lavapipe on this project's 2-core machine (stop 42; its threads
// start, wait and join). A lower bound for a pass of n dispatches, n / this, that bounds the
// rate of a pass whose work is small; a dispatch of several workgroups costs lavapipe more.
double dispatchesPerSecond(const gpu::Device& device, gpu::PipelineCache& pipelines,
                           const TimedDispatch& timer, int runs) {
  gpu::Buffer result(device, 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUsage::DeviceLocal,
                     "ceiling.dispatch");
  const gpu::Pipeline& p = pipelines.compute(shader("ceiling_dispatch.comp"));
  const uint32_t value = 1;
  const double s = timer.medianSeconds(
      [&](VkCommandBuffer cmd) {
        vkCmdBindPipeline(cmd, p.bindPoint(), p.handle());
        gpu::DescriptorWrites(p).buffer("Result", result.handle()).push(device, cmd);
        push(cmd, p, value);
        vkCmdDispatch(cmd, 1, 1, 1);
      },
      runs);
  return 1.0 / s;
}

}  // namespace

std::optional<double> DeviceCeilings::scatteredPerSecond(WorkUnit unit) const {
  if (unit == WorkUnit::TextureSamples) return scatteredTextureSamplesPerSecond;
  return std::nullopt;
}

std::optional<double> DeviceCeilings::perSecond(WorkUnit unit) const {
  switch (unit) {
    case WorkUnit::BufferBytes:
      return bufferBytesPerSecond;
    case WorkUnit::ImageBytes:
      return imageBytesPerSecond;
    case WorkUnit::TransferBytes:
      return transferBytesPerSecond;
    case WorkUnit::TextureSamples:
      return textureSamplesPerSecond;
    case WorkUnit::Flops:
      return flopsPerSecond;
    case WorkUnit::Dispatches:
      return dispatchesPerSecond;
    case WorkUnit::Rays:
      return std::nullopt;
  }
  return std::nullopt;
}

std::string DeviceCeilings::describeScattered(WorkUnit unit) {
  return unit == WorkUnit::TextureSamples ? "trilinear RGBA16F 3D samples/s, scattered lanes" : std::string();
}

std::string DeviceCeilings::describe(WorkUnit unit) {
  switch (unit) {
    case WorkUnit::BufferBytes:
      return "storage-buffer copy, bytes read + written/s";
    case WorkUnit::ImageBytes:
      return "RGBA16F 3D storage-image copy, bytes read + written/s";
    case WorkUnit::TransferBytes:
      return "RGBA16F 3D vkCmdCopyImage, bytes read + written/s";
    case WorkUnit::TextureSamples:
      return "trilinear RGBA16F 3D samples/s, coherent";
    case WorkUnit::Flops:
      return "FMA chains, flops/s";
    case WorkUnit::Dispatches:
      return "dispatches of 1 invocation + barrier/s";
    case WorkUnit::Rays:
      return "none (rays/s reported as measured)";
  }
  return {};
}

namespace {

// Every rate a DeviceCeilings holds (not `seconds`).
constexpr double DeviceCeilings::*kRates[] = {
    &DeviceCeilings::textureSamplesPerSecond, &DeviceCeilings::scatteredTextureSamplesPerSecond,
    &DeviceCeilings::bufferBytesPerSecond,    &DeviceCeilings::imageBytesPerSecond,
    &DeviceCeilings::transferBytesPerSecond,  &DeviceCeilings::flopsPerSecond,
    &DeviceCeilings::dispatchesPerSecond};

// Each rate of `measurements` picked by `pick` from its sorted values.
template <class Pick>
DeviceCeilings elementWise(const std::vector<DeviceCeilings>& measurements, Pick pick) {
  DeviceCeilings c;
  for (auto rate : kRates) {
    std::vector<double> values;
    for (const DeviceCeilings& m : measurements) values.push_back(m.*rate);
    std::sort(values.begin(), values.end());
    c.*rate = pick(values);
  }
  for (const DeviceCeilings& m : measurements) c.seconds += m.seconds;
  return c;
}

}  // namespace

DeviceCeilings medianOf(const std::vector<DeviceCeilings>& measurements) {
  return elementWise(measurements, [](const std::vector<double>& v) {
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  });
}

DeviceCeilings lowestOf(const std::vector<DeviceCeilings>& measurements) {
  return elementWise(measurements, [](const std::vector<double>& v) { return v.front(); });
}

DeviceCeilings highestOf(const std::vector<DeviceCeilings>& measurements) {
  return elementWise(measurements, [](const std::vector<double>& v) { return v.back(); });
}

DeviceCeilings measureDeviceCeilings(const gpu::Device& device, gpu::PipelineCache& pipelines, int runs) {
  const auto start = std::chrono::steady_clock::now();
  const TimedDispatch timer(device);
  DeviceCeilings c;
  c.flopsPerSecond = fmaFlopsPerSecond(device, pipelines, timer, runs);
  c.bufferBytesPerSecond = bufferBytesPerSecond(device, pipelines, timer, runs);
  c.imageBytesPerSecond = imageBytesPerSecond(device, pipelines, timer, runs);
  c.transferBytesPerSecond = transferBytesPerSecond(device, timer, runs);
  c.textureSamplesPerSecond = trilinearSamplesPerSecond(device, pipelines, timer, runs, false);
  c.scatteredTextureSamplesPerSecond = trilinearSamplesPerSecond(device, pipelines, timer, runs, true);
  c.dispatchesPerSecond = dispatchesPerSecond(device, pipelines, timer, runs);
  c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return c;
}

}  // namespace bounce
