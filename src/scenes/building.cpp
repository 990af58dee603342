// The procedural building "building:RxC[:SEED]": R x C rooms of 4 x 4 units, walls 3 units high
// and 0.2 thick centred on the grid lines, doorways (1 x 2.2) between rooms along a random
// spanning tree of the room grid plus a quarter of the other walls, and a few pieces of
// furniture per room, with its cell graph: every room's free space and every doorway's tunnel
// through its wall are cells, and each tunnel's two openings are portals. Cell boundaries are
// covered by the walls and floors (the slabs are watertight, building_walls.hpp) except at the
// portals and at the open tops, above which nothing lies.
#include "scenes/building.hpp"

#include <zraster/error.hpp>
#include <zraster/scenes.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numeric>
#include <string>

#include "scenes/building_walls.hpp"

namespace zraster {
namespace detail {
namespace {

constexpr double kRoomSize = 4.0, kWallHeight = 3.0, kHalfWall = 0.1;
constexpr double kDoorWidth = 1.0, kDoorHeight = 2.2;
constexpr double kExtraDoorChance = 0.25;

enum BuildingMaterial : std::uint32_t { kWall = 1, kFloor, kWood, kRed, kBlue, kGreen };

Material building_material(std::string name, glm::vec3 color, float specular) {
    Material m;
    m.name = std::move(name);
    m.base_color = color;
    m.specular = glm::vec3(specular);
    m.shininess = 32.0f;
    return m;
}

Mesh furniture_table() {
    Mesh table;
    const auto add_box = [&](glm::vec3 center, glm::vec3 half) {
        Mesh box = make_box(half);
        const auto base = std::uint32_t(table.positions.size());
        for (const glm::vec3& p : box.positions) table.positions.push_back(p + center);
        table.normals.insert(table.normals.end(), box.normals.begin(), box.normals.end());
        if (!box.uvs.empty()) table.uvs.insert(table.uvs.end(), box.uvs.begin(), box.uvs.end());
        for (const std::uint32_t i : box.indices) table.indices.push_back(base + i);
    };
    add_box({0.0f, 0.72f, 0.0f}, {0.6f, 0.03f, 0.4f});
    for (const float x : {-0.52f, 0.52f})
        for (const float z : {-0.32f, 0.32f}) add_box({x, 0.345f, z}, {0.04f, 0.345f, 0.04f});
    update_bounds(table);
    return table;
}

// A doorway in a wall: where along it, and the cell of its tunnel.
struct Doorway {
    double start = 0.0, end = 0.0;
    std::uint32_t tunnel = 0;
};

class BuildingMaker {
  public:
    explicit BuildingMaker(const BuildingSpec& spec) : spec_(spec), rng_(spec.seed) {}

    Scene make() {
        scene_.name = "building:" + std::to_string(spec_.rows) + "x" +
                      std::to_string(spec_.columns) + ":" + std::to_string(spec_.seed);
        add_materials();
        add_rooms();
        choose_doorways();
        add_walls();
        add_furniture();
        finish_graph();
        return std::move(scene_);
    }

  private:
    std::uint32_t room(int i, int j) const { return std::uint32_t(j * spec_.columns + i); }

    void add_materials() {
        scene_.materials.push_back(building_material("wall", {0.85f, 0.83f, 0.78f}, 0.05f));
        scene_.materials.push_back(building_material("floor", {0.55f, 0.42f, 0.30f}, 0.1f));
        scene_.materials.push_back(building_material("wood", {0.62f, 0.45f, 0.25f}, 0.2f));
        scene_.materials.push_back(building_material("red", {0.80f, 0.22f, 0.18f}, 0.3f));
        scene_.materials.push_back(building_material("blue", {0.25f, 0.45f, 0.85f}, 0.5f));
        scene_.materials.push_back(building_material("green", {0.30f, 0.68f, 0.36f}, 0.3f));
    }

    std::uint32_t add_mesh(Mesh mesh, std::string name, std::uint32_t material) {
        mesh.name = std::move(name);
        mesh.material = material;
        scene_.meshes.push_back(std::move(mesh));
        return std::uint32_t(scene_.meshes.size() - 1);
    }

    std::uint32_t add_instance(std::uint32_t mesh, const glm::mat4& transform, std::string name) {
        Instance instance;
        instance.mesh = mesh;
        instance.transform = transform;
        instance.name = std::move(name);
        scene_.instances.push_back(std::move(instance));
        return std::uint32_t(scene_.instances.size() - 1);
    }

