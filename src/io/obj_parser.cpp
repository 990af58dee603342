// The fast OBJ reader (see obj_parser.hpp). Stages:
//  1. The file is mapped and cut into line-aligned chunks, parsed in parallel: each chunk keeps
//     its own v/vt/vn arrays, faces (corner indices as written, negative ones relative to the
//     chunk's own counts) and the o/g/usemtl/mtllib statements between them.
//  2. Prefix sums give every chunk its global offsets; a second parallel pass resolves and
//     range-checks the corner indices in place.
//  3. The statements replay Assimp's object/mesh bookkeeping in file order, which cuts the face
//     sequence into meshes.
//  4. Meshes are built in parallel: one vertex per distinct (position, normal, uv) value, in
//     first-corner order, exactly as welding Assimp's per-corner vertices gives; quads are split
//     as Assimp's triangulation splits them.
//  5. Materials: the MTL libraries are resolved and read by Assimp (from a small generated OBJ
//     that repeats the file's mtllib and usemtl statements in order), then converted as the
//     Assimp path converts them.
//
// How Assimp 5.2's OBJ importer reads a line (the behaviour reproduced here, found by feeding it
// small files): the first character picks the statement; lines starting with a blank are
// ignored; `o` names an object by the first word of the rest, reusing an existing object of that
// name without changing the current mesh; `g` creates an object named by the whole rest of the
// line (trailing blanks included) when it differs from the active group; `usemtl` (trimmed name)
// starts a mesh named after the material when the current mesh has faces and another material,
// otherwise it sets the current mesh's material; reading an MTL library makes its last material
// the current one (so later objects get it) and gives each new material to the current mesh;
// faces before any object create "defaultobject"; `l` and `p` elements count as faces of the
// current mesh but are dropped later; a non-finite texture coordinate reads as 0.
//
// Welding: each v, vt and vn value gets the index of the first equal value (after
// normalisation, the v flip, -0 == +0), and a mesh vertex is one distinct triple of those, so
// that equal values written twice weld as they do in the Assimp path.
#include "io/obj_parser.hpp"

#include <zraster/error.hpp>

#include "io/obj_chunk_parser.hpp"
#include "io/obj_materials.hpp"
#include "io/obj_mesh_builder.hpp"
#include "io/obj_numbers.hpp"
#include "io/obj_scan.hpp"
#include "io/obj_structure.hpp"
#include "io/text_util.hpp"

#include <tbb/parallel_for.h>

#include <cstring>
#include <optional>

