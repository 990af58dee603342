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
// Rooms a side: a row of 32,768 rooms reaches coordinates where the rooms' float bounds and the
// portals between them no longer meet exactly (an instance then seems to reach the next cell).
inline constexpr int kMaxBuildingSide = 16'384;

// nullopt when `spec` does not start with "building:"; throws InputError when it does but is
// malformed or out of range.
std::optional<BuildingSpec> parse_building_spec(std::string_view spec);

// In room (0, 0) at (2, 1.6, 2), looking at (4 C, 1.6, 4 R).
Camera building_camera(const BuildingSpec& spec);

}  // namespace zraster::detail
