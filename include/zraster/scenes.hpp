// Procedural scenes: the benchmark scenes of docs/bench-scenes.md (bit-exact generators), simple
// primitives, and the built-in default scene.
#pragma once
#include <zraster/camera.hpp>
#include <zraster/export.hpp>
#include <zraster/scene.hpp>

#include <cstdint>
#include <optional>
#include <string_view>

namespace zraster {

// splitmix64 (Steele, Lea, Flood 2014), exactly as docs/bench-scenes.md specifies.
struct SplitMix64 {
    std::uint64_t state;
    explicit SplitMix64(std::uint64_t seed) : state(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    double unit() { return double(next() >> 11) * 0x1.0p-53; }  // [0, 1), exact
    double uniform(double a, double b) { return a + (b - a) * unit(); }
};

// The benchmark generators: exactly the geometry of docs/bench-scenes.md (checked by
// geometry_hash).
ZRASTER_API Mesh make_bench_sphere(long n);
ZRASTER_API Mesh make_bench_city(long n, std::uint64_t seed = 1);
ZRASTER_API Mesh make_bench_soup(long n, std::uint64_t seed = 1);

// FNV-1a 64 over the float32 little-endian x, y, z bytes of the 3 corners of every triangle in
// draw order (docs/bench-scenes.md).
ZRASTER_API std::uint64_t geometry_hash(const Mesh& mesh);

// Primitives with normals and UVs, counter-clockwise front faces seen from outside.
ZRASTER_API Mesh make_uv_sphere(float radius, int stacks, int slices);
ZRASTER_API Mesh make_box(const glm::vec3& half_extent);
ZRASTER_API Mesh make_torus(float major_radius, float minor_radius, int rings, int sides);
// A square in the xz plane facing +y, side `size`, UVs repeated `uv_repeat` times.
ZRASTER_API Mesh make_ground_plane(float size, float uv_repeat);

// The building of docs/portals.md, "building:RxC[:SEED]": rows x columns rooms of 4 x 4 units
// (room (i, j) spans x in [4i, 4i+4], z in [4j, 4j+4]), walls 3 units high with doorways along
// a seeded spanning tree of the rooms plus some more, furniture in every room, and its cell
// graph (Scene::cells: rooms and doorway tunnels, joined by portals).
ZRASTER_API Scene make_building(int rows, int columns, std::uint64_t seed = 1);

// True if spec names a procedural scene: "sphere:N", "city:N[:SEED]", "soup:N[:SEED]",
// "building:RxC[:SEED]" or "builtin:NAME".
ZRASTER_API bool is_procedural_spec(std::string_view spec);
// Builds the scene for such a spec; throws InputError for a malformed spec or absurd N.
// builtin names: "default" (the showcase scene), "sphere", "cube".
ZRASTER_API Scene make_procedural_scene(std::string_view spec);

// The recommended camera for a builtin scene, framed for a 16:9 image: for "builtin:default" a
// low eye looking slightly down, the ground receding to the horizon; for "building:RxC[:SEED]"
// in room (0, 0) at (2, 1.6, 2) looking at (4C, 1.6, 4R). nullopt for other specs (frame those
// with fit_camera).
ZRASTER_API std::optional<Camera> builtin_camera(std::string_view spec);

}  // namespace zraster
