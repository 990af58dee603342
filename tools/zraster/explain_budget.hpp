// The budget of `zraster explain`'s own pictures. Its frames are held in memory until the
// folder is written (and the animation holds a padded copy of each): at --size 8192x8192 the
// z-buffer's nine frames took 4.9 GB and minutes. Each algorithm counts the pixels of the
// pictures it will make before making them, against --max-explain-pixels.
#pragma once
#include <cstdint>
#include <string>

namespace zraster::cli {

// Pixels of all pictures one explain run makes (each frame of a sequence once). 2^27 pixels
// (512 MiB as RGBA; about twice that held at the peak) covers the default size with every frame
// and the z-buffer's nine frames up to 2048x2048.
inline constexpr std::uint64_t kDefaultMaxExplainPixels = std::uint64_t{1} << 27;

// Throws LimitExceeded "max_explain_pixels" (about --size) when `pictures` pictures of
// `pixels_each` pixels are more than `limit`; `what` names them ("explain zbuffer's 9 frames"),
// `fewer` says how else to make fewer ("or raise --step", or empty).
void check_explain_pixels(std::uint64_t pictures, std::uint64_t pixels_each, std::uint64_t limit,
                          const std::string& what, const std::string& fewer = "");

}  // namespace zraster::cli
