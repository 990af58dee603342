// LightWave scenes (.lws) load object files (LoadObjectLayer, LoadObject lines), and Assimp reads
// every object and combines the scenes in time quadratic in the number of loads (20,000 loads of
// a one-triangle object: 17 s; 100,000 of a 48 KB object did not finish in a minute). The scene
// is scanned first: each object must be a readable file the reference policy allows (else an
// InputError naming it) within max_file_bytes, pass the checks it would have if given directly
// and not be a scene itself; and the loads are counted.
#pragma once
#include <zraster/load.hpp>

#include <cstdint>
#include <filesystem>

namespace zraster::io {

// Each object load counts this many placements toward max_instances: 1,000,000 / 200 = 5,000
// loads, about 1.5 s of combining (measured: 5,000 loads 1.4 s, 20,000 17 s).
inline constexpr std::uint64_t kLightWaveLoadWeight = 200;
// The memory an object load takes per byte of its file (measured: 1,000 loads of a 48 KB OBJ,
// 688 MB).
inline constexpr std::uint64_t kLightWaveBytesPerObjectByte = 15;

// Throws InputError for a refused object (outside the folder, not a regular file),
// LimitExceeded for an object past max_file_bytes (max_file_bytes), more than
// max_instances / kLightWaveLoadWeight loads (max_instances), or loads whose object bytes times
// kLightWaveBytesPerObjectByte exceed max_geometry_bytes (max_geometry_bytes).
void check_lightwave_scene(const std::filesystem::path& path, const LoadOptions& options);

}  // namespace zraster::io
