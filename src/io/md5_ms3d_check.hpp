// Two game formats whose importers trust the counts and indices they read: Doom 3's MD5 meshes
// (a triangle index of -1 failed an assertion, a vertex naming 60,000 weights of 3 read past
// them: SIGSEGV) and MilkShape 3D (.ms3d: triangles over 0 vertices: SIGSEGV). Checked before
// the import, naming the record.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

namespace zraster::io {

// An MD5 mesh file's text: InputError(file, "malformed MD5 file: line N: ...") for a triangle
// index that is not one of its mesh's vertices, or a vertex whose weights are not among its
// mesh's.
void check_md5_mesh(std::string_view text, const std::string& file);

// An MS3D file's bytes: InputError(file, "malformed MS3D file: ...") for a triangle naming a
// vertex past the vertices (or any, when there are none).
void check_ms3d(std::string_view bytes, const std::string& file);

}  // namespace zraster::io