    // Rooms (cells 0 .. R*C-1) and their floors, which reach under the walls to the grid lines.
    void add_rooms() {
        for (int j = 0; j < spec_.rows; ++j)
            for (int i = 0; i < spec_.columns; ++i) {
                const glm::dvec3 corner(kRoomSize * i, 0.0, kRoomSize * j);
                Cell cell;
                cell.name = "room_" + std::to_string(i) + "_" + std::to_string(j);
                cell.volume = box_volume(
                    corner + glm::dvec3(kHalfWall, 0.0, kHalfWall),
                    corner + glm::dvec3(kRoomSize - kHalfWall, kWallHeight, kRoomSize - kHalfWall));
                graph_.cells.push_back(std::move(cell));
                Mesh floor = make_floor(corner);
                const std::uint32_t mesh = add_mesh(std::move(floor), "floor", kFloor);
                floors_.push_back(
                    add_instance(mesh, glm::mat4(1.0f), graph_.cells.back().name + "/floor"));
                graph_.cells.back().instances.push_back(floors_.back());
            }
    }

    static Mesh make_floor(const glm::dvec3& corner) {
        Mesh floor;
        const double s = kRoomSize;
        for (const glm::dvec3 offset :
             {glm::dvec3(0, 0, 0), glm::dvec3(0, 0, s), glm::dvec3(s, 0, s), glm::dvec3(s, 0, 0)}) {
            floor.positions.push_back(glm::vec3(corner + offset));
            floor.normals.push_back({0.0f, 1.0f, 0.0f});
        }
        floor.indices = {0, 1, 2, 0, 2, 3};
        update_bounds(floor);
        return floor;
    }

    // Walls between rooms, in a fixed order: constant-x walls (index i*R + j for the wall left
    // of room (i, j), i in 1..C-1), then constant-z walls. A random spanning tree of them gets
    // doorways (every room reachable), and each other wall with probability kExtraDoorChance.
    void choose_doorways() {
        const int rows = spec_.rows, columns = spec_.columns;
        for (int i = 1; i < columns; ++i)
            for (int j = 0; j < rows; ++j) edges_.push_back({true, i, j});
        for (int j = 1; j < rows; ++j)
            for (int i = 0; i < columns; ++i) edges_.push_back({false, i, j});
        std::vector<std::size_t> order(edges_.size());
        std::iota(order.begin(), order.end(), std::size_t{0});
        for (std::size_t k = order.size(); k > 1; --k)  // Fisher-Yates
            std::swap(order[k - 1], order[rng_.next() % k]);
        std::vector<std::uint32_t> parent(std::size_t(rows) * columns);
        std::iota(parent.begin(), parent.end(), 0u);
        const auto find = [&](std::uint32_t x) {
            while (parent[x] != x) x = parent[x] = parent[parent[x]];
            return x;
        };
        doors_.assign(edges_.size(), std::nullopt);
        for (const std::size_t k : order) {
            const EdgeRooms rooms = edge_rooms(k);
            const std::uint32_t a = find(rooms.first), b = find(rooms.second);
            const bool tree = a != b;
            if (tree) parent[a] = b;
            const double chance = rng_.unit();
            const double offset = rng_.uniform(-0.8, 0.8);
            if (!tree && chance >= kExtraDoorChance) continue;
            const double middle = kRoomSize / 2 + offset;
            doors_[k] = Doorway{middle - kDoorWidth / 2, middle + kDoorWidth / 2, 0};
        }
    }

    using EdgeRooms = std::pair<std::uint32_t, std::uint32_t>;
    EdgeRooms edge_rooms(std::size_t k) const {
        const auto& e = edges_[k];
        return e.constant_x ? EdgeRooms{room(e.i - 1, e.j), room(e.i, e.j)}
                            : EdgeRooms{room(e.i, e.j - 1), room(e.i, e.j)};
    }

    void add_walls() {
        std::optional<Doorway> none;
        for (std::size_t k = 0; k < edges_.size(); ++k) {
            const auto& e = edges_[k];
            add_wall(e.constant_x, e.constant_x ? e.i : e.j, e.constant_x ? e.j : e.i, doors_[k],
                     edge_rooms(k));
        }
        // The outer walls: one room each.
        for (int j = 0; j < spec_.rows; ++j) {
            add_wall(true, 0, j, none, {room(0, j), room(0, j)});
            add_wall(true, spec_.columns, j, none,
                     {room(spec_.columns - 1, j), room(spec_.columns - 1, j)});
        }
        for (int i = 0; i < spec_.columns; ++i) {
            add_wall(false, 0, i, none, {room(i, 0), room(i, 0)});
            add_wall(false, spec_.rows, i, none,
                     {room(i, spec_.rows - 1), room(i, spec_.rows - 1)});
        }
    }

