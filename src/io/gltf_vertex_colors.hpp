// glTF COLOR_0 of type VEC3 as Assimp delivers it. Debian's Assimp 5.2.5 copies the three
// components into a four-component color it leaves zeroed, so RGB vertex colors arrive with
// alpha 0, where glTF says they are opaque. Which primitives had VEC3 colors is read from the
// document here; Assimp's meshes do not say (and post-processing may split them).
#pragma once
#include <filesystem>

namespace zraster::io {

enum class GltfColorAlpha {
    AsRead,           // not glTF, or no COLOR_0 of type VEC3: keep Assimp's alpha
    Opaque,           // every COLOR_0 is VEC3: alpha 1
    OpaqueWhereZero,  // both kinds: a mesh whose alphas are all 0 had VEC3 colors
};

// For the glTF or GLB file at `path` (AsRead for any other, or a document that does not parse:
// the structure checks have refused what matters by then).
GltfColorAlpha gltf_color_alpha(const std::filesystem::path& path);

}  // namespace zraster::io
