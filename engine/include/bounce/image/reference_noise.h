#pragma once
// Errors against a noisy reference. A path-traced reference is an estimate: rendered as
// two independent halves (two seeds, half the samples each), its own noise shows in how
// far they differ, and that noise can be taken out of an error measured against it.
//
// With halves A and B and the reference R = (A + B) / 2 per value, E[(A − B)²] = 2σ²
// for the halves' variance σ², and R's variance is σ²/2 = E[(A − B)²] / 4. So
//   noise floor       sqrt(Σ (A − B)² / 4 / n) / mean(R)
//                     the relative RMSE of R against the truth it estimates, the error
//                     even a perfect image shows against R;
//   unbiased error    sqrt(max(0, Σ (I − R)² − Σ (A − B)² / 4) / n) / mean(R)
//                     the relative RMSE of an image I against that truth: E[(I − R)²] is
//                     (I − truth)² + Var(R) for an I independent of R.
// The clamp at 0 is where an image is closer to the truth than the noise can resolve.

#include "bounce/image/image_buffer.h"

#include <limits>

namespace bounce {

/// NaN where nothing was compared (also the defaults: not measured).
struct NoisyReferenceError {
  static constexpr double kUnmeasured = std::numeric_limits<double>::quiet_NaN();
  double relativeRmse = kUnmeasured;          ///< against R, noise included (as compareImages)
  double relativeMae = kUnmeasured;           ///< mean |I − R| / mean(R)
  double noiseRelativeRmse = kUnmeasured;     ///< R's own noise: the floor above
  double unbiasedRelativeRmse = kUnmeasured;  ///< the error with R's noise taken out
  double meanRatio = kUnmeasured;             ///< Σ I / Σ R
  size_t nonFinite = 0;                       ///< values of I left out for NaN/Inf (as compareImages)
};

/// `image` against the mean of `halfA` and `halfB` over RGB (or the single channel when
/// all three are grey). Values that are NaN/Inf in any of them are left out; sizes that
/// differ, or nothing left to compare, give NaN statistics. A reference whose mean is 0
/// gives relative errors of 0.
NoisyReferenceError compareWithNoisyReference(const ImageBuffer& image, const ImageBuffer& halfA,
                                              const ImageBuffer& halfB);

/// a + b·scale per value (the sizes and channel counts must match; otherwise empty):
/// the mean of two halves is sum(a, b, 1) then ×0.5, an indirect image is a − direct.
ImageBuffer combineImages(const ImageBuffer& a, const ImageBuffer& b, float scaleB, float scaleSum = 1.0f);

}  // namespace bounce
