// The warning for normals a file gives that cannot be used (not finite, of zero length, or
// missing for some corners of a mesh that has them): such vertices get normals computed from the
// faces (angle-weighted, as for a file without normals), so every normal of a loaded scene is of
// unit length. One warning per file, from zraster's OBJ reader and the Assimp path alike.
#pragma once
#include <string>

namespace zraster::io {

// `first_mesh`: the label of the first mesh (in the scene's order) whose normals were replaced.
inline std::string recomputed_normals_warning(const std::string& first_mesh) {
    return "normals that are missing, not finite or of zero length (first in mesh " + first_mesh +
           ") recomputed from the faces";
}

}  // namespace zraster::io