    // The wall on grid line `line` (x = 4 line for constant x), along segment `segment`.
    // Constant-x walls span the whole segment (and so the corners); constant-z walls stop at the
    // constant-x walls' faces.
    void add_wall(bool constant_x, int line, int segment, std::optional<Doorway>& door,
                  const EdgeRooms& rooms) {
        WallSlab slab;
        slab.constant_x = constant_x;
        slab.center = kRoomSize * line;
        slab.half_thickness = kHalfWall;
        const double base = kRoomSize * segment;
        slab.start = base + (constant_x ? 0.0 : kHalfWall);
        slab.end = base + kRoomSize - (constant_x ? 0.0 : kHalfWall);
        slab.height = kWallHeight;
        slab.door_height = kDoorHeight;
        if (door) slab.door = std::make_pair(base + door->start, base + door->end);
        const std::string name = std::string(constant_x ? "wall_x" : "wall_z") +
                                 std::to_string(line) + "_" + std::to_string(segment);
        const std::uint32_t mesh = add_mesh(make_wall_slab(slab), name, kWall);
        const std::uint32_t wall = add_instance(mesh, glm::mat4(1.0f), name);
        graph_.cells[rooms.first].instances.push_back(wall);
        if (rooms.second != rooms.first) graph_.cells[rooms.second].instances.push_back(wall);
        if (door) add_tunnel(slab, *door, rooms, wall);
    }

    // The doorway's tunnel through the slab: a cell holding the slab and both rooms' floors,
    // with a portal at each opening.
    void add_tunnel(const WallSlab& slab, Doorway& door, const EdgeRooms& rooms,
                    std::uint32_t wall) {
        const double lo = slab.center - kHalfWall, hi = slab.center + kHalfWall;
        const double a0 = slab.door->first, a1 = slab.door->second;
        const auto point = [&](double across, double up, double along) {
            return slab.constant_x ? glm::dvec3(across, up, along) : glm::dvec3(along, up, across);
        };
        Cell cell;
        cell.name = "door_" + std::string(slab.constant_x ? "x" : "z") + "_" +
                    graph_.cells[rooms.first].name.substr(5) + "_" +
                    graph_.cells[rooms.second].name.substr(5);
        cell.volume = box_volume(glm::min(point(lo, 0, a0), point(hi, kDoorHeight, a1)),
                                 glm::max(point(lo, 0, a0), point(hi, kDoorHeight, a1)));
        cell.instances = {wall, floors_[rooms.first], floors_[rooms.second]};
        door.tunnel = std::uint32_t(graph_.cells.size());
        graph_.cells.push_back(std::move(cell));
        for (const double across : {lo, hi}) {
            Portal portal;
            portal.cells = {across == lo ? rooms.first : rooms.second, door.tunnel};
            portal.corners = {point(across, 0, a0), point(across, 0, a1),
                              point(across, kDoorHeight, a1), point(across, kDoorHeight, a0)};
            graph_.portals.push_back(std::move(portal));
        }
    }

    // Two to four pieces per room (boxes, spheres, tables), inside [1, 3] of the room so that
    // nothing touches a wall.
    void add_furniture() {
        const std::uint32_t box = add_mesh(make_box(glm::vec3(0.5f)), "box", kRed);
        const std::uint32_t sphere = add_mesh(make_uv_sphere(1.0f, 12, 24), "sphere", kBlue);
        const std::uint32_t table = add_mesh(furniture_table(), "table", kWood);
        const std::uint32_t green_box = add_mesh(make_box(glm::vec3(0.5f)), "crate", kGreen);
        for (int j = 0; j < spec_.rows; ++j)
            for (int i = 0; i < spec_.columns; ++i) {
                const int pieces = 2 + int(rng_.next() % 3);
                Cell& cell = graph_.cells[room(i, j)];
                for (int k = 0; k < pieces; ++k) {
                    const double x = kRoomSize * i + rng_.uniform(1.0, 3.0);
                    const double z = kRoomSize * j + rng_.uniform(1.0, 3.0);
                    const double angle = rng_.uniform(0.0, 6.283185307179586);
                    const double size = rng_.uniform(0.3, 0.8);
                    const int kind = int(rng_.next() % 4);
                    glm::mat4 t = glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.0, z));
                    std::uint32_t mesh = table;
                    if (kind == 0 || kind == 3) {
                        mesh = kind == 0 ? box : green_box;
                        t = glm::rotate(t, float(angle), glm::vec3(0, 1, 0));
                        t = glm::scale(glm::translate(t, glm::vec3(0.0f, float(size) / 2, 0.0f)),
                                       glm::vec3(float(size), float(size), float(size) * 0.8f));
                    } else if (kind == 1) {
                        mesh = sphere;
                        t = glm::scale(glm::translate(t, glm::vec3(0.0f, float(size) / 2, 0.0f)),
                                       glm::vec3(float(size) / 2));
                    } else {
                        t = glm::rotate(t, float(angle), glm::vec3(0, 1, 0));
                    }
                    cell.instances.push_back(add_instance(
                        mesh, t, cell.name + "/" + scene_.meshes[mesh].name + std::to_string(k)));
                }
            }
    }

