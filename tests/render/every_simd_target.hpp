// Runs a kernel test once per instruction set this machine supports and the build generated
// (Highway's targets), each through the dispatcher: the scalar twin is then compared with every
// SIMD path, not only the best one.
#pragma once
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include "raster/visibility_kernel.hpp"

namespace zraster::test {

template <class Check>
void on_every_simd_target(Check check) {
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        SCOPED_TRACE(hwy::TargetName(target));
        // The dispatcher really switched (not just the best target again).
        ASSERT_STREQ(detail::visibility_kernel_target(), hwy::TargetName(target));
        check();
    }
    hwy::SetSupportedTargetsForTest(0);
}

}  // namespace zraster::test
