// zraster's reader for Wavefront OBJ files, used by load_scene for .obj files. Its
// specification is docs/obj-format.md: the statements it reads (v, vt, vn, f, l, p, o, g,
// usemtl, mtllib), the index forms, how quads become triangles, what it refuses with which
// message, and the lines it leaves to Assimp.
//
// Assimp 5.2's OBJ importer is the test oracle, not the specification: for a file the reader
// accepts, the scene is the one load_scene's Assimp path makes (Assimp's importer, its
// triangulation and FlipUVs, then zraster's conversion and vertex welding: the same meshes,
// names, materials, instances, warnings, triangles and welded vertices in the same order), and
// tests/io compare the two. Coordinates are correctly rounded (std::from_chars) where Assimp's
// fast_atof is sometimes one unit in the last place off: the only intended difference.
//
// Lines Assimp reads in ways of its own (polygons of five or more corners, which it
// triangulates by ear clipping; faces mixing corner forms; curves and surfaces; line
// continuations; numbers it does not count as numbers, ...) are not guessed at: the reader
// answers with the first such line instead of a scene, and load_scene reads the file through
// the Assimp path.
#pragma once
#include <zraster/load.hpp>
#include <zraster/scene.hpp>

#include "io/loaded_scene.hpp"
#include "io/obj_material_libraries.hpp"

#include <cstddef>
#include <filesystem>
#include <string>
#include <variant>

namespace zraster::io {

// Why the fast reader leaves a file to Assimp.
struct ObjFallback {
    std::size_t line = 0;  // 1-based; 0 when the reason is not one line
    std::string reason;
};

// Reads an OBJ file that check_input_file has accepted. Throws InputError ("FILE: line N:
// cause" where a line is to blame) for out-of-range or zero face indices, non-finite vertex
// coordinates, no triangles, too many triangles, or an unreadable file.
std::variant<LoadedScene, ObjFallback> read_obj(const std::filesystem::path& path,
                                                const LoadOptions& options);

// load_scene through Assimp for any format (defined in load_scene.cpp): what read_obj falls back
// to, and what the tests compare it with. In this process or in a worker process, as
// options.isolation says. For an OBJ, `obj_libraries` is the scan of its material libraries
// when the caller made it (else it is made after the import).
LoadedScene load_scene_with_assimp(const std::filesystem::path& path, const LoadOptions& options,
                                   const ObjMaterialLibraries* obj_libraries = nullptr);

// The checks made before Assimp sees a file (input_file_check, declared_counts_check with the
// glTF byte ranges). Returns the file size. Throws InputError.
std::uintmax_t precheck_assimp_input(const std::filesystem::path& path, const LoadOptions& options);

// The import and conversion proper, always in this process; the pre-checks too unless
// `prechecked` (the worker's parent made them).
LoadedScene import_with_assimp(const std::filesystem::path& path, const LoadOptions& options,
                               bool prechecked,
                               const ObjMaterialLibraries* obj_libraries = nullptr);

}  // namespace zraster::io
