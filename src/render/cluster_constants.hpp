// Safety margins of the cluster test (cluster_cull.cpp and its SIMD twin, cluster_kernel.cpp),
// each far above the rounding it covers.
#pragma once

namespace zraster::detail {

// Float clip coordinates computed by the vertex stage, and double ones computed by the test, are
// within kClipError * (|row| . (|p|, 1)) of the exact value (three products and three sums in
// float: at most 3 * 2^-24 of that sum; no FMA contraction, -ffp-contract=off).
inline constexpr double kClipError = 0x1p-21;
// Relative slack for quantities evaluated in double (extents, cone angles, the margin).
inline constexpr double kSlack = 1e-12;
inline constexpr double kMarginSlack = 1e-9;
// |x| <= guard * w must hold in float: the box must clear the guard band by this factor.
inline constexpr double kShrink = 1.0 - 0x1p-20;

}  // namespace zraster::detail
