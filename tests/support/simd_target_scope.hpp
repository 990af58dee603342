// Restricts Highway's dynamic dispatch to one instruction set for the scope's lifetime, so that a
// test can run every SIMD kernel the machine supports and the library was built for, not only
// the best one.
#pragma once
#include <hwy/targets.h>

#include <cstdint>

namespace zraster::test {

class SimdTargetScope {
  public:
    explicit SimdTargetScope(std::int64_t target) { hwy::SetSupportedTargetsForTest(target); }
    ~SimdTargetScope() { hwy::SetSupportedTargetsForTest(0); }
    SimdTargetScope(const SimdTargetScope&) = delete;
    SimdTargetScope& operator=(const SimdTargetScope&) = delete;
};

}  // namespace zraster::test
