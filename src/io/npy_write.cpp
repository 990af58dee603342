// NumPy .npy output (format version 1.0: magic, little-endian header length, a Python dict
// literal padded with spaces to a multiple of 64 bytes, then the raw little-endian data).
#include <zraster/image_io.hpp>

#include "io/atomic_write.hpp"
#include "io/image_size_check.hpp"

#include <bit>
#include <string>

namespace zraster {

namespace {

template <typename T>
std::vector<std::uint8_t> npy_file(int width, int height, std::span<const T> values,
                                   const char* descr) {
    static_assert(sizeof(T) == 4);
    io::check_image_size("write_npy", width, height, 1, values.size());

    std::string dict = std::string("{'descr': '") + descr +
                       "', 'fortran_order': False, 'shape': (" + std::to_string(height) + ", " +
                       std::to_string(width) + "), }";
    const std::size_t preamble = 10;  // magic (6) + version (2) + header length (2)
    const std::size_t total = (preamble + dict.size() + 1 + 63) / 64 * 64;
    dict.append(total - preamble - dict.size() - 1, ' ');
    dict.push_back('\n');

    std::vector<std::uint8_t> out;
    out.reserve(total + values.size() * 4);
    out.insert(out.end(), {0x93, 'N', 'U', 'M', 'P', 'Y', 1, 0});
    out.push_back(static_cast<std::uint8_t>(dict.size() & 0xFF));
    out.push_back(static_cast<std::uint8_t>(dict.size() >> 8));
    out.insert(out.end(), dict.begin(), dict.end());
    // Explicit little-endian bytes: the file format says '<', whatever the host is.
    for (const T v : values) {
        const auto bits = std::bit_cast<std::uint32_t>(v);
        for (int shift = 0; shift < 32; shift += 8)
            out.push_back(static_cast<std::uint8_t>(bits >> shift));
    }
    return out;
}

}  // namespace

std::vector<std::uint8_t> encode_npy(int width, int height, std::span<const float> values) {
    return npy_file(width, height, values, "<f4");
}

std::vector<std::uint8_t> encode_npy(int width, int height, std::span<const std::int32_t> values) {
    return npy_file(width, height, values, "<i4");
}

void write_npy(const std::filesystem::path& path, int width, int height,
               std::span<const float> values) {
    io::write_file_atomically(path, encode_npy(width, height, values));
}

void write_npy(const std::filesystem::path& path, int width, int height,
               std::span<const std::int32_t> values) {
    io::write_file_atomically(path, encode_npy(width, height, values));
}

}  // namespace zraster
