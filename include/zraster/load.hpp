// Loading scenes from mesh files (OBJ with MTL, PLY, STL, glTF 2.0, 3DS, OFF and the other
// formats Assimp reads).
#pragma once
#include <zraster/export.hpp>
#include <zraster/portals.hpp>
#include <zraster/scene.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace zraster {

// Where the Assimp importer runs. zraster's own OBJ reader always runs in the calling process
// (it is fuzzed and sanitizer-clean); Assimp (every other format, and OBJ files the built-in
// reader leaves to it) is not: Debian's libassimp 5.2.5 corrupts memory on some malformed PLY and
// glTF files (see RELIABILITY.md).
enum class LoadIsolation {
    // Assimp runs in the calling process: fastest, but a crash in Assimp ends the process.
    InProcess,
    // Assimp runs in a child process (fork) with a memory limit (RLIMIT_AS), a CPU time limit
    // (RLIMIT_CPU) and a wall-clock timeout; it sends the converted scene back over a pipe in a
    // versioned binary format that this process validates fully (counts against the limits,
    // indices in range, finite values) before using it. A crash, a signal, a timeout or running
    // out of memory in the child becomes an InputError naming the file ("the importer crashed
    // (signal 11, SIGSEGV)"). The pre-checks of the file (size, declared counts, glTF byte
    // ranges) run in the calling process first. The command-line tool's default.
    //
    // fork() copies only the calling thread: the child runs Assimp and the conversion, which use
    // no threads and no locks another thread of the caller could hold besides malloc's (glibc
    // makes those fork-safe). Costs one fork per file (about a millisecond plus the copy of the
    // scene through the pipe).
    WorkerProcess,
};

struct LoadOptions {
    // Larger files are refused before their geometry is allocated. A glTF file is also held to
    // it before Assimp reads it: its primitives may decode at most max_triangles faces and
    // 3 x max_triangles vertices (Assimp copies an accessor into every primitive that reads it).
    std::size_t max_triangles = 50'000'000;
    // The memory a glTF file's accessors decode to, estimated before Assimp reads them: every
    // accessor a primitive reads, per primitive (attributes, morph targets, indices; a sparse
    // accessor's dense copy too), at the bytes the import and the conversion take per element
    // (measured). A 600-byte sparse accessor of 150 million vertices, or one 900,000-vertex
    // accessor read by 166 primitives, reached 6 to 8 GB; the default keeps a load to about
    // 1-2 GB.
    std::size_t max_geometry_bytes = std::size_t{1} << 30;
    // Polygons of more than 4 corners (OBJ, PLY) are triangulated by Assimp in time quadratic
    // in their corners: a face of n corners counts n^2, summed over the file, refused past this
    // before Assimp reads it. The default, 2^28 (one face of 16,384 corners, or 10 million
    // pentagons), is about 4 s of triangulation (measured: one face at the budget).
    std::uint64_t max_triangulation_work = std::uint64_t{1} << 28;
    // The model file, and each file it makes the importer read whole (a LightWave scene's
    // objects, a material library: these within min(max_file_bytes, 64 MiB), being text).
    std::size_t max_file_bytes = std::size_t{4} << 30;
    // Meshes placed by the node hierarchy (instances). Nodes that share children multiply: a
    // 1.5 KB glTF can place billions; it is refused before the hierarchy is expanded.
    std::size_t max_instances = 1'000'000;
    // Materials a file defines (OBJ: the `newmtl` statements of its material libraries, counted
    // before Assimp reads them; other formats: the materials Assimp made). Assimp's OBJ importer
    // takes about 34 KB a material: 200,000 `newmtl` lines of a 4.7 MB library reached 6.8 GB.
    // The default keeps that within about 1 GB.
    std::size_t max_materials = 20'000;

    // External references (glTF buffers and images, OBJ material libraries and textures) must be
    // regular files inside the model's folder, once symbolic links are followed: a buffer URI
    // like "../../etc/passwd" is refused (an InputError when geometry depends on it, a warning
    // for a texture or material library, which are then not read). True reads them anywhere.
    // FIFOs, devices and directories are refused either way.
    bool allow_outside_references = false;

    // Textures. An image wider or taller than max_texture_side texels is reduced (halved with a
    // box filter until it fits, as its mip levels are) with a warning. The decoded bytes of all
    // of a model's textures, mip levels included, stay within max_texture_bytes: an image whose
    // decoding alone would exceed it is not decoded (its header says its size), and a texture
    // that would take the total past it is not kept; either way a warning, and the material's
    // color is used.
    int max_texture_side = 8192;
    std::size_t max_texture_bytes = std::size_t{512} << 20;

