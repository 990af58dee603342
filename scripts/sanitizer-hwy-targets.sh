#!/usr/bin/env bash
# Prints the compiler flag that leaves out of a sanitizer build the Highway targets it would only
# compile, never run (HWY_DISABLED_TARGETS, as a number: the flag passes through a shell):
#   - SSSE3 and SSE4 always: the Release suite tests every kernel on every target, and the
#     kernels compiled per target were a quarter of a sanitizer build's compile time;
#   - AVX-512 (AVX3, AVX3_DL) on a machine without it: under AddressSanitizer the SIMD kernel
#     files take minutes each to compile, a third of it for targets this machine cannot run.
# AVX2 and the portable baseline stay, and AVX-512 where the machine has it.
disabled=$(((1 << 12) | (1 << 11)))
if ! grep -qw avx512f /proc/cpuinfo 2>/dev/null || ! grep -qw avx512bw /proc/cpuinfo 2>/dev/null; then
    disabled=$((disabled | (1 << 8) | (1 << 7)))
fi
echo "-DHWY_DISABLED_TARGETS=$disabled"
