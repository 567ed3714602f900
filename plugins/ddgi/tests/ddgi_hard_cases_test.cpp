// DDGI's hard cases with exact answers (../shared/notes/ddgi.md §10), on lavapipe with
// validation on. Each test prints what it measured, so a failure says by how much.

#include "convergence.h"
#include "ddgi_test_support.h"
#include "scene/generated_meshes.h"

#include <glm/gtc/matrix_transform.hpp>

#include <fmt/format.h>

#include <cmath>
#include <cstdio>

namespace bounce::test {
namespace {

constexpr double kPi = 3.14159265358979;

class DdgiHardCases : public RenderFixture {};

/// A grey Lambert material (no specular lobe) of albedo `rho`, added to `scene`.
uint32_t addLambert(Scene& scene, const char* name, float rho) {
  Material m;
  m.name = name;
  m.baseColorFactor = glm::vec4(glm::vec3(rho), 1.0f);
  m.metallicFactor = 0.0f;
  m.specularFactor = 0.0f;
  return scene.addMaterial(m);
}

TEST_F(DdgiHardCases, ClosedFurnaceConvergesAlongTheGeometricSeries) {
  // H1: a closed room, every surface albedo ρ = 0.5 and emission Le = 1, no lights. Physics:
  // E = πLe/(1−ρ) = 2π everywhere. With hysteresis 0 and the brightness clamp off each
  // update adds one bounce: after k updates E_k = E∞(1 − ρᵏ), at every probe texel and so
  // at every pixel (every weighted average of equal values is that value). Tolerance 0.5%:
  // the issue asks 2%; what remains is the RGBA16F rounding of the published channel
  // (measured 0.06%).
  start("content/tests/white_furnace.gltf",
        {"r.DDGI.Hysteresis=0", "r.DDGI.BrightnessThreshold=1e9", "r.Bloom.Intensity=0"}, "DDGI");
  const double rho = 0.5, eInf = kPi * 1.0 / (1.0 - rho);
  for (int k = 1; k <= 10; ++k) {
    RenderedFrame f = render(48, 48, {"indirect-irradiance"});
    ASSERT_TRUE(f.graph.executed("DDGI.Trace"));
    ASSERT_TRUE(f.graph.executed("DDGI.Gather"));
    const double expected = eInf * (1.0 - std::pow(rho, k));
    if (k != 1 && k != 2 && k != 3 && k != 10) continue;
    const ImageBuffer& e = f.images.at("indirect-irradiance");
    for (uint32_t c = 0; c < 3; ++c) {
      const ChannelStats s = channelStats(e, c);
      std::printf("update %d channel %u: E mean %.4f min %.4f max %.4f, expected %.4f\n", k, c, s.mean, s.min,
                  s.max, expected);
      ASSERT_TRUE(s.finite);
      EXPECT_NEAR(s.min, expected, 0.005 * expected) << "update " << k;
      EXPECT_NEAR(s.max, expected, 0.005 * expected) << "update " << k;
    }
  }
}

// The note's transcription of RTXGI's irradiance blend (§4.3) for a furnace, where every
// ray sees the same radiance: the stored gamma-encoded value per update, noise-free. The
// test oracle for the hysteresis curve, written from the note, not from the shader.
struct FurnaceTranscription {
  double rho, le, h, irradianceThreshold, brightnessThreshold, gamma = 5.0;
  double stored = 0.0;  // x, gamma-encoded E/2π
  double irradiance() const { return 2.0 * kPi * std::pow(stored, gamma); }
  void update() {
    const double radiance = le + rho * irradiance() / kPi;  // hits shaded with the previous irradiance
    const double x = std::pow(radiance / 2.0, 1.0 / gamma);
    double hysteresis = stored == 0.0 ? 0.0 : h;
    double delta = x - stored;
    if (stored - x > irradianceThreshold) hysteresis = std::max(0.0, hysteresis - 0.75);
    if (delta > brightnessThreshold) delta *= 0.25;  // grey: luminance(δ) = δ
    double step = (1.0 - hysteresis) * delta;
    if (x < stored)
      step = (step < 0 ? -1.0 : 1.0) * std::min(std::max(1.0 / 1024.0, std::abs(step)), std::abs(delta));
    stored += step;
  }
};

// `v` rounded to the nearest FP16 value (11 significant bits; normal range only, which is
// all the tests need): what the RGBA16F IndirectDiffuse channel reports.
// Devices differ in how they convert: lavapipe truncates (measured: its channel reads
// 6.22266 where the true value is 6.22341), GPUs round to nearest.
double roundToHalf(double v, bool truncate) {
  int e = 0;
  const double m = std::frexp(v, &e);  // v = m·2^e, m in [0.5, 1)
  const double scaled = std::ldexp(m, 11);
  return std::ldexp(truncate ? std::floor(scaled) : std::nearbyint(scaled), e - 11);
}

TEST_F(DdgiHardCases, ClosedFurnaceWithHysteresisFollowsTheTranscribedCurve) {
  // H1 with hysteresis 0.97: the number of updates to reach 99% of E∞ must match the
  // transcription's within the rounding of the channel: with Bounce's thresholds (RTXGI's
  // Test Harness, 0.2 / 1.0; the note: 269 updates for ρ = 0.5, Le = 1) and with the SDK's
  // (0.25 / 0.10; the note: 578). 27 probes (spacing 1 m) keep the frames cheap; the gather
  // runs at full resolution, so every pixel is one probe lookup (no upsampling rounding).
  const double eInf = 2.0 * kPi;
  struct Thresholds {
    const char* name;
    double irradiance, brightness;
    int note;
  };
  for (const Thresholds t :
       {Thresholds{"Bounce (Test Harness)", 0.2, 1.0, 269}, Thresholds{"RTXGI SDK", 0.25, 0.10, 578}}) {
    // RTXGI's blend from the first update: Bounce's warm-up off (the test after next).
    start("content/tests/white_furnace.gltf",
          {"r.DDGI.ProbeSpacing=1", "r.DDGI.RaysPerProbe=64", "r.Bloom.Intensity=0", "r.DDGI.WarmUp=0",
           "r.DDGI.LightingPassScale=1", fmt::format("r.DDGI.IrradianceThreshold={}", t.irradiance),
           fmt::format("r.DDGI.BrightnessThreshold={}", t.brightness)},
          "DDGI");
    // The channel is RGBA16F: near 99% one update adds ~4e-4 W/m² and the format's step
    // at 6.2 is 4e-3, so the crossing is compared as the channel reports it, for either
    // rounding of the conversion.
    auto crossing = [&](bool truncate) {
      FurnaceTranscription model{0.5, 1.0, 0.97, t.irradiance, t.brightness};
      int updates = 0;
      while (roundToHalf(model.irradiance(), truncate) < 0.99 * eInf && updates < 5000) {
        model.update();
        ++updates;
      }
      return updates;
    };
    const int nearest = crossing(false), truncated = crossing(true);
    int gpuUpdates = 0;
    double e = 0.0;
    while (gpuUpdates < std::max(nearest, truncated) + 10) {
      RenderedFrame f = render(4, 4, {"indirect-irradiance"});
      ++gpuUpdates;
      e = channelStats(f.images.at("indirect-irradiance"), 1).min;
      if (e >= 0.99 * eInf) break;
    }
    std::printf(
        "%s thresholds: 99%% of E = 2π after %d updates (transcription: %d rounding to nearest, %d "
        "truncating; the note, in float: %d); E %.4f\n",
        t.name, gpuUpdates, nearest, truncated, t.note, e);
    EXPECT_GE(gpuUpdates, std::min(nearest, truncated) - 1) << t.name;
    EXPECT_LE(gpuUpdates, std::max(nearest, truncated) + 1) << t.name;
    finish();
  }
}

TEST_F(DdgiHardCases, NewProbesWarmUpBounceByBounceThenAverage) {
  // Bounce's warm-up of new probes (convergence.h) in the furnace (ρ = 0.5, E∞ = 2π):
  // 7 sweeps with hysteresis 0 (0.5⁷ < 1% missing), each adding a bounce, then a running
  // mean m/(m+1) up to the volume's 0.97, which it reaches at the 33rd: settled after 40
  // updates, and every frame before says so. Each update must read what the note's
  // transcription gives with that hysteresis, within the channel's FP16 rounding (0.5%).
  // RTXGI's blend from the first update holds 71% of E∞ after as many (measured).
  const double eInf = 2.0 * kPi;
  const ddgi::WarmUp warmUp = ddgi::warmUpFor(0.97f, 0.5f, true);
  ASSERT_EQ(warmUp.bounceSweeps, 7u);
  ASSERT_EQ(warmUp.settledSweeps, 40u);
  double warmed = 0.0, rtxgi = 0.0;
  for (const bool on : {true, false}) {
    start("content/tests/white_furnace.gltf",
          {"r.DDGI.ProbeSpacing=1", "r.DDGI.RaysPerProbe=64", "r.Bloom.Intensity=0",
           "r.DDGI.LightingPassScale=1", fmt::format("r.DDGI.WarmUp={}", on ? 1 : 0)},
          "DDGI");
    FurnaceTranscription model{0.5, 1.0, 0.97, 0.2, 1.0};
    double e = 0.0;
    for (uint64_t update = 0; update <= warmUp.settledSweeps; ++update) {
      const RenderedFrame f = render(4, 4, {"indirect-irradiance"});
      e = channelStats(f.images.at("indirect-irradiance"), 1).min;
      if (!on) continue;
      model.h = ddgi::warmUpHysteresis(0.97f, warmUp, update);
      model.update();
      EXPECT_NEAR(e, model.irradiance(), 0.005 * model.irradiance()) << "update " << update;
      EXPECT_EQ(f.settling.empty(), update >= warmUp.settledSweeps) << "update " << update;
      if (update + 1 == warmUp.bounceSweeps || update == warmUp.settledSweeps)
        std::printf("warm-up: update %llu (hysteresis %.3f): E %.4f, transcription %.4f, E∞ %.4f\n",
                    static_cast<unsigned long long>(update + 1), model.h, e, model.irradiance(), eInf);
    }
    (on ? warmed : rtxgi) = e;
    finish();
  }
  std::printf("after %llu updates: %.1f%% of E∞ warmed up, %.1f%% without\n",
              static_cast<unsigned long long>(warmUp.settledSweeps + 1), 100.0 * warmed / eInf,
              100.0 * rtxgi / eInf);
  EXPECT_GT(warmed, 0.995 * eInf);
  EXPECT_LT(warmed, 1.005 * eInf);
  EXPECT_LT(rtxgi, 0.8 * eInf);
}

TEST_F(DdgiHardCases, SmallerIrradianceFormatsStillConverge) {
  // The furnace with hysteresis 0.97 in RGBA16F and in the talk's R11G11B10F. Without the
  // one-unit-in-the-last-place minimum step their updates round away near the end: RGBA16F
  // would stall at 92% of E∞ (the note's transcription with FP16 rounding). With it RGBA16F
  // passes 99% (in 177 updates, sooner than float's 271: the last steps are whole units).
  // R11G11B10F still stops short: below 1 its red and green hold 1/128 steps of the gamma-5
  // value, and once the update's target (which the bounce feedback keeps below E∞) lies
  // less than half a step above the stored value, lavapipe's truncating conversion keeps
  // it there — measured 96.1% of E∞ (RTXGI multiplies by 1.0989 for the same loss in its
  // 10-bit format). It is a memory mode; the bound below is 95%.
  const double eInf = 2.0 * kPi;
  struct Format {
    const char* name;
    double reaches;
  };
  for (const Format f : {Format{"RGBA16F", 0.99}, Format{"R11G11B10F", 0.95}}) {
    // The warm-up off: its running mean takes the small steps the minimum step is for
    // only after hundreds of updates, as RTXGI's blend does.
    start("content/tests/white_furnace.gltf",
          {"r.DDGI.ProbeSpacing=1", "r.DDGI.RaysPerProbe=64", "r.Bloom.Intensity=0", "r.DDGI.WarmUp=0",
           "r.DDGI.LightingPassScale=1", fmt::format("r.DDGI.IrradianceFormat={}", f.name)},
          "DDGI");
    int updates = 0;
    double e = 0.0;
    for (; updates < 700 && e < f.reaches * eInf; ++updates)
      e = channelStats(render(4, 4, {"indirect-irradiance"}).images.at("indirect-irradiance"), 1).min;
    std::printf("%s: %.0f%% of E∞ after %d updates (E %.4f, E∞ %.4f)\n", f.name, f.reaches * 100.0, updates,
                e, eInf);
    EXPECT_LT(updates, 700) << f.name;
    EXPECT_LE(e, 1.005 * eInf) << f.name << ": never above E∞ beyond rounding";
    finish();
  }
}

TEST_F(DdgiHardCases, NothingToBounceCullsEveryPassAndMatchesNoGi) {
  // The Cornell box with its light not flagged for DDGI and no emissive material: every
  // DDGI pass is culled with the reason, and the image equals the one without GI.
  start("content/cornell_box.gltf", {"Light.DdgiIndirectLighting=0", "r.Bloom.Intensity=0"}, "DDGI");
  RenderedFrame f = render(32, 32, {"radiance"});
  for (const char* pass :
       {"DDGI.Constants", "DDGI.Trace", "DDGI.BlendIrradiance", "DDGI.BlendDistance", "DDGI.Gather"}) {
    EXPECT_FALSE(f.graph.executed(pass)) << pass;
    for (const CompiledPass& p : f.graph.passes)
      if (p.name == pass) {
        EXPECT_NE(p.reason.find("nothing to bounce"), std::string::npos) << p.reason;
      }
  }
  const ImageBuffer withDdgi = f.images.at("radiance");
  finish();
  start("content/cornell_box.gltf", {"r.Bloom.Intensity=0"}, "none");
  const ImageBuffer none = render(32, 32, {"radiance"}).images.at("radiance");
  ASSERT_EQ(withDdgi.pixels.size(), none.pixels.size());
  for (size_t i = 0; i < none.pixels.size(); ++i) ASSERT_EQ(withDdgi.pixels[i], none.pixels[i]) << i;
}

TEST_F(DdgiHardCases, DisablingCullsEveryPassUnderEitherName) {
  // r.DDGI.Enable 0, or its RTXGI-UE name r.RTXGI.DDGI 0: every DDGI pass culled with the
  // reason; back on, they run again.
  start("content/cornell_box.gltf", {"r.RTXGI.DDGI=0", "r.Bloom.Intensity=0"}, "DDGI");
  RenderedFrame f = render(16, 16, {});
  EXPECT_FALSE(f.graph.executed("DDGI.Trace"));
  EXPECT_FALSE(f.graph.executed("DDGI.Gather"));
  for (const CompiledPass& p : f.graph.passes)
    if (p.name == "DDGI.Gather") {
      EXPECT_NE(p.reason.find("r.DDGI.Enable is 0"), std::string::npos) << p.reason;
    }
  engine->console().execute("r.DDGI.Enable 1");
  EXPECT_TRUE(render(16, 16, {}).graph.executed("DDGI.Trace"));
}

TEST_F(DdgiHardCases, ALightSwitchedOffReachesExactlyZero) {
  // H4: converge with the light on, then set its intensity to 0 (still flagged): the
  // probes' rays then see only the bounce of what the probes still hold, which falls by
  // at most h + (1 − h)ρ per update, and a channel whose rays see exactly nothing moves to 0
  // by at least 1/1024 per update: the published light must read exactly 0 within the
  // ⌈1024·x⌉ updates of the largest stored value x ≤ 1 (the stored values here are
  // (E/2π)^(1/5) < 1). Measured: 55 updates, where the RGBA16F channel rounds E to 0.
  start("content/cornell_box.gltf", {"r.DDGI.Hysteresis=0.5", "r.Bloom.Intensity=0"}, "DDGI");
  for (int i = 0; i < 8; ++i) render(24, 24, {});
  const ChannelStats lit =
      channelStats(render(24, 24, {"indirect-irradiance"}).images.at("indirect-irradiance"), 1);
  std::printf("lit: indirect E mean %.4f max %.4f\n", lit.mean, lit.max);
  ASSERT_GT(lit.mean, 0.01);
  engine->scene()->editLight(0, [](Light& l) { l.intensity = 0.0f; });
  int updates = 0;
  double maxE = lit.max;
  for (; updates < 1100 && maxE > 0.0; ++updates)
    maxE = channelStats(render(8, 8, {"indirect-irradiance"}).images.at("indirect-irradiance"), 1).max;
  std::printf("light off: indirect E reached %.6g after %d updates\n", maxE, updates);
  EXPECT_EQ(maxE, 0.0);
  EXPECT_LE(updates, 1024);
}

TEST_F(DdgiHardCases, APlaneUnderAUniformSkySeesPiTimesTheSky) {
  // H3: a plane (ρ 0.5) under a uniform sky of radiance 1 and nothing else (its light is
  // not flagged for DDGI): away from its edges it sees the whole sky hemisphere and none
  // of itself, so E = π Ls. One update with hysteresis 0 gives it; the probes below the
  // plane see its back and keep nothing (random-ray backfaces above 10%), and their
  // weight is crushed. Tolerance 2%.
  start(
      "content/tests/lambert_plane_directional.gltf",
      {"r.DDGI.SkyRadiance=1", "Light.DdgiIndirectLighting=0", "r.DDGI.Hysteresis=0", "r.Bloom.Intensity=0"},
      "DDGI");
  RenderedFrame f;
  for (int i = 0; i < 3; ++i) f = render(32, 32, {"indirect-irradiance"});
  const ImageBuffer& e = f.images.at("indirect-irradiance");
  // The central half of the view: the plane's middle, more than a probe spacing from its edges.
  const ChannelStats s =
      channelStats(e, 1, [](uint32_t x, uint32_t y) { return x >= 8 && x < 24 && y >= 8 && y < 24; });
  std::printf("plane under a sky of 1: E mean %.4f min %.4f max %.4f (π = %.4f)\n", s.mean, s.min, s.max,
              kPi);
  EXPECT_TRUE(s.finite);
  EXPECT_NEAR(s.min, kPi, 0.02 * kPi);
  EXPECT_NEAR(s.max, kPi, 0.02 * kPi);
}

TEST_F(DdgiHardCases, OpenWhiteFurnaceShowsTheSkyOnEverySurface) {
  // H2: a floor with a box on it, every surface albedo 1, no emission and no light, under a
  // uniform sky of radiance 1. Every surface then reflects exactly the sky (L = 1, E = π)
  // and the objects vanish: each probe texel sees radiance 1 whether its rays leave or hit,
  // so every weighted average is π. The infinite bounce gets there at the rate the most
  // enclosed probe's occluded fraction decays (hysteresis 0). Tolerance 2% for E and for
  // the radiance (the G-buffer's 8-bit albedo of 1 is exact). Classification on: probes
  // inside the 1 m box (relocation cannot move them, their nearest face is past 45% of a
  // cell) keep nothing, and with classification off they pulled pixels beside the box
  // down by up to 6.6% (mean 0.3%); classified inactive, they are skipped and every pixel
  // reads π to FP16 rounding (measured).
  auto scene = std::make_unique<Scene>();
  const uint32_t m = addLambert(*scene, "white", 1.0f);
  scene->addInstance({.name = "floor",
                      .mesh = scene->addMesh(generated::box({6.0f, 0.2f, 6.0f}, false, m, "floor")),
                      .world = glm::translate(glm::mat4(1.0f), {0.0f, -0.1f, 0.0f})});
  scene->addInstance({.name = "box",
                      .mesh = scene->addMesh(generated::box({1.0f, 1.0f, 1.0f}, false, m, "box")),
                      .world = glm::translate(glm::mat4(1.0f), {0.0f, 0.5f, 0.0f})});
  Camera c;
  c.world =
      glm::inverse(glm::lookAt(glm::vec3(1.8f, 1.5f, 1.8f), glm::vec3(0.0f, 0.3f, 0.0f), glm::vec3(0, 1, 0)));
  scene->addCamera(c);
  start("content/tests/emissive_quad.gltf",
        {"r.DDGI.SkyRadiance=1", "r.DDGI.Hysteresis=0", "r.DDGI.ProbeSpacing=0.5",
         "r.DDGI.LightingPassScale=1", "r.Bloom.Intensity=0", "r.DDGI.Classification=1"},
        "DDGI");
  engine->setScene(std::move(scene));
  RenderedFrame f;
  for (int i = 0; i < 30; ++i) f = render(32, 32, {"indirect-irradiance", "radiance"});
  const ImageBuffer &e = f.images.at("indirect-irradiance"), &l = f.images.at("radiance");
  // Pixels that show geometry (the sky behind is black in the radiance: nothing drawn).
  auto drawn = [&](uint32_t x, uint32_t y) { return e.at(x, y, 1) > 0.0f; };
  const ChannelStats es = channelStats(e, 1, drawn), ls = channelStats(l, 1, drawn);
  std::printf(
      "open white furnace, sky 1: E mean %.4f min %.4f max %.4f (π); L mean %.4f min %.4f max %.4f (1)\n",
      es.mean, es.min, es.max, ls.mean, ls.min, ls.max);
  EXPECT_NEAR(es.min, kPi, 0.02 * kPi);
  EXPECT_NEAR(es.max, kPi, 0.02 * kPi);
  EXPECT_NEAR(ls.min, 1.0, 0.02);
  EXPECT_NEAR(ls.max, 1.0, 0.02);
}

TEST_F(DdgiHardCases, HdrEmittersAndDegenerateGeometryStayFinite) {
  // H9/H10: a ceiling panel 10^4 times brighter than the furnace walls, and a furnace with
  // degenerate triangles and zero normals inside: every output finite, the HDR room
  // brighter than the plain furnace's 2π.
  for (const char* scene : {"content/tests/hdr_emitter.gltf", "content/tests/degenerate_geometry.gltf"}) {
    start(scene, {"r.DDGI.Hysteresis=0.5", "r.Bloom.Intensity=0"}, "DDGI");
    RenderedFrame f;
    for (int i = 0; i < 6; ++i) f = render(24, 24, {"indirect-irradiance", "radiance"});
    for (const char* aov : {"indirect-irradiance", "radiance"})
      for (uint32_t c = 0; c < 3; ++c) {
        const ChannelStats s = channelStats(f.images.at(aov), c);
        EXPECT_TRUE(s.finite) << scene << " " << aov;
        EXPECT_GE(s.min, 0.0) << scene << " " << aov;
      }
    const ChannelStats e = channelStats(f.images.at("indirect-irradiance"), 1);
    std::printf("%s: E mean %.4g max %.4g\n", scene, e.mean, e.max);
    EXPECT_GT(e.mean, 1.0) << scene;
    finish();
  }
}

TEST_F(DdgiHardCases, TheSameSeedGivesTheSameImage) {
  // H12: two runs with the same seed are bitwise identical; another seed is not.
  auto run = [&](int seed) {
    start("content/cornell_box.gltf", {fmt::format("r.DDGI.RandomSeed={}", seed), "r.Bloom.Intensity=0"},
          "DDGI");
    ImageBuffer e;
    for (int i = 0; i < 3; ++i) e = render(24, 24, {"indirect-irradiance"}).images.at("indirect-irradiance");
    finish();
    return e.pixels;
  };
  const auto a = run(1), b = run(1), c = run(2);
  EXPECT_TRUE(a == b);
  EXPECT_FALSE(a == c);
}

TEST_F(DdgiHardCases, UpdatesStopWhenConvergedAndAChangeRestartsThem) {
  // A static scene stops tracing once its probes have converged (hysteresis 0, albedo 0.5:
  // 2·⌈ln(1/2048)/ln 0.5⌉ = 22 frames), the report says why, and the image stays; editing
  // a material restarts the updates.
  start("content/tests/white_furnace.gltf", {"r.DDGI.Hysteresis=0", "r.Bloom.Intensity=0"}, "DDGI");
  auto reason = [](const RenderedFrame& f, const char* pass) {
    for (const CompiledPass& p : f.graph.passes)
      if (p.name == pass) return p.reason;
    return std::string();
  };
  RenderedFrame f;
  int updates = 0;
  for (int i = 0; i < 30; ++i) {
    f = render(8, 8, {"indirect-irradiance"});
    if (f.graph.executed("DDGI.Trace")) ++updates;
  }
  std::printf("updates before stopping: %d; then: %s\n", updates, reason(f, "DDGI.Trace").c_str());
  EXPECT_EQ(updates, 22);
  EXPECT_FALSE(f.graph.executed("DDGI.BlendIrradiance"));
  EXPECT_TRUE(f.graph.executed("DDGI.Gather"));
  EXPECT_NE(reason(f, "DDGI.Trace").find("converged"), std::string::npos);
  EXPECT_NEAR(channelStats(f.images.at("indirect-irradiance"), 1).mean, 2.0 * kPi, 0.005 * 2.0 * kPi);
  engine->scene()->editMaterial(0, [](Material& m) { m.emissiveStrength = 2.0f; });
  f = render(8, 8, {"indirect-irradiance"});
  EXPECT_TRUE(f.graph.executed("DDGI.Trace")) << reason(f, "DDGI.Trace");
}

// A 4 m room with a point light and a 20 cm single-sided box around the rest position
// (0.5, 1.5, 0.5) of a probe of the 4×4×4 grid that r.DDGI.ProbeSpacing 1 fits; the box's
// +z face is 5 cm from the probe, its other faces 10 and 15 cm. The camera looks down −z at
// the probe from 0.7 m, between two probe planes.
std::unique_ptr<Scene> probeInsideBoxScene() {
  auto s = std::make_unique<Scene>();
  const uint32_t m = addLambert(*s, "white", 0.7f);
  s->addInstance({.name = "room",
                  .mesh = s->addMesh(generated::box(glm::vec3(4.0f), true, m, "room")),
                  .world = glm::translate(glm::mat4(1.0f), {0.0f, 2.0f, 0.0f})});
  s->addInstance({.name = "box",
                  .mesh = s->addMesh(generated::box(glm::vec3(0.2f), false, m, "box")),
                  .world = glm::translate(glm::mat4(1.0f), {0.5f, 1.5f, 0.45f})});
  Light light;
  light.name = "light";
  light.type = LightType::Point;
  light.intensity = 10.0f;
  light.position = {-1.0f, 3.5f, -1.0f};
  s->addLight(light);
  Camera c;
  c.world = glm::translate(glm::mat4(1.0f), {0.5f, 1.5f, 1.2f});
  c.yfov = 1.0f;
  s->addCamera(c);
  return s;
}

TEST_F(DdgiHardCases, AProbeInsideGeometryIsMovedOutThroughTheNearestFace) {
  // H6: the probe sees backfaces on all its fixed rays; relocation moves it through the
  // nearest face (+z, 5 cm) by that distance plus half the minimum front-face distance
  // (0.15 m): the fixed ray nearest +z, (0.248, 0, 0.969), takes it to (0.55, 1.5, 0.70),
  // outside the box and 0.2 of a cell from rest (< 0.45). The probe-states view
  // (r.DDGI.DebugMode 4) then shows its sphere, yellow-green by the offset, beside the
  // middle of the view; without relocation it stays hidden inside the box.
  // The debug spheres are 3 cm here, so one at rest cannot poke through the 5 cm face.
  // Indirect light stays finite either way. (Its effect on shading is small here: the
  // Chebyshev test already gives the enclosed probe almost no weight; measured in an earlier
  // version of this scene, box centred on the probe, glossy material: E around the box 2.68
  // with relocation, 2.69 without.)
  auto run = [&](bool relocation) {
    start("content/tests/emissive_quad.gltf",
          {"r.DDGI.ProbeSpacing=1", "r.DDGI.Hysteresis=0.5", "r.Bloom.Intensity=0",
           fmt::format("r.DDGI.Relocation={}", relocation ? 1 : 0)},
          "DDGI");
    engine->setScene(probeInsideBoxScene());
    for (int i = 0; i < 8; ++i) {
      const ImageBuffer e = render(32, 32, {"indirect-irradiance"}).images.at("indirect-irradiance");
      EXPECT_TRUE(channelStats(e, 0).finite && channelStats(e, 1).finite && channelStats(e, 2).finite);
    }
    // Spheres of 3 cm, so the one at rest stays inside the box (its face is 5 cm away).
    engine->console().execute("r.DDGI.DebugProbeRadius 0.03");
    engine->console().execute("r.DDGI.DebugMode 4");
    const ImageBuffer shown = render(64, 64, {}, true).images.at("display");
    finish();
    // Pixels of a relocated probe's sphere: green mixed with yellow by the offset (an
    // active probe at rest is plain green, R ≈ 0.08; the walls and box are grey).
    int relocatedPixels = 0;
    for (uint32_t y = 0; y < shown.height; ++y)
      for (uint32_t x = 0; x < shown.width; ++x) {
        const float r = shown.at(x, y, 0), g = shown.at(x, y, 1), b = shown.at(x, y, 2);
        if (r > 0.2f && g > 0.35f && b < 0.2f) ++relocatedPixels;
      }
    return relocatedPixels;
  };
  const int on = run(true), off = run(false);
  std::printf("pixels of a relocated probe in the probe-states view: %d with relocation, %d without\n", on,
              off);
  EXPECT_GE(on, 4);
  EXPECT_EQ(off, 0);
}

TEST_F(DdgiHardCases, ClassificationSwitchesOffAProbeInsideGeometry) {
  // H6 with classification: the probe inside the box sees backfaces on all its fixed rays
  // (over the 25% threshold), so it becomes inactive — red in the probe-states view, where
  // its 10 cm sphere pokes through the box's face 5 cm away — and sampling skips it. With
  // classification off the same sphere is green (active). Relocation off in both.
  auto middle = [&](bool classification) {
    start("content/tests/emissive_quad.gltf",
          {"r.DDGI.ProbeSpacing=1", "r.DDGI.Hysteresis=0.5", "r.Bloom.Intensity=0", "r.DDGI.Relocation=0",
           fmt::format("r.DDGI.Classification={}", classification ? 1 : 0)},
          "DDGI");
    engine->setScene(probeInsideBoxScene());
    for (int i = 0; i < 4; ++i) {
      const ImageBuffer e = render(32, 32, {"indirect-irradiance"}).images.at("indirect-irradiance");
      EXPECT_TRUE(channelStats(e, 0).finite && channelStats(e, 1).finite && channelStats(e, 2).finite);
    }
    engine->console().execute("r.DDGI.DebugProbeRadius 0.1");
    engine->console().execute("r.DDGI.DebugMode 4");
    const ImageBuffer shown = render(64, 64, {}, true).images.at("display");
    finish();
    glm::dvec3 mean(0.0);
    for (uint32_t y = 30; y < 34; ++y)
      for (uint32_t x = 30; x < 34; ++x)
        for (int c = 0; c < 3; ++c) mean[c] += shown.at(x, y, uint32_t(c)) / 16.0;
    return mean;
  };
  const glm::dvec3 on = middle(true), off = middle(false);
  std::printf(
      "probe-states view at the enclosed probe: (%.3f, %.3f, %.3f) classified, (%.3f, %.3f, %.3f) not\n",
      on.x, on.y, on.z, off.x, off.y, off.z);
  EXPECT_GT(on.x, 2.0 * on.y) << "red: inactive";
  EXPECT_GT(off.y, 2.0 * off.x) << "green: active";
}

TEST_F(DdgiHardCases, AnUpdateBudgetUpdatesProbesRoundRobin) {
  // r.DDGI.ProbeUpdateBudget 27 of the furnace's 216 probes: each frame traces 27 probes'
  // rays (the report says so), and after 8 frames every probe has been updated once, so
  // every pixel is lit; after the first frame most probes still hold nothing.
  start("content/tests/white_furnace.gltf",
        {"r.DDGI.ProbeUpdateBudget=27", "r.DDGI.Hysteresis=0", "r.DDGI.LightingPassScale=1",
         "r.Bloom.Intensity=0"},
        "DDGI");
  RenderedFrame f = render(24, 24, {"indirect-irradiance"});
  std::string reason;
  for (const CompiledPass& p : f.graph.passes)
    if (p.name == "DDGI.Trace") reason = p.reason;
  EXPECT_NE(reason.find("27 of 216 probes"), std::string::npos) << reason;
  const ChannelStats first = channelStats(f.images.at("indirect-irradiance"), 1);
  for (int i = 0; i < 7; ++i) f = render(24, 24, {"indirect-irradiance"});
  const ChannelStats eighth = channelStats(f.images.at("indirect-irradiance"), 1);
  std::printf("budget 27 of 216: E after 1 frame mean %.3f min %.3f; after 8 frames mean %.3f min %.3f\n",
              first.mean, first.min, eighth.mean, eighth.min);
  EXPECT_LT(first.mean, 0.5 * eighth.mean);
  EXPECT_GT(eighth.min, 0.9 * kPi);  // every probe holds at least the first bounce, π Le
}

// Two closed 2 m rooms side by side along x, sharing a wall `wall` thick; 10 cm slabs
// elsewhere; a point light in the left room only.
std::unique_ptr<Scene> twoRoomsScene(float wall) {
  auto s = std::make_unique<Scene>();
  const uint32_t m = addLambert(*s, "wall", 0.73f);
  const float t = 0.1f, half = wall * 0.5f, outer = 2.0f + half;
  auto slab = [&](const char* name, glm::vec3 size, glm::vec3 centre) {
    s->addInstance({.name = name,
                    .mesh = s->addMesh(generated::box(size, false, m, name)),
                    .world = glm::translate(glm::mat4(1.0f), centre)});
  };
  const float width = 2.0f * outer + 2.0f * t;
  slab("floor", {width, t, 2.0f + 2.0f * t}, {0.0f, -t / 2, 0.0f});
  slab("ceiling", {width, t, 2.0f + 2.0f * t}, {0.0f, 2.0f + t / 2, 0.0f});
  slab("back", {width, 2.0f, t}, {0.0f, 1.0f, -1.0f - t / 2});
  slab("front", {width, 2.0f, t}, {0.0f, 1.0f, 1.0f + t / 2});
  slab("left", {t, 2.0f, 2.0f}, {-outer - t / 2, 1.0f, 0.0f});
  slab("right", {t, 2.0f, 2.0f}, {outer + t / 2, 1.0f, 0.0f});
  slab("shared", {wall, 2.0f, 2.0f}, {0.0f, 1.0f, 0.0f});
  Light light;
  light.name = "light";
  light.type = LightType::Point;
  light.intensity = 10.0f;
  light.position = {-1.0f - half, 1.5f, 0.0f};
  s->addLight(light);
  return s;
}

TEST_F(DdgiHardCases, LeakThroughAWallFallsWithItsThickness) {
  // H5: the dark room's floor within one probe spacing (0.5 m) of the shared wall, against
  // the lit room's mirror-image floor band, for walls of 0.05 to 1 spacing. Physically 0
  // (the reference path tracer's too, so the note's "≤ 2× the reference" becomes a bound on
  // the fraction). Measured: 1.28% at 0.05 spacing, 0.73% at 0.1, below 0.003% from 0.25 on:
  // probes on the far side see the wall's front faces, and the Chebyshev test then rejects
  // them for points behind it once the wall is thicker than the bias. Bounds: 3% for any
  // wall, 0.1% from a quarter spacing on.
  const float spacing = 0.5f;
  double previous = 1e30;
  for (const float fraction : {0.05f, 0.1f, 0.25f, 0.5f, 1.0f}) {
    const float wall = fraction * spacing;
    start("content/tests/emissive_quad.gltf",
          {fmt::format("r.DDGI.ProbeSpacing={}", spacing), "r.DDGI.Hysteresis=0.5", "r.Bloom.Intensity=0"},
          "DDGI");
    engine->setScene(twoRoomsScene(wall));
    // Looking straight down at the floor band next to the wall, from either side.
    auto band = [&](float side) {
      Camera c;
      c.world = glm::translate(glm::mat4(1.0f), {side * (wall * 0.5f + spacing * 0.5f), 1.0f, 0.0f}) *
                glm::rotate(glm::mat4(1.0f), -1.5707963f, glm::vec3(1.0f, 0.0f, 0.0f));
      c.yfov = 0.45f;  // ~0.46 m of floor: the band
      return FrameView::fromCamera(c, 16, 16);
    };
    for (int i = 0; i < 16; ++i) render(band(-1.0f), {});
    const double lit =
        channelStats(render(band(-1.0f), {"indirect-irradiance"}).images.at("indirect-irradiance"), 1).mean;
    const double dark =
        channelStats(render(band(1.0f), {"indirect-irradiance"}).images.at("indirect-irradiance"), 1).mean;
    finish();
    const double leak = dark / std::max(lit, 1e-9);
    std::printf("wall %.3f m (%.2f spacing): dark band E %.4f, lit band E %.4f, leak %.4f\n", wall, fraction,
                dark, lit, leak);
    EXPECT_GT(lit, 0.01);
    EXPECT_LE(leak, previous + 1e-3) << "leak must not grow with the wall's thickness";
    EXPECT_LT(leak, fraction >= 0.25f ? 0.001 : 0.03) << wall;
    previous = leak;
  }
}

}  // namespace
}  // namespace bounce::test