    LoadIsolation isolation = LoadIsolation::InProcess;
    // WorkerProcess only. The importer's budgets, which bound the parts of a format zraster does
    // not count before reading (a small file Assimp expands, in memory or in time, stops at them).
    // The child's wall-clock limit (its CPU time limit is this, rounded up, plus one second);
    // by default (kWorkerTimeoutFromFile) 30 s plus 1 s per MiB of the file. Past it:
    // LimitExceeded "worker_timeout_seconds".
    double worker_timeout_seconds = kWorkerTimeoutFromFile;
    // The address space the child may add to what it inherits (0: no limit); by default
    // (kWorkerMemoryFromBudgets) 256 MiB, 4 times the file's bytes, max_geometry_bytes and twice
    // max_texture_bytes (the textures kept and one being decoded): past
    // it, LimitExceeded "max_geometry_bytes" (else "worker_memory_bytes"). The scene it sends
    // back may be at most this long.
    std::size_t worker_memory_bytes = kWorkerMemoryFromBudgets;

    static constexpr double kWorkerTimeoutFromFile = -1.0;
    static constexpr std::size_t kWorkerMemoryFromBudgets = ~std::size_t{0};
};

// The worker's budgets for a file of `file_bytes` under `options` (the defaults above resolved;
// explicit values as they are).
ZRASTER_API double worker_timeout_for(std::uint64_t file_bytes, const LoadOptions& options);
ZRASTER_API std::size_t worker_memory_for(std::uint64_t file_bytes, const LoadOptions& options);

// A file whose name ends in ".cells.json" is a cell graph file (docs/portals.md): the mesh
// files it names placed as instances, with its cells and portals (Scene::cells, validated). Its
// mistakes are InputErrors naming the file, the JSON element and the cause.
//
// Loads every mesh with its material (base color, specular, shininess, alpha: opacity, alpha
// mode and cutoff, base-color and opacity textures; docs/materials.md says what each format
// gives), vertex colors (glTF COLOR_0, PLY red/green/blue/alpha: Mesh::colors, clamped to
// [0, 1]) and the node hierarchy as instances (node transforms applied). Computes
// angle-weighted normals when the file has none, and bounds.
// Normals the file gives that are not finite or of zero length are recomputed from the faces
// (every normal of the scene is of unit length).
// Non-fatal problems (a missing material library or texture: the default material or the
// material's color is used; a texture reduced to fit the limits; an unknown glTF alpha mode or a
// material member of the wrong type; unusable normals) are
// appended to *warnings when it is given, one line each, starting with the file name.
// The other files the model named and the loader read (glTF buffers and images, material
// libraries, textures, a cells file's mesh files and theirs), and those it names but zraster does
// not read (every MTL map_* or bump statement's file, every glTF image: a clearcoat texture; a
// file refused for lying outside the model's folder), canonical and sorted, are appended to
// *files_read when it is given: a caller that writes files must not replace them. Throws InputError
// (one line naming the file and the cause) for a missing or unreadable file, an unknown format,
// malformed or truncated content (an OBJ or MTL word that is not a number included), no triangles
// (or none with an area), or NaN/Inf coordinates; LimitExceeded past a LoadOptions budget; and with
// LoadIsolation::WorkerProcess when the importer process crashes, times out or runs out of memory.
ZRASTER_API Scene load_scene(const std::filesystem::path& path, const LoadOptions& options = {},
                             std::vector<std::string>* warnings = nullptr,
                             std::vector<std::filesystem::path>* files_read = nullptr);

// Potentially visible sets as `zraster pvs` writes them (docs/portals.md): {"zraster_pvs": 1,
// "scene", "method", "slack", "cells", "steps", "sets": [{"cell": name, "bounded": bool,
// "visible": [cell indices]}, ...]}.
ZRASTER_API std::string pvs_to_json(const PotentiallyVisibleSets& sets, const CellGraph& graph,
                                    const std::string& scene, const PvsOptions& options);
// Reads such a file for `graph` (one set per cell, names matching, indices in range, each set
// holding its own cell); throws InputError naming the file and the element otherwise.
ZRASTER_API std::vector<std::vector<std::uint32_t>> load_pvs(const std::filesystem::path& path,
                                                             const CellGraph& graph);

// The file name endings load_scene reads a format from, lower case with the dot (".obj", ".glb",
// ".mesh.xml", ...): zraster's OBJ reader's and every Assimp importer's, as this build's Assimp
// lists them. Sorted, no duplicates.
ZRASTER_API const std::vector<std::string>& mesh_file_extensions();
// Whether the file name ends in one of mesh_file_extensions(), in any case: what a search of a
// folder for mesh files takes (`zraster batch`).
ZRASTER_API bool has_mesh_file_extension(const std::filesystem::path& path);

// A human-readable summary (for `zraster info`), one item per line, each line ending in '\n':
// source, meshes (name, triangles, vertices, material, mesh-space bounds), instances, totals
// over instances, exact world bounds, materials (name, base color, texture sizes, alpha mode and
// whether alpha can be below 1, from what) and the loader's warnings, when given.
// Long lists are cut after 50 entries with a count of the rest.
ZRASTER_API std::string describe_scene(const Scene& scene,
                                       const std::vector<std::string>& warnings = {});

}  // namespace zraster
