// The frame memory estimate (see render.hpp).
#include <zraster/error.hpp>
#include <zraster/render.hpp>

#include <string>

namespace zraster {
namespace {

std::uint64_t add(std::uint64_t a, std::uint64_t b) {
    return a > UINT64_MAX - b ? UINT64_MAX : a + b;
}

std::uint64_t times(std::uint64_t count, std::uint64_t bytes) {
    return bytes != 0 && count > UINT64_MAX / bytes ? UINT64_MAX : count * bytes;
}

// Exact below a mebibyte (a small limit is told as given), else rounded up to MiB.
std::string byte_text(std::uint64_t bytes) {
    if (bytes < (std::uint64_t{1} << 20)) return std::to_string(bytes) + " bytes";
    return std::to_string((bytes >> 20) + ((bytes & ((1u << 20) - 1)) != 0)) + " MiB";
}

}  // namespace

std::uint64_t estimated_frame_bytes(std::uint64_t vertices, std::uint64_t triangles,
                                    std::uint64_t target_samples, std::uint64_t bytes_per_sample) {
    return add(add(times(vertices, kFrameBytesPerVertex), times(triangles, kFrameBytesPerTriangle)),
               times(target_samples, bytes_per_sample));
}

void check_frame_memory(std::string_view source, std::uint64_t vertices, std::uint64_t triangles,
                        std::uint64_t target_samples, const RenderLimits& limits,
                        std::uint64_t bytes_per_sample) {
    const std::uint64_t bytes =
        estimated_frame_bytes(vertices, triangles, target_samples, bytes_per_sample);
    if (bytes <= limits.max_frame_bytes) return;
    std::string counts = std::to_string(vertices) + " vertices and " + std::to_string(triangles) +
                         " triangles over all instances";
    if (target_samples > 0) counts += ", " + std::to_string(target_samples) + " target samples";
    throw LimitExceeded(std::string(source), "max_frame_bytes",
                        "the frame needs about " + byte_text(bytes) + " (" + counts +
                            "), more than max_frame_bytes (" + byte_text(limits.max_frame_bytes) +
                            ")");
}

}  // namespace zraster