    void finish_graph() {
        std::vector<Bounds3f> boxes;
        std::vector<std::string> names;
        for (const Instance& instance : scene_.instances) {
            boxes.push_back(scene_.meshes[instance.mesh].bounds.transformed(instance.transform));
            names.push_back(instance.name);
        }
        validate_cell_graph(graph_, boxes, names, scene_.name);
        scene_.cells = std::make_shared<const CellGraph>(std::move(graph_));
    }

    struct Edge {
        bool constant_x;
        int i, j;  // the room right of (constant x) or behind (constant z) the wall
    };
    const BuildingSpec spec_;
    SplitMix64 rng_;
    Scene scene_;
    CellGraph graph_;
    std::vector<std::uint32_t> floors_;  // per room
    std::vector<Edge> edges_;
    std::vector<std::optional<Doorway>> doors_;
};

enum class Parsed { Ok, Malformed, OutOfRange };

// Decimal digits only, up to 2^64 - 1.
Parsed parse_count(std::string_view text, std::uint64_t& value) {
    if (text.empty() || text.find_first_not_of("0123456789") != text.npos) return Parsed::Malformed;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error == std::errc::result_out_of_range) return Parsed::OutOfRange;
    return error == std::errc() && end == text.data() + text.size() ? Parsed::Ok
                                                                    : Parsed::Malformed;
}

}  // namespace

std::optional<BuildingSpec> parse_building_spec(std::string_view spec) {
    constexpr std::string_view prefix = "building:";
    if (spec.substr(0, prefix.size()) != prefix) return std::nullopt;
    const std::string file(spec);
    const auto malformed = [&] {
        return InputError(file, "malformed scene spec: expected building:RxC[:SEED]");
    };
    std::string_view rest = spec.substr(prefix.size());
    const auto colon = rest.find(':');
    const std::string_view size = rest.substr(0, colon);
    const auto x = size.find('x');
    std::uint64_t rows = 0, columns = 0, seed = 1;
    if (x == size.npos) throw malformed();
    const Parsed r = parse_count(size.substr(0, x), rows);
    const Parsed c = parse_count(size.substr(x + 1), columns);
    if (r == Parsed::Malformed || c == Parsed::Malformed) throw malformed();
    if (colon != rest.npos) {
        const Parsed s = parse_count(rest.substr(colon + 1), seed);
        if (s == Parsed::Malformed) throw malformed();
        if (s == Parsed::OutOfRange)
            throw InputError(file, "SEED out of range (0..18446744073709551615)");
    }
    if (r == Parsed::OutOfRange || c == Parsed::OutOfRange || rows < 1 || columns < 1 ||
        rows > std::uint64_t(kMaxBuildingSide) || columns > std::uint64_t(kMaxBuildingSide) ||
        rows * columns > std::uint64_t(kMaxBuildingRooms))
        throw InputError(file, "R x C out of range (at least 1 x 1, at most " +
                                   std::to_string(kMaxBuildingSide) + " a side and " +
                                   std::to_string(kMaxBuildingRooms) + " rooms)");
    return BuildingSpec{int(rows), int(columns), seed};
}

Camera building_camera(const BuildingSpec& spec) {
    Camera camera;
    camera.eye = {2.0, 1.6, 2.0};
    camera.target = {kRoomSize * spec.columns, 1.6, kRoomSize * spec.rows};
    camera.up = {0.0, 1.0, 0.0};
    camera.fovy_degrees = 60.0;
    camera.near = 0.05;
    camera.far = std::hypot(kRoomSize * spec.columns, kRoomSize * spec.rows, kWallHeight) + 1.0;
    return camera;
}

}  // namespace detail

Scene make_building(int rows, int columns, std::uint64_t seed) {
    return detail::BuildingMaker({rows, columns, seed}).make();
}

}  // namespace zraster
