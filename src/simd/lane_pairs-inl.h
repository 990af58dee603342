// Pairs of vectors computed together, interleaved (lanewise and the operations built on it):
// the same code runs on one vector or on two or four at once.
//
// Highway "-inl" header: included once per instruction set by files that use foreach_target.
#if defined(ZRASTER_SIMD_LANE_PAIRS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ZRASTER_SIMD_LANE_PAIRS_INL_H_
#undef ZRASTER_SIMD_LANE_PAIRS_INL_H_
#else
#define ZRASTER_SIMD_LANE_PAIRS_INL_H_
#endif

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace zraster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// A Pair of vectors (or of Pairs: four) that one computation treats as one wider vector,
// their operations interleaved (part 0's, then part 1's). A loop step whose work is one long
// dependency chain runs at the chain's latency, whatever the vector width: the out-of-order
// window does not reach the next step. Two or four vectors a step fill it.
template <class V>
struct Pair {
    V a, b;
};
template <class T>
inline constexpr bool kIsPair = false;
template <class V>
inline constexpr bool kIsPair<Pair<V>> = true;

// Part I (0 or 1) of a pair; a single vector (a constant) stands for both parts.
template <int I, class T>
HWY_INLINE const T& part(const T& v) {
    return v;
}
template <int I, class V>
HWY_INLINE const V& part(const Pair<V>& v) {
    if constexpr (I == 0)
        return v.a;
    else
        return v.b;
}

// f applied to each part, first to part 0 of every argument, then to part 1.
template <class F, class... X>
HWY_INLINE auto lanewise(F f, const X&... x) {
    if constexpr ((kIsPair<X> || ...)) {
        using R = decltype(lanewise(f, part<0>(x)...));
        return Pair<R>{lanewise(f, part<0>(x)...), lanewise(f, part<1>(x)...)};
    } else {
        return f(x...);
    }
}

template <class X, class Y>
HWY_INLINE auto add(const X& x, const Y& y) {
    return lanewise([](const auto& a, const auto& b) { return hn::Add(a, b); }, x, y);
}
template <class X, class Y>
HWY_INLINE auto sub(const X& x, const Y& y) {
    return lanewise([](const auto& a, const auto& b) { return hn::Sub(a, b); }, x, y);
}
template <class X, class Y>
HWY_INLINE auto mul(const X& x, const Y& y) {
    return lanewise([](const auto& a, const auto& b) { return hn::Mul(a, b); }, x, y);
}
template <class X, class Y>
HWY_INLINE auto div(const X& x, const Y& y) {
    return lanewise([](const auto& a, const auto& b) { return hn::Div(a, b); }, x, y);
}
template <class X>
HWY_INLINE auto sqrt(const X& x) {
    return lanewise([](const auto& a) { return hn::Sqrt(a); }, x);
}
template <class X>
HWY_INLINE auto neg(const X& x) {
    return lanewise([](const auto& a) { return hn::Neg(a); }, x);
}
template <class X, class Y>
HWY_INLINE auto greater(const X& x, const Y& y) {
    return lanewise([](const auto& a, const auto& b) { return hn::Gt(a, b); }, x, y);
}
template <class X, class Y>
HWY_INLINE auto less(const X& x, const Y& y) {
    return lanewise([](const auto& a, const auto& b) { return hn::Lt(a, b); }, x, y);
}
template <class M, class X, class Y>
HWY_INLINE auto select(const M& m, const X& x, const Y& y) {
    return lanewise(
        [](const auto& c, const auto& a, const auto& b) { return hn::IfThenElse(c, a, b); }, m, x,
        y);
}

// `value` in every lane, shaped like `like` (one vector or a pair).
template <class D, class X>
HWY_INLINE X broadcast(D d, float value, const X& like) {
    return lanewise([&](const auto&) { return hn::Set(d, value); }, like);
}

template <class X, class Y>
HWY_INLINE auto dot3(const X& ax, const X& ay, const X& az, const Y& bx, const Y& by, const Y& bz) {
    return add(add(mul(ax, bx), mul(ay, by)), mul(az, bz));
}

// N (1, 2 or 4) vectors as nested Pairs, vector j loaded by load(j).
template <int N, class Load>
HWY_INLINE auto group_of(const Load& load, int first = 0) {
    if constexpr (N == 1) {
        return load(first);
    } else {
        using Half = decltype(group_of<N / 2>(load, first));
        return Pair<Half>{group_of<N / 2>(load, first), group_of<N / 2>(load, first + N / 2)};
    }
}

// Calls visit(vector, j) for the vectors j = 0..N-1 of a group_of<N>.
template <int N, class X, class Visit>
HWY_INLINE void for_each_of(const X& group, const Visit& visit, int first = 0) {
    if constexpr (N == 1) {
        visit(group, first);
    } else {
        for_each_of<N / 2>(group.a, visit, first);
        for_each_of<N / 2>(group.b, visit, first + N / 2);
    }
}

}  // namespace zraster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // include guard (per target)
