// Face indices of an OBJ file that zraster's reader leaves to Assimp (polygons of five or more
// corners, mixed corner forms, ...: obj_parser.hpp). Assimp's OBJ importer clamps or drops a
// texture coordinate or normal index past the file's values without a word, so that a corner
// takes another one's uv or normal; the reader refuses such indices in the files it reads, and
// this scan does for the others, before Assimp.
//
// It is deliberately narrower than the reader: only `f` lines whose every corner is v, v/vt,
// v//vn or v/vt/vn with plain indices are checked, a texture or normal slot only where Assimp
// reads it as one (after the file's first `vt`), and a file with line continuations not at all.
#pragma once
#include <zraster/load.hpp>

#include <filesystem>
#include <string>

namespace zraster::io {

// Throws InputError("FILE: line N: texture coordinate index out of range (I; the file has N
// texture coordinates)", and likewise for vertex and normal indices) for the first such index,
// "FILE: line N: 'WORD' is not a number" for a coordinate or index that is not one (as the reader
// refuses it: obj_number_token.hpp), and "FILE: line N: a face of C corners; at most 32767".
// Throws LimitExceeded past options.max_triangulation_work (triangulation_budget.hpp).
// `warning`, when given, receives the first vertex color outside 0..1
// (vertex_color_outside_warning), empty when there is none.
void check_obj_indices(const std::filesystem::path& path, const LoadOptions& options,
                       std::string* warning = nullptr);

// "line N: vertex color (r, g, b) is outside 0..1; zraster does not use OBJ vertex colors
// (ignored)": what both OBJ paths warn, once a file.
std::string vertex_color_outside_warning(std::size_t line, const float* rgb);

}  // namespace zraster::io
