// Writing images and arrays. Every writer is atomic: it writes a temporary file beside the
// target and renames it, so a failure never leaves a truncated file at the output path.
// Failures throw InputError naming the path and the cause. The encoders give the same files'
// bytes in memory (for OutputFiles, zraster/output_files.hpp: several outputs all or nothing).
#pragma once
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>
#include <zraster/export.hpp>

namespace zraster {

// 8-bit PNG, rows top to bottom, `channels` in {1, 2, 3, 4}.
ZRASTER_API void write_png8(const std::filesystem::path& path, int width, int height, int channels,
                            std::span<const std::uint8_t> pixels);
// 16-bit grayscale PNG (big-endian in the file, as PNG requires).
ZRASTER_API void write_png16_gray(const std::filesystem::path& path, int width, int height,
                                  std::span<const std::uint16_t> pixels);
// NumPy .npy version 1.0, C order, shape (height, width), little-endian.
ZRASTER_API void write_npy(const std::filesystem::path& path, int width, int height,
                           std::span<const float> values);
ZRASTER_API void write_npy(const std::filesystem::path& path, int width, int height,
                           std::span<const std::int32_t> values);

ZRASTER_API std::vector<std::uint8_t> encode_png8(int width, int height, int channels,
                                                  std::span<const std::uint8_t> pixels);
ZRASTER_API std::vector<std::uint8_t> encode_png16_gray(int width, int height,
                                                        std::span<const std::uint16_t> pixels);
ZRASTER_API std::vector<std::uint8_t> encode_npy(int width, int height,
                                                 std::span<const float> values);
ZRASTER_API std::vector<std::uint8_t> encode_npy(int width, int height,
                                                 std::span<const std::int32_t> values);

// Reads an 8-bit image (PNG, JPEG, ... via stb_image) as RGBA8. Throws InputError.
struct ImageRGBA8 {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;
};
ZRASTER_API ImageRGBA8 read_image_rgba8(const std::filesystem::path& path);

}  // namespace zraster
