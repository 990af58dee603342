#include "io/assimp_mesh.hpp"

#include <zraster/error.hpp>

#include "io/weld_vertices.hpp"

#include <assimp/mesh.h>

#include <algorithm>
#include <cmath>

namespace zraster::io {

namespace {

bool finite(const aiVector3D& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// File normals are used when usable: unit length after normalisation. Returns false when some
// are not (zero or non-finite); those are replaced by computed ones.
bool copy_normals(const aiMesh& source, Mesh& mesh) {
    bool all_valid = true;
    mesh.normals.resize(source.mNumVertices);
    for (unsigned v = 0; v < source.mNumVertices; ++v) {
        const aiVector3D& n = source.mNormals[v];
        // In double: squares of tiny float components are denormal in float (a normal of
        // length 1e-20 came out 6% too long) and squares of huge ones overflow.
        const glm::dvec3 d(n.x, n.y, n.z);
        const double length = glm::length(d);
        if (finite(n) && std::isfinite(length) && length > 0.0) {
            mesh.normals[v] = glm::vec3(d / length);
        } else {
            mesh.normals[v] = glm::vec3(std::nanf(""));
            all_valid = false;
        }
    }
    return all_valid;
}

// The first vertex-color set (glTF COLOR_0, PLY red/green/blue/alpha), as Assimp normalizes it:
// components outside [0, 1] are clamped and non-finite ones become 1, each with one warning.
void copy_colors(const aiMesh& source, const MeshConversion& how, Mesh& mesh,
                 std::vector<std::string>& warnings) {
    const std::string& label = how.label;
    bool clamped = false, replaced = false;
    mesh.colors.resize(source.mNumVertices);
    for (unsigned v = 0; v < source.mNumVertices; ++v) {
        const aiColor4D& c = source.mColors[0][v];
        float in[4] = {c.r, c.g, c.b, c.a};
        for (float& x : in) {
            if (!std::isfinite(x)) {
                x = 1.0f;
                replaced = true;
            } else if (x < 0.0f || x > 1.0f) {
                x = std::clamp(x, 0.0f, 1.0f);
                clamped = true;
            }
        }
        mesh.colors[v] = glm::vec4(in[0], in[1], in[2], in[3]);
    }
    bool alpha_zero = true, all_zero = true;
    for (const glm::vec4& c : mesh.colors) {
        alpha_zero &= c.w == 0.0f;
        all_zero &= c == glm::vec4(0.0f);
    }
    // Every color (0, 0, 0, 0): what Assimp gives an AMF file that has none. Multiplied in, it
    // would hide the mesh; read as no colors.
    if (all_zero && how.color_alpha != GltfColorAlpha::Opaque) {
        mesh.colors.clear();
        warnings.push_back("mesh " + label +
                           ": vertex colors all (0, 0, 0, 0), as the importer reads a file "
                           "without colors: ignored");
        return;
    }
    if (how.color_alpha == GltfColorAlpha::Opaque ||
        (how.color_alpha == GltfColorAlpha::OpaqueWhereZero && alpha_zero))
        for (glm::vec4& c : mesh.colors) c.w = 1.0f;
    if (replaced) warnings.push_back("mesh " + label + ": non-finite vertex colors replaced by 1");
    if (clamped)
        warnings.push_back("mesh " + label + ": vertex colors outside [0, 1] clamped to it");
}

}  // namespace

Mesh convert_mesh(const aiMesh& source, const MeshConversion& how,
                  std::vector<std::string>& warnings, bool* normals_recomputed) {
    const std::string& label = how.label;
    const std::string& file = how.file;
    Mesh mesh;
    mesh.name = source.mName.C_Str();
    const unsigned count = source.mNumVertices;

    mesh.positions.reserve(count);
    for (unsigned v = 0; v < count; ++v) {
        const aiVector3D& p = source.mVertices[v];
        if (!finite(p))
            throw InputError(file, "non-finite vertex coordinates (mesh " + label + ", vertex " +
                                       std::to_string(v) + ")");
        mesh.positions.emplace_back(p.x, p.y, p.z);
    }

    mesh.indices.reserve(std::size_t{source.mNumFaces} * 3);
    for (unsigned f = 0; f < source.mNumFaces; ++f) {
        const aiFace& face = source.mFaces[f];
        if (face.mNumIndices != 3) continue;  // points and lines: not drawn
        for (unsigned k = 0; k < 3; ++k) {
            if (face.mIndices[k] >= count)
                throw InputError(file, "vertex index out of range (mesh " + label + ", face " +
                                           std::to_string(f) + ")");
            mesh.indices.push_back(face.mIndices[k]);
        }
    }

    if (source.HasTextureCoords(0)) {
        bool replaced = false;
        mesh.uvs.reserve(count);
        for (unsigned v = 0; v < count; ++v) {
            const aiVector3D& t = source.mTextureCoords[0][v];
            const bool ok = std::isfinite(t.x) && std::isfinite(t.y);
            replaced |= !ok;
            mesh.uvs.push_back(ok ? glm::vec2(t.x, t.y) : glm::vec2(0.0f));
        }
        if (replaced)
            warnings.push_back("mesh " + label +
                               ": non-finite texture coordinates replaced by (0, 0)");
    }

    if (how.vertex_colors && source.HasVertexColors(0)) copy_colors(source, how, mesh, warnings);

    if (source.HasNormals()) {
        if (!copy_normals(source, mesh)) {
            if (normals_recomputed != nullptr) *normals_recomputed = true;
            const std::vector<glm::vec3> computed = normals_over_shared_positions(mesh);
            for (std::size_t v = 0; v < mesh.normals.size(); ++v)
                if (std::isnan(mesh.normals[v].x)) mesh.normals[v] = computed[v];
        }
    }
    if (how.weld) weld_identical_vertices(mesh);
    if (mesh.normals.empty()) mesh.normals = normals_over_shared_positions(mesh);
    update_bounds(mesh);
    return mesh;
}

}  // namespace zraster::io
