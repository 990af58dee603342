// Animated PNG (APNG, the Mozilla extension of PNG that every current browser plays): frames of
// one size, each shown for a fixed time, looping. Written with libdeflate, as the stills are.
// A viewer without APNG support shows the first frame.
#pragma once
#include <cstdint>
#include <vector>

#include "rgba_image.hpp"

namespace zraster::cli {

// The file's bytes. Every frame must have frames[0]'s size; delay in milliseconds.
std::vector<std::uint8_t> encode_apng(const std::vector<RgbaImage>& frames, int delay_ms);

}  // namespace zraster::cli
