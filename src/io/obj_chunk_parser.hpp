// The line parser: what one chunk of an OBJ file holds, read in one pass and in parallel with the
// other chunks (obj_scan.hpp cuts them).
//
// A chunk keeps its own v, vt and vn values, its faces (corner indices as written, encoded as
// obj_numbers.hpp says: negative ones are relative to counts the chunk does not know yet), and
// the o, g, usemtl and mtllib statements between them as events: what they do depends on the
// statements of earlier chunks, so they are replayed in file order afterwards (obj_structure.hpp).
// Line numbers are chunk-local until the chunks before are counted.
//
// Parsing stops at the first line that is an error of the file (a zero index) or that the reader
// leaves to Assimp (docs/obj-format.md lists them): the Problem.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace zraster::io::obj {

enum class EventKind : std::uint8_t { Object, Group, Material, Library };

// An o, g, usemtl or mtllib statement, placed among the faces.
struct Event {
    EventKind kind;
    std::uint32_t faces_before;  // faces of the chunk before it
    std::uint32_t line;          // chunk-local, 0-based
    std::string text;
};

enum FaceKind : std::uint8_t { kPolygon, kLineElement, kPointElement };
enum : std::uint8_t { kHasUv = 1, kHasNormal = 2 };

struct Face {
    std::uint32_t line;   // chunk-local, 0-based
    std::uint32_t first;  // first corner, chunk-local
    std::uint16_t corners;
    std::uint8_t kind;
    std::uint8_t attributes;  // kHasUv | kHasNormal: which indices each corner has
};

// The first line of a chunk that is an error of the file, or that the reader leaves to Assimp.
// Parsing a chunk stops there.
struct Problem {
    bool error = false;
    std::uint32_t line = 0;  // chunk-local
    std::string what;
};

struct Chunk {
    const char* begin = nullptr;
    const char* end = nullptr;
    std::size_t first_line = 0;  // global, 0-based
    std::uint32_t lines = 0;
    std::vector<float> positions;  // x y z
    std::vector<float> uvs;        // u, 1 - v: Assimp's FlipUVs
    std::vector<float> normals;    // unit length as convert_mesh makes them; NaN if unusable
    std::vector<Face> faces;
    // Per corner; corner_t and corner_n only as far as faces with those indices need them.
    // Encoded indices after parsing, resolved global indices once every chunk is parsed.
    std::vector<std::int32_t> corner_v, corner_t, corner_n;
    std::vector<Event> events;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> non_finite_positions;  // index, line
    // The first face using the uv slot while no `vt` was read yet (in this chunk): Assimp then
    // reads that slot as a normal index.
    std::optional<std::uint32_t> uv_slot_without_uvs;
    std::optional<Problem> problem;
    // The first `v x y z r g b` whose color is outside 0..1 or not finite (zraster does not use
    // OBJ vertex colors: warned about once a file): its line and color.
    std::optional<std::uint32_t> color_outside_line;
    float color_outside[3] = {0, 0, 0};
};

// The chunk holding the file's face (or value) number `index`, given the number before each
// chunk (`prefix`, one more entry than chunks).
inline std::size_t chunk_holding(const std::vector<std::size_t>& prefix, std::size_t index) {
    return static_cast<std::size_t>(std::upper_bound(prefix.begin(), prefix.end(), index) -
                                    prefix.begin() - 1);
}

// The file's bytes (followed by the zero padding of FileBytes) in line-aligned chunks, each
// parsed, in parallel.
std::vector<Chunk> parse_chunks(const char* data, std::size_t size);

}  // namespace zraster::io::obj
