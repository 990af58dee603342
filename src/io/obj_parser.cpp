// Reading an OBJ file (see obj_parser.hpp, and docs/obj-format.md for the format as read): the
// steps, in order. Each part has its own file:
//   obj_scan          the file's bytes, cut into line-aligned chunks
//   obj_numbers       floats and face indices
//   obj_chunk_parser  the lines of each chunk, chunks in parallel
//   (here)            chunk offsets; corner indices resolved and values gathered, in parallel
//   obj_materials     the mtllib statements, the libraries they read, the scene's materials
//   obj_structure     objects, groups and meshes, as the statements replayed in file order give
//   obj_mesh_builder  meshes built in parallel, welded and triangulated as the Assimp path does
// A step that finds an error of the file throws an InputError; one that finds a line the reader
// leaves to Assimp returns an ObjFallback, which read_obj returns. docs/obj-format.md gives the
// order in which problems are reported.
#include "io/obj_parser.hpp"

#include <zraster/error.hpp>

#include "io/obj_chunk_parser.hpp"
#include "io/obj_index_scan.hpp"
#include "io/obj_materials.hpp"
#include "io/obj_mesh_builder.hpp"
#include "io/obj_numbers.hpp"
#include "io/obj_scan.hpp"
#include "io/obj_structure.hpp"
#include "io/recomputed_normals.hpp"
#include "io/text_util.hpp"

#include <tbb/parallel_for.h>

#include <cstring>

