// PNG output: our own chunk writer (signature, IHDR, IDAT, IEND, each with its CRC-32) around
// libdeflate's zlib compressor.
//
// Speed matters here: an image is written at the end of every `zraster render`, and
// `zraster batch` writes hundreds per second; a general-purpose PNG writer (per-row filter
// search, zlib at level 8) takes as long as the rendering. Every row uses filter "Up" (the
// difference from the row above): renders and depth maps are smooth vertically, so it compresses
// them about as well as the usual per-row heuristic, which costs five passes, for one
// subtraction per byte. libdeflate runs at level 1: files a few percent larger than level 2's
// for about half the instructions (BENCHMARKS.md, batch). The stream is compressed on one thread:
// deflate output that libdeflate produces for separate bands cannot be concatenated (each ends
// with a final block at a bit position it does not report).
#include <zraster/error.hpp>
#include <zraster/image_io.hpp>

#include "io/atomic_write.hpp"
#include "io/image_size_check.hpp"
#include "memory/huge_pages.hpp"

#include <libdeflate.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string_view>

namespace zraster {

namespace {

constexpr int kCompressionLevel = 1;
// IDAT chunks are split so that no chunk length comes near PNG's 2^31 - 1 limit.
constexpr std::size_t kMaxIdatBytes = std::size_t{1} << 30;

void put_u32_be(std::uint8_t* out, std::uint32_t v) {
    out[0] = static_cast<std::uint8_t>(v >> 24);
    out[1] = static_cast<std::uint8_t>(v >> 16);
    out[2] = static_cast<std::uint8_t>(v >> 8);
    out[3] = static_cast<std::uint8_t>(v);
}

void put_chunk(std::vector<std::uint8_t>& out, std::string_view type,
               std::span<const std::uint8_t> data) {
    std::uint8_t header[8];
    put_u32_be(header, static_cast<std::uint32_t>(data.size()));
    std::memcpy(header + 4, type.data(), 4);
    out.insert(out.end(), header, header + 8);
    out.insert(out.end(), data.begin(), data.end());
    // The CRC covers the chunk type and data, not the length.
    std::uint32_t crc = libdeflate_crc32(0, header + 4, 4);
    if (!data.empty()) crc = libdeflate_crc32(crc, data.data(), data.size());
    std::uint8_t trailer[4];
    put_u32_be(trailer, crc);
    out.insert(out.end(), trailer, trailer + 4);
}

struct CompressorDeleter {
    void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};

// `filtered` holds the scanlines, each a filter byte and the row's bytes. Compresses them into
// a complete PNG file.
std::vector<std::uint8_t> png_file(int width, int height, std::uint8_t bit_depth,
                                   std::uint8_t color_type,
                                   std::span<const std::uint8_t> filtered) {
    std::unique_ptr<libdeflate_compressor, CompressorDeleter> compressor(
        libdeflate_alloc_compressor(kCompressionLevel));
    if (!compressor) throw std::bad_alloc();
    std::vector<std::uint8_t> zlib;
    memory::resize_on_huge_pages(zlib,
                                 libdeflate_zlib_compress_bound(compressor.get(), filtered.size()));
    const std::size_t zlib_size = libdeflate_zlib_compress(
        compressor.get(), filtered.data(), filtered.size(), zlib.data(), zlib.size());
    if (zlib_size == 0) throw std::runtime_error("PNG compression failed");

    std::vector<std::uint8_t> png;
    memory::reserve_on_huge_pages(png, zlib_size + 64 + 12 * (zlib_size / kMaxIdatBytes));
    png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    std::uint8_t header[13];
    put_u32_be(header, static_cast<std::uint32_t>(width));
    put_u32_be(header + 4, static_cast<std::uint32_t>(height));
    header[8] = bit_depth;
    header[9] = color_type;
    header[10] = 0;  // deflate
    header[11] = 0;  // adaptive filtering (each row names its filter)
    header[12] = 0;  // no interlace
    put_chunk(png, "IHDR", header);
    for (std::size_t at = 0; at < zlib_size; at += kMaxIdatBytes)
        put_chunk(png, "IDAT",
                  std::span<const std::uint8_t>(zlib.data() + at,
                                                std::min(kMaxIdatBytes, zlib_size - at)));
    put_chunk(png, "IEND", {});
    return png;
}

// Filter "Up": each byte minus the byte above it (the row above the first is zero).
void filter_up(std::uint8_t* out, const std::uint8_t* row, const std::uint8_t* above,
               std::size_t bytes) {
    out[0] = 2;
    if (above == nullptr) {
        // The analyzer assumes an empty pixel span; check_image_size() refuses those first.
        std::memcpy(out + 1, row, bytes);  // NOLINT(clang-analyzer-core.NonNullParamChecker)
        return;
    }
    for (std::size_t i = 0; i < bytes; ++i)
        out[1 + i] = static_cast<std::uint8_t>(row[i] - above[i]);
}

}  // namespace

std::vector<std::uint8_t> encode_png8(int width, int height, int channels,
                                      std::span<const std::uint8_t> pixels) {
    if (channels < 1 || channels > 4)
        throw std::invalid_argument("write_png8: channels must be 1, 2, 3 or 4");
    io::check_image_size("write_png8", width, height, channels, pixels.size());
    // Gray, gray + alpha, RGB, RGBA.
    static constexpr std::uint8_t kColorType[5] = {0, 0, 4, 2, 6};

    const std::size_t row_bytes = static_cast<std::size_t>(width) * channels;
    std::vector<std::uint8_t> filtered;
    memory::resize_on_huge_pages(filtered, (row_bytes + 1) * static_cast<std::size_t>(height));
    for (std::size_t y = 0; y < static_cast<std::size_t>(height); ++y) {
        const std::uint8_t* row = pixels.data() + y * row_bytes;
        filter_up(filtered.data() + y * (row_bytes + 1), row, y > 0 ? row - row_bytes : nullptr,
                  row_bytes);
    }
    return png_file(width, height, 8, kColorType[channels], filtered);
}

std::vector<std::uint8_t> encode_png16_gray(int width, int height,
                                            std::span<const std::uint16_t> pixels) {
    io::check_image_size("write_png16_gray", width, height, 1, pixels.size());
    const std::size_t row_bytes = static_cast<std::size_t>(width) * 2;

    // Samples are big-endian in the file; "Up" works on those bytes.
    std::vector<std::uint8_t> filtered;
    memory::resize_on_huge_pages(filtered, (row_bytes + 1) * static_cast<std::size_t>(height));
    std::vector<std::uint8_t> previous(row_bytes), current(row_bytes);
    for (std::size_t y = 0; y < static_cast<std::size_t>(height); ++y) {
        const std::uint16_t* row = pixels.data() + y * static_cast<std::size_t>(width);
        for (std::size_t x = 0; x < static_cast<std::size_t>(width); ++x) {
            current[2 * x] = static_cast<std::uint8_t>(row[x] >> 8);
            current[2 * x + 1] = static_cast<std::uint8_t>(row[x] & 0xFF);
        }
        filter_up(filtered.data() + y * (row_bytes + 1), current.data(),
                  y > 0 ? previous.data() : nullptr, row_bytes);
        previous.swap(current);
    }
    return png_file(width, height, 16, 0, filtered);
}

void write_png8(const std::filesystem::path& path, int width, int height, int channels,
                std::span<const std::uint8_t> pixels) {
    io::write_file_atomically(path, encode_png8(width, height, channels, pixels));
}

void write_png16_gray(const std::filesystem::path& path, int width, int height,
                      std::span<const std::uint16_t> pixels) {
    io::write_file_atomically(path, encode_png16_gray(width, height, pixels));
}

}  // namespace zraster
