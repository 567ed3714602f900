// bounce-compare: the error of an image against a reference, as bounce-bench measures it.
//
//   bounce-compare IMAGE.exr REFERENCE.exr [--heat-map FILE.png] [--scale S] [--epsilon E]
//                  [--worst N]
//
// Prints relative RMSE, mean relative error, the mean ratio Σ image / Σ reference and its
// lowest and highest over a 4 × 4 grid (ImageErrorStats), and the count of NaN/Inf pixels
// of IMAGE, and with --worst N the N pixels holding most of the squared error. For AOVs of `bounce-render
// --aov` against the same AOV of the path tracer
// (`--gi Reference`). Exit status: 0, or 2 for bad arguments or unreadable or mismatched
// images (one line naming the file).

#include "bounce/image/image_buffer.h"

#include <fmt/format.h>
#include "parse_arguments.h"

#include <CLI/CLI.hpp>

#include <string>

namespace {

constexpr int kBadInput = 2;

int fail(const std::string& message) {
  bounce::app::printError("bounce-compare", message);
  return kBadInput;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bounce-compare: an image's error against a reference (linear EXR)"};
  bounce::app::acceptUnrealSpellings(app);
  std::string imagePath, referencePath, heatMapPath;
  double scale = 0.5, epsilon = 1e-2;
  size_t worst = 0;
  app.add_option("image", imagePath, "The image to judge (EXR)")->required();
  app.add_option("reference", referencePath, "The reference (EXR)")->required();
  app.add_option("--heat-map", heatMapPath, "Write per-pixel relative error as a PNG (red at --scale)");
  app.add_option("--scale", scale, "Relative error shown red in the heat map")->check(CLI::PositiveNumber);
  app.add_option(
         "--epsilon", epsilon,
         "Added to the reference in relative errors, in the images' units (keeps black pixels finite)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--worst", worst, "List the N pixels holding most of the squared error")
      ->check(CLI::Range(size_t(0), size_t(1) << 20));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : kBadInput;
  }

  bounce::ImageBuffer image, reference;
  std::string error;
  if (!bounce::readExr(imagePath, image, &error)) return fail(error);
  if (!bounce::readExr(referencePath, reference, &error)) return fail(error);
  if (image.width != reference.width || image.height != reference.height)
    return fail(fmt::format("{} is {}x{} but {} is {}x{}", imagePath, image.width, image.height,
                            referencePath, reference.width, reference.height));

  const bounce::ImageErrorStats s = bounce::compareImages(image, reference, epsilon);
  fmt::print("relative RMSE        {:.4f}\n", s.relativeRmse);
  fmt::print("mean relative error  {:.4f}\n", s.meanRelativeError);
  fmt::print("image / reference    {:.4f} (4x4 regions {:.3f} .. {:.3f})\n", s.meanRatio, s.lowestRegionRatio,
             s.highestRegionRatio);
  fmt::print("RMSE                 {:.6g}\n", s.rmse);
  fmt::print("non-finite pixels    {}\n", s.nonFinite);
  if (worst > 0) {
    fmt::print("worst pixels         x y: image reference (share of squared error)\n");
    for (const bounce::PixelError& p : bounce::worstPixels(image, reference, worst))
      fmt::print("  {} {}: {:.4g} {:.4g} ({:.2f}%)\n", p.x, p.y, p.image, p.reference,
                 100.0 * p.shareOfSquaredError);
  }
  if (!heatMapPath.empty() &&
      !bounce::writePng(bounce::errorHeatMap(image, reference, scale, epsilon), heatMapPath, &error))
    return fail(error);
  return 0;
}