namespace zraster::io {

namespace obj {
namespace {

std::string at_line(std::size_t line, const std::string& what) {
    return "line " + std::to_string(line) + ": " + what;
}

// Where each chunk's values and faces start among the file's: how many the chunks before it
// hold (one more entry than chunks, the last one the file's total).
struct Offsets {
    std::vector<std::size_t> positions, uvs, normals, faces;
};

// Gives each chunk its first line and its offsets. The first chunk that stopped at a problem
// stops reading: its error is thrown, or its fallback returned.
std::optional<ObjFallback> count_chunks(std::vector<Chunk>& chunks, const std::string& file,
                                        Offsets& offsets) {
    const std::size_t n = chunks.size();
    offsets.positions.assign(n + 1, 0);
    offsets.uvs.assign(n + 1, 0);
    offsets.normals.assign(n + 1, 0);
    offsets.faces.assign(n + 1, 0);
    for (std::size_t k = 0; k < n; ++k) {
        Chunk& c = chunks[k];
        if (k > 0) c.first_line = chunks[k - 1].first_line + chunks[k - 1].lines;
        if (c.problem) {
            const std::size_t line = c.first_line + c.problem->line + 1;
            if (c.problem->error) throw InputError(file, at_line(line, c.problem->what));
            return ObjFallback{line, c.problem->what};
        }
        offsets.positions[k + 1] = offsets.positions[k] + c.positions.size() / 3;
        offsets.uvs[k + 1] = offsets.uvs[k] + c.uvs.size() / 2;
        offsets.normals[k + 1] = offsets.normals[k] + c.normals.size() / 3;
        offsets.faces[k + 1] = offsets.faces[k] + c.faces.size();
    }
    if (offsets.positions[n] >= kNone || offsets.uvs[n] >= kNone || offsets.normals[n] >= kNone)
        return ObjFallback{0, "more than 2^32 - 1 vertices"};
    return std::nullopt;
}

// Chunk k's values, copied to their place among the file's.
void gather_values(const Chunk& c, std::size_t k, const Offsets& offsets, Attributes& attributes) {
    // The arrays may be empty: memcpy from a null data() is undefined even for 0 bytes (UBSan,
    // found by fuzz_load_obj).
    if (!c.positions.empty())
        std::memcpy(attributes.positions.data() + offsets.positions[k], c.positions.data(),
                    c.positions.size() * sizeof(float));
    if (!c.uvs.empty())
        std::memcpy(attributes.uvs.data() + offsets.uvs[k], c.uvs.data(),
                    c.uvs.size() * sizeof(float));
    if (!c.normals.empty())
        std::memcpy(attributes.normals.data() + offsets.normals[k], c.normals.data(),
                    c.normals.size() * sizeof(float));
}

// What resolving a chunk's corner indices found: its first error and its first fallback.
struct Resolution {
    std::optional<std::pair<std::uint32_t, std::string>> error, fallback;  // line, what
};

// "vertex index out of range (9; the file has 3 vertices)": `what` names the index and the
// value (`values` its plural), for an encoded index `raw` resolved outside the file's `total`.
std::string index_out_of_range(const std::string& what, const std::string& values, std::int32_t raw,
                               std::size_t total) {
    if (raw < 0)
        return what + " index out of range (a negative index before the first " + what + ")";
    return what + " index out of range (" + std::to_string(raw + 1) + "; the file has " +
           std::to_string(total) + " " + values + ")";
}

// Replaces chunk k's corner indices by global ones. An index of any kind outside the file's
// values is an error: Assimp would read a vertex index past the end as garbage, and clamps or
// drops texture coordinate and normal indices without a word (a face then gets another
// corner's uv or normal).
Resolution resolve_corners(Chunk& c, std::size_t k, const Offsets& offsets) {
    const std::size_t total_v = offsets.positions.back(), total_t = offsets.uvs.back(),
                      total_n = offsets.normals.back();
    Resolution r;
    if (c.uv_slot_without_uvs && offsets.uvs[k] == 0)
        r.fallback = {*c.uv_slot_without_uvs,
                      "texture index before any texture coordinate (Assimp reads it as a "
                      "normal index)"};
    for (const Face& face : c.faces) {
        for (std::size_t corner = face.first; corner < face.first + face.corners; ++corner) {
            const std::int64_t v = resolve_index(c.corner_v[corner], offsets.positions[k], total_v);
            if (v < 0) {
                r.error = {face.line,
                           index_out_of_range("vertex", "vertices", c.corner_v[corner], total_v)};
                return r;
            }
            c.corner_v[corner] = static_cast<std::int32_t>(v);
            if (face.attributes & kHasUv) {
                const std::int64_t t = resolve_index(c.corner_t[corner], offsets.uvs[k], total_t);
                // (In a file with normals and no `vt`, Assimp reads the slot as a normal index:
                // the fallback above.)
                if (t < 0 && !(total_t == 0 && total_n > 0)) {
                    r.error = {face.line,
                               index_out_of_range("texture coordinate", "texture coordinates",
                                                  c.corner_t[corner], total_t)};
                    return r;
                }
                c.corner_t[corner] = static_cast<std::int32_t>(t);
            }
            if (face.attributes & kHasNormal) {
                const std::int64_t m =
                    resolve_index(c.corner_n[corner], offsets.normals[k], total_n);
                if (m < 0) {
                    r.error = {face.line, index_out_of_range("normal", "normals",
                                                             c.corner_n[corner], total_n)};
                    return r;
                }
                c.corner_n[corner] = static_cast<std::int32_t>(m);
            }
        }
    }
    return r;
}

// Every chunk's values gathered and corner indices resolved, in parallel; then the first error
// (thrown) and else the first fallback, in file order.
std::optional<ObjFallback> resolve_indices(std::vector<Chunk>& chunks, const Offsets& offsets,
                                           const std::string& file, Attributes& attributes) {
    attributes.positions.resize(offsets.positions.back());
    attributes.uvs.resize(offsets.uvs.back());
    attributes.normals.resize(offsets.normals.back());
    const std::size_t n = chunks.size();
    std::vector<Resolution> resolutions(n);
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t k) {
        gather_values(chunks[k], k, offsets, attributes);
        resolutions[k] = resolve_corners(chunks[k], k, offsets);
    });
    for (std::size_t k = 0; k < n; ++k) {
        if (const auto& error = resolutions[k].error)
            throw InputError(file, at_line(chunks[k].first_line + error->first + 1, error->second));
    }
    for (std::size_t k = 0; k < n; ++k) {
        if (const auto& fallback = resolutions[k].fallback)
            return ObjFallback{chunks[k].first_line + fallback->first + 1, fallback->second};
    }
    return std::nullopt;
}

void check_triangle_count(std::size_t triangles, const std::string& file,
                          const LoadOptions& options) {
    if (triangles == 0) throw InputError(file, "no triangles");
    if (triangles > options.max_triangles)
        throw LimitExceeded(file, "max_triangles",
                            "too many triangles (" + std::to_string(triangles) + ", limit " +
                                std::to_string(options.max_triangles) + ")");
}

// The first mesh with a non-finite position, as convert_mesh reports it, and the line of its `v`.
void check_finite_positions(const std::vector<MeshOutcome>& built, const std::vector<Chunk>& chunks,
                            const Offsets& offsets, const Structure& structure,
                            const std::vector<std::uint32_t>& output, const std::string& file) {
    for (std::size_t i = 0; i < built.size(); ++i) {
        if (!built[i].non_finite) continue;
        const auto [position, vertex] = *built[i].non_finite;
        const std::size_t k = chunk_holding(offsets.positions, position);
        std::size_t line = 0;
        for (const auto& [index, local_line] : chunks[k].non_finite_positions)
            if (offsets.positions[k] + index == position)
                line = chunks[k].first_line + local_line + 1;
        const std::string& name = structure.meshes[output[i]].name;
        throw InputError(file, at_line(line, "non-finite vertex coordinates (mesh " +
                                                 (name.empty() ? "#" + std::to_string(i) : name) +
                                                 ", vertex " + std::to_string(vertex) + ")"));
    }
}

// The scene: the built meshes with their materials, one instance each, named after its object.
std::variant<LoadedScene, ObjFallback> assemble_scene(const std::filesystem::path& path,
                                                      std::vector<MeshOutcome>& built,
                                                      const Structure& structure,
                                                      const std::vector<std::uint32_t>& output,
                                                      const Statements& statements,
                                                      const LoadOptions& options) {
    const std::string file = path.string();
    LoadedScene loaded;
    Scene& scene = loaded.scene;
    scene.name = file;
    std::vector<std::string> warnings;
    Materials materials(path, statements, options, scene, warnings);
    std::optional<std::string> recomputed;  // the first mesh whose normals were replaced
    for (std::size_t i = 0; i < built.size(); ++i) {
        const MeshPlan& plan = structure.meshes[output[i]];
        const std::optional<std::uint32_t> material = materials.index_of(plan.material);
        if (!material) return ObjFallback{0, "Assimp cannot read the material libraries"};
        Mesh& mesh = built[i].mesh;
        mesh.material = *material;
        if (built[i].normals_recomputed && !recomputed)
            recomputed = mesh.name.empty() ? "#" + std::to_string(i) : mesh.name;
        Instance instance;
        instance.mesh = static_cast<std::uint32_t>(scene.meshes.size());
        const std::string& object = structure.objects[plan.object].name;
        instance.name = object.empty() ? mesh.name : object;
        scene.meshes.push_back(std::move(mesh));
        scene.instances.push_back(std::move(instance));
    }
    if (recomputed) warnings.push_back(recomputed_normals_warning(*recomputed));
    // One line each, as load_scene_with_assimp makes them.
    for (const std::string& w : warnings) loaded.warnings.push_back(file + ": " + one_line(w));
    return loaded;
}

}  // namespace
}  // namespace obj

