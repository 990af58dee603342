// The procedural building "building:RxC[:SEED]" (docs/portals.md): its spec and camera.
#pragma once
#include <zraster/camera.hpp>

#include <cstdint>
#include <optional>
#include <string_view>

namespace zraster::detail {

struct BuildingSpec {
    int rows = 1, columns = 1;
    std::uint64_t seed = 1;
};

inline constexpr int kMaxBuildingRooms = 65'536;  // rows * columns

// nullopt when `spec` does not start with "building:"; throws InputError when it does but is
// malformed or out of range.
std::optional<BuildingSpec> parse_building_spec(std::string_view spec);

// In room (0, 0) at (2, 1.6, 2), looking at (4 C, 1.6, 4 R).
Camera building_camera(const BuildingSpec& spec);

}  // namespace zraster::detail
