// The vectors of the occlusion kernels (occluder_setup_kernel.cpp, occluder_raster_kernel.cpp,
// occlusion_query_kernel.cpp): one lane per pixel row of a tile, or per triangle in the setup,
// at most kOcclusionTileHeight lanes (16 floats: one AVX-512 vector, two AVX2 ones).
//
// Highway "-inl" header: included once per instruction set by files that use foreach_target.
#if defined(ZRASTER_OCCLUSION_OCCLUSION_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ZRASTER_OCCLUSION_OCCLUSION_LANES_INL_H_
#undef ZRASTER_OCCLUSION_OCCLUSION_LANES_INL_H_
#else
#define ZRASTER_OCCLUSION_OCCLUSION_LANES_INL_H_
#endif

#include <hwy/highway.h>

#include <cstddef>

#include "occlusion/occlusion_kernel.hpp"

HWY_BEFORE_NAMESPACE();
namespace zraster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::CappedTag<float, kOcclusionTileHeight>;
using DI = hn::RebindToSigned<DF>;
using DU = hn::RebindToUnsigned<DF>;
constexpr std::size_t kMaxLanes = kOcclusionTileHeight;  // for arrays of one vector

// Float to int, rounding toward zero, for lanes known to be in int range: Highway's ConvertTo
// spends four more instructions per vector on saturating out-of-range lanes.
HWY_INLINE hn::Vec<DI> TruncInRange(hn::Vec<DF> v) {
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX3
    static_assert(hn::MaxLanes(DF()) == 16);
    return hn::Vec<DI>{_mm512_cvttps_epi32(v.raw)};
#elif HWY_ARCH_X86 && HWY_TARGET == HWY_AVX2
    static_assert(hn::MaxLanes(DF()) == 8);
    return hn::Vec<DI>{_mm256_cvttps_epi32(v.raw)};
#elif HWY_ARCH_X86 && (HWY_TARGET == HWY_SSE4 || HWY_TARGET == HWY_SSSE3)
    static_assert(hn::MaxLanes(DF()) == 4);
    return hn::Vec<DI>{_mm_cvttps_epi32(v.raw)};
#else
    return hn::ConvertTo(DI(), v);
#endif
}

// a < b ? a : b and a > b ? a : b lane by lane, NaN and signed zeros included (the scalar
// twins' selections). x86's min and max instructions are exactly these (they return the second
// operand unless the first compares less, or greater): one instruction instead of a compare and
// a blend. Elsewhere the compare and the select.
HWY_INLINE hn::Vec<DF> LessOf(hn::Vec<DF> a, hn::Vec<DF> b) {
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX3
    return hn::Vec<DF>{_mm512_min_ps(a.raw, b.raw)};
#elif HWY_ARCH_X86 && HWY_TARGET == HWY_AVX2
    return hn::Vec<DF>{_mm256_min_ps(a.raw, b.raw)};
#elif HWY_ARCH_X86 && (HWY_TARGET == HWY_SSE4 || HWY_TARGET == HWY_SSSE3)
    return hn::Vec<DF>{_mm_min_ps(a.raw, b.raw)};
#else
    return hn::IfThenElse(hn::Lt(a, b), a, b);
#endif
}
HWY_INLINE hn::Vec<DF> GreaterOf(hn::Vec<DF> a, hn::Vec<DF> b) {
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX3
    return hn::Vec<DF>{_mm512_max_ps(a.raw, b.raw)};
#elif HWY_ARCH_X86 && HWY_TARGET == HWY_AVX2
    return hn::Vec<DF>{_mm256_max_ps(a.raw, b.raw)};
#elif HWY_ARCH_X86 && (HWY_TARGET == HWY_SSE4 || HWY_TARGET == HWY_SSSE3)
    return hn::Vec<DF>{_mm_max_ps(a.raw, b.raw)};
#else
    return hn::IfThenElse(hn::Gt(a, b), a, b);
#endif
}

}  // namespace zraster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // include guard
