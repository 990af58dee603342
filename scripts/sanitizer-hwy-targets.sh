#!/usr/bin/env bash
# Prints the compiler flag that leaves Highway's SSSE3 and SSE4 targets out of a build
# (HWY_DISABLED_TARGETS = HWY_SSSE3 | HWY_SSE4, as a number: the flag passes through a shell).
# The sanitizer builds use it to compile the SIMD kernels for fewer targets.
echo "-DHWY_DISABLED_TARGETS=$(((1 << 12) | (1 << 11)))"
