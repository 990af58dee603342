// The per-file limits of `zraster batch`, --max-triangles and --max-memory: a file too large for
// them is refused with a record of its own (LimitExceeded), before the memory is allocated,
// instead of ending the whole batch out of memory.
#pragma once
#include <zraster/scene.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "render_arguments.hpp"

namespace zraster::cli {

struct BatchLimits {
    std::uint64_t max_triangles = 0;  // over all instances
    std::uint64_t max_memory = 0;     // bytes one file may take while it is rendered
};

// 3/4 of the physical memory, shared among `jobs` files rendered at once.
std::uint64_t default_max_memory(int jobs);

// The least a loaded triangle takes: its three indices (12 bytes) and its share of the
// pipeline's binning (50).
inline constexpr std::uint64_t kMinBytesPerTriangle = 62;

// The triangles the loader may allocate under `limits` (LoadOptions::max_triangles): at most
// max_triangles, and no more than max_memory holds at kMinBytesPerTriangle each.
std::size_t load_triangle_limit(const BatchLimits& limits);

// The memory rendering `scene` with every view's arguments needs, estimated: the scene's arrays
// and textures, the pipeline's working memory per vertex and per triangle, the targets per pixel
// and sample, and the encoded outputs kept until they are written.
std::uint64_t estimated_memory(const Scene& scene, const std::vector<RenderArguments>& views);

// Throws LimitExceeded (limit "max_triangles" or "max_memory") naming the scene's file when it
// is over a limit.
void check_batch_limits(const Scene& scene, const std::vector<RenderArguments>& views,
                        const BatchLimits& limits);

}  // namespace zraster::cli