namespace zraster::io {

std::variant<Scene, ObjFallback> read_obj(const std::filesystem::path& path,
                                          const LoadOptions& options) {
    const std::string file = path.string();
    const obj::FileBytes bytes(path);
    if (bytes.size() == 0) throw InputError(file, "empty file");
    if (bytes.size() < 16) return ObjFallback{0, "Assimp refuses OBJ files under 16 bytes"};

    // Stage 1.
    std::vector<obj::Chunk> chunks = obj::parse_chunks(bytes.data(), bytes.size());

    const std::size_t n = chunks.size();
    std::vector<std::size_t> v_prefix(n + 1), t_prefix(n + 1), n_prefix(n + 1), face_prefix(n + 1);
    for (std::size_t k = 0; k < n; ++k) {
        obj::Chunk& c = chunks[k];
        if (k > 0) c.first_line = chunks[k - 1].first_line + chunks[k - 1].lines;
        if (c.problem) {
            const std::size_t line = c.first_line + c.problem->line + 1;
            if (c.problem->error)
                throw InputError(file, "line " + std::to_string(line) + ": " + c.problem->what);
            return ObjFallback{line, c.problem->what};
        }
        v_prefix[k + 1] = v_prefix[k] + c.positions.size() / 3;
        t_prefix[k + 1] = t_prefix[k] + c.uvs.size() / 2;
        n_prefix[k + 1] = n_prefix[k] + c.normals.size() / 3;
        face_prefix[k + 1] = face_prefix[k] + c.faces.size();
    }
    const std::size_t total_v = v_prefix[n], total_t = t_prefix[n], total_n = n_prefix[n];
    if (total_v >= obj::kNone || total_t >= obj::kNone || total_n >= obj::kNone)
        return ObjFallback{0, "more than 2^32 - 1 vertices"};

    // Stage 2: resolve indices in place, gather the attributes.
    obj::Attributes attributes;
    attributes.positions.resize(total_v);
    attributes.uvs.resize(total_t);
    attributes.normals.resize(total_n);
    struct Resolution {
        std::optional<std::pair<std::uint32_t, std::string>> error, fallback;  // line, what
    };
    std::vector<Resolution> resolutions(n);
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t k) {
        obj::Chunk& c = chunks[k];
        // The arrays may be empty: memcpy from a null data() is undefined even for 0 bytes
        // (UBSan, found by fuzz_load_obj).
        if (!c.positions.empty())
            std::memcpy(attributes.positions.data() + v_prefix[k], c.positions.data(),
                        c.positions.size() * sizeof(float));
        if (!c.uvs.empty())
            std::memcpy(attributes.uvs.data() + t_prefix[k], c.uvs.data(),
                        c.uvs.size() * sizeof(float));
        if (!c.normals.empty())
            std::memcpy(attributes.normals.data() + n_prefix[k], c.normals.data(),
                        c.normals.size() * sizeof(float));
        Resolution& r = resolutions[k];
        if (c.uv_slot_without_uvs && t_prefix[k] == 0)
            r.fallback = {*c.uv_slot_without_uvs,
                          "texture index before any texture coordinate (Assimp reads it as a "
                          "normal index)"};
        for (const obj::Face& face : c.faces) {
            for (std::size_t corner = face.first; corner < face.first + face.corners; ++corner) {
                const std::int64_t v = obj::resolve_index(c.corner_v[corner], v_prefix[k], total_v);
                if (v < 0) {
                    const std::int32_t raw = c.corner_v[corner];
                    r.error = {face.line,
                               raw >= 0
                                   ? "vertex index out of range (" + std::to_string(raw + 1) +
                                         "; the file has " + std::to_string(total_v) + " vertices)"
                                   : "vertex index out of range (a negative index before "
                                     "the first vertex)"};
                    return;
                }
                c.corner_v[corner] = static_cast<std::int32_t>(v);
                if (face.attributes & obj::kHasUv) {
                    const std::int64_t t =
                        obj::resolve_index(c.corner_t[corner], t_prefix[k], total_t);
                    if (t < 0 && !r.fallback)
                        r.fallback = {face.line, "texture coordinate index out of range"};
                    c.corner_t[corner] = static_cast<std::int32_t>(t);
                }
                if (face.attributes & obj::kHasNormal) {
                    const std::int64_t m =
                        obj::resolve_index(c.corner_n[corner], n_prefix[k], total_n);
                    if (m < 0 && !r.fallback) r.fallback = {face.line, "normal index out of range"};
                    c.corner_n[corner] = static_cast<std::int32_t>(m);
                }
            }
        }
    });
    for (std::size_t k = 0; k < n; ++k) {
        if (resolutions[k].error)
            throw InputError(
                file, "line " +
                          std::to_string(chunks[k].first_line + resolutions[k].error->first + 1) +
                          ": " + resolutions[k].error->second);
    }
    for (std::size_t k = 0; k < n; ++k) {
        if (resolutions[k].fallback)
            return ObjFallback{chunks[k].first_line + resolutions[k].fallback->first + 1,
                               resolutions[k].fallback->second};
    }

    // Stage 3. The material libraries first: reading them changes Assimp's current material.
    obj::Statements statements;
    if (auto fallback = obj::read_statements(path, chunks, statements)) return *fallback;
    obj::Structure structure = obj::replay_statements(chunks, face_prefix, statements.libraries);
    const obj::OutputMeshes output = obj::output_meshes(structure, chunks, face_prefix);
    if (output.triangles == 0) throw InputError(file, "no triangles");
    if (output.triangles > options.max_triangles)
        throw InputError(file, "too many triangles (" + std::to_string(output.triangles) +
                                   ", limit " + std::to_string(options.max_triangles) + ")");

    // Stage 4.
    obj::index_equal_values(chunks, attributes);
    std::vector<obj::MeshOutcome> built =
        obj::build_meshes(chunks, face_prefix, attributes, structure.meshes, output.meshes);
    for (std::size_t i = 0; i < built.size(); ++i) {
        if (!built[i].non_finite) continue;
        // The first mesh with one, as convert_mesh reports it, and the line of its `v`.
        const auto [position, vertex] = *built[i].non_finite;
        const std::size_t k = static_cast<std::size_t>(
            std::upper_bound(v_prefix.begin(), v_prefix.end(), position) - v_prefix.begin() - 1);
        std::size_t line = 0;
        for (const auto& [index, local_line] : chunks[k].non_finite_positions)
            if (v_prefix[k] + index == position) line = chunks[k].first_line + local_line + 1;
        const std::string& name = structure.meshes[output.meshes[i]].name;
        throw InputError(file, "line " + std::to_string(line) +
                                   ": non-finite vertex coordinates (mesh " +
                                   (name.empty() ? "#" + std::to_string(i) : name) + ", vertex " +
                                   std::to_string(vertex) + ")");
    }

    // Stage 5.
    Scene scene;
    scene.source = file;
    std::vector<std::string> warnings;
    obj::Materials materials(path, statements, scene, warnings);
    for (std::size_t i = 0; i < built.size(); ++i) {
        const obj::MeshPlan& plan = structure.meshes[output.meshes[i]];
        const std::optional<std::uint32_t> material = materials.index_of(plan.material);
        if (!material) return ObjFallback{0, "Assimp cannot read the material libraries"};
        Mesh& mesh = built[i].mesh;
        mesh.material = *material;
        Instance instance;
        instance.mesh = static_cast<std::uint32_t>(scene.meshes.size());
        const std::string& object = structure.objects[plan.object].name;
        instance.name = object.empty() ? mesh.name : object;
        scene.meshes.push_back(std::move(mesh));
        scene.instances.push_back(std::move(instance));
    }
    // One line each, as load_scene_with_assimp makes them.
    for (const std::string& w : warnings) scene.warnings.push_back(file + ": " + one_line(w));
    return scene;
}

}  // namespace zraster::io
