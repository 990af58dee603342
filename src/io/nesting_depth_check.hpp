// Importers that read nested objects recursively overflow their stack on deep nesting: in
// process that is a crash no handler can catch (the default worker only reports it). For the
// formats below the nesting is measured before Assimp reads the file, as its parser would see it,
// and refused past kMaxNestingDepth levels (no model needs a hundred). COLLADA's nodes are
// measured by the COLLADA scan (collada_instances_check.hpp).
//
//   X (text)  Frames within Frames. A data reference ("{ m }") directly inside a Frame is read by
//             the importer as an unknown object that ends inside the next Frame, so sibling
//             Frames after it nest: 200,000 such frames overflowed its stack.
//   AC3D      OBJECTs within OBJECTs ("kids N" lines).
//   SMD       bones: each node's parent in the "nodes" section (100,000 bones in a chain crashed
//             the importer); a parent that is no node, or a loop of parents, is refused too.
#pragma once
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace zraster::io {

inline constexpr std::size_t kMaxNestingDepth = 1000;

// The deepest Frame nesting of a text X file's body (after its 16-byte header) as Assimp's parser
// reads it, and whether a data reference inside a Frame made Frames nest.
struct XFrameDepth {
    std::size_t depth = 0;
    bool reference_in_frame = false;
};
XFrameDepth x_frame_depth(std::string_view body);

// The deepest OBJECT nesting of an AC3D file.
std::size_t ac3d_object_depth(std::string_view text);

// The deepest chain of parents of an SMD file's "nodes" section; throws InputError(file, ...)
// for a parent that is not a node or a loop of parents.
std::size_t smd_bone_depth(std::string_view text, const std::string& file);

// Throws InputError(file, "malformed X/AC3D/SMD file: ...") for a text X or AC3D file (by its
// header) or an SMD file (by its extension, as Assimp picks it) nested past kMaxNestingDepth;
// does nothing for other files.
void check_nesting_depth(const std::filesystem::path& path, std::string_view head);

}  // namespace zraster::io
