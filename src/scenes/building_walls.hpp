// The walls of the building scene (building.cpp): solid slabs, watertight by construction.
#pragma once
#include <zraster/mesh.hpp>

#include <optional>

namespace zraster::detail {

// A wall slab along one grid line of the building: `along` spans [start, end] on the wall's
// length axis (x for a wall of constant z, z for a wall of constant x), its thickness is
// [center - half_thickness, center + half_thickness] across, its height [0, height]. With a
// doorway [door_start, door_end] x [0, door_height], the slab is one closed mesh around the
// opening. Faces lie on a grid of the breakpoints (along: start, door edges, end; height: 0,
// door_height, height, always, so that slabs meeting end to end share their end edges), and
// every face spans whole grid edges: shared edges have the same corners, so no crack opens.
struct WallSlab {
    bool constant_x = true;  // the wall lies in a plane of constant x (else constant z)
    double center = 0.0, half_thickness = 0.1;
    double start = 0.0, end = 4.0;
    double height = 3.0, door_height = 2.2;
    std::optional<std::pair<double, double>> door;
};

Mesh make_wall_slab(const WallSlab& wall);

}  // namespace zraster::detail