std::variant<LoadedScene, ObjFallback> read_obj(const std::filesystem::path& path,
                                                const LoadOptions& options) {
    const std::string file = path.string();
    const obj::FileBytes bytes(path);
    if (bytes.size() == 0) throw InputError(file, "empty file");
    if (bytes.size() < 16) return ObjFallback{0, "Assimp refuses OBJ files under 16 bytes"};

    std::vector<obj::Chunk> chunks = obj::parse_chunks(bytes.data(), bytes.size());
    obj::Offsets offsets;
    if (auto fallback = obj::count_chunks(chunks, file, offsets)) return *fallback;
    obj::Attributes attributes;
    if (auto fallback = obj::resolve_indices(chunks, offsets, file, attributes)) return *fallback;

    // The material libraries before the structure: reading one changes Assimp's current
    // material.
    obj::Statements statements;
    const ReferencePolicy policy(path, options.allow_outside_references);
    if (auto fallback = obj::read_statements(path, chunks, policy, options, statements))
        return *fallback;
    obj::Structure structure = obj::replay_statements(chunks, offsets.faces, statements.libraries);
    const obj::OutputMeshes output = obj::output_meshes(structure, chunks, offsets.faces);
    obj::check_triangle_count(output.triangles, file, options);

    obj::index_equal_values(chunks, attributes);
    std::vector<obj::MeshOutcome> built =
        obj::build_meshes(chunks, offsets.faces, attributes, structure.meshes, output.meshes);
    obj::check_finite_positions(built, chunks, offsets, structure, output.meshes, file);
    std::variant<LoadedScene, ObjFallback> result =
        obj::assemble_scene(path, built, structure, output.meshes, statements, options);
    if (LoadedScene* loaded = std::get_if<LoadedScene>(&result)) {
        loaded->files_read = policy.files_read();
        for (const obj::Chunk& c : chunks)
            if (c.color_outside_line) {
                loaded->warnings.push_back(
                    file + ": " +
                    vertex_color_outside_warning(c.first_line + *c.color_outside_line + 1,
                                                 c.color_outside));
                break;
            }
    }
    return result;
}

}  // namespace zraster::io
