// Scene loading through Assimp: checks before the import, the import itself, and the conversion
// to zraster's arrays (meshes, materials with textures, node instances).
#include <zraster/error.hpp>
#include <zraster/load.hpp>

#include "io/assimp_errors.hpp"
#include "io/assimp_material.hpp"
#include "io/assimp_mesh.hpp"
#include "io/assimp_nodes.hpp"
#include "io/assimp_warnings.hpp"
#include "io/cells_file.hpp"
#include "io/confined_io_system.hpp"
#include "io/declared_counts_check.hpp"
#include "io/drawable_check.hpp"
#include "io/format_structure_check.hpp"
#include "io/gltf_image_uris.hpp"
#include "io/gltf_material_types.hpp"
#include "io/gltf_texture_transform.hpp"
#include "io/input_file_check.hpp"
#include "io/load_worker.hpp"
#include "io/mirrored_mesh.hpp"
#include "io/mtl_dissolve.hpp"
#include "io/named_files.hpp"
#include "io/obj_index_scan.hpp"
#include "io/obj_material_libraries.hpp"
#include "io/obj_parser.hpp"
#include "io/recomputed_normals.hpp"
#include "io/reference_policy.hpp"
#include "io/text_util.hpp"
#include "io/texture_loader.hpp"

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <cctype>
#include <cmath>
#include <optional>
#include <set>
#include <variant>

namespace zraster {

namespace {

constexpr unsigned kUnset = ~0u;  // not converted (yet)

bool is_skeleton_placeholder(const aiScene& scene, const aiMesh& mesh) {
    return mesh.mMaterialIndex < scene.mNumMaterials &&
           scene.mMaterials[mesh.mMaterialIndex] != nullptr &&
           io::is_skeleton_placeholder_material(*scene.mMaterials[mesh.mMaterialIndex]);
}

// Faces of three or more corners in the imported (not yet triangulated) scene, not counting the
// skeleton Assimp draws for a file without meshes.
std::size_t count_polygons(const aiScene& scene) {
    std::size_t n = 0;
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        const aiMesh* mesh = scene.mMeshes[m];
        if (mesh == nullptr || mesh->mFaces == nullptr) continue;
        if (is_skeleton_placeholder(scene, *mesh)) continue;
        for (unsigned f = 0; f < mesh->mNumFaces; ++f)
            if (mesh->mFaces[f].mNumIndices >= 3 && mesh->mFaces[f].mIndices != nullptr) ++n;
    }
    return n;
}

std::string mesh_label(const aiMesh& mesh, unsigned index) {
    const std::string name = mesh.mName.C_Str();
    return name.empty() ? "#" + std::to_string(index) : name;
}

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// A node transform can turn finite positions into infinities or NaN. If the transformed box is
// finite, so is every point in it; otherwise find the first bad vertex for the message.
void check_instance_finite(const Mesh& mesh, const glm::mat4& transform, const std::string& label,
                           const std::string& file) {
    const Bounds3f box = mesh.bounds.transformed(transform);
    if (finite(box.lo) && finite(box.hi)) return;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::vec4 q = transform * glm::vec4(mesh.positions[v], 1.0f);
        if (!finite(glm::vec3(q) / q.w))
            throw InputError(file, "non-finite vertex coordinates (mesh " + label + ", vertex " +
                                       std::to_string(v) + ")");
    }
}

bool is_obj(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension == ".obj";
}

class MaterialTable {
  public:
    MaterialTable(const aiScene& scene, const std::filesystem::path& path,
                  const io::ReferencePolicy& policy, const LoadOptions& options, Scene& out,
                  std::vector<std::string>& warnings, const io::ObjMaterialLibraries* scanned)
        : scene_(scene),
          out_(out),
          warnings_(warnings),
          textures_(scene, path, policy, options, warnings),
          map_(scene.mNumMaterials, kUnset) {
        if (is_obj(path)) {
            // The caller's scan when it made one (load_any's, before the import): one a file.
            io::ObjMaterialLibraries libraries =
                scanned != nullptr ? *scanned
                                   : io::scan_obj_material_libraries(path, policy, options);
            warnings.insert(warnings.end(), libraries.warnings.begin(), libraries.warnings.end());
            warnings.insert(warnings.end(), libraries.notices.begin(), libraries.notices.end());
            obj_missing_library_ = !libraries.warnings.empty();
            obj_defined_ = std::move(libraries.defined_materials);
            obj_dissolve_ = std::move(libraries.dissolve);
        }
    }

    // Our index for an Assimp material, converting it on first use.
    std::uint32_t index_of(unsigned ai_index) {
        if (ai_index >= scene_.mNumMaterials || scene_.mMaterials[ai_index] == nullptr) return 0;
        if (map_[ai_index] != kUnset) return map_[ai_index];
        const aiMaterial& source = *scene_.mMaterials[ai_index];
        map_[ai_index] = 0;
        if (io::is_placeholder_material(source)) return 0;
        const std::string name = io::material_name(source);
        // Assimp's OBJ importer invents a material for a `usemtl` that no library defines.
        if (obj_defined_ && !obj_defined_->contains(name)) {
            if (!obj_missing_library_)
                warnings_.push_back("material '" + name +
                                    "' is not defined, using the default material");
            return 0;
        }
        Material material =
            io::convert_material(source, "material " + std::to_string(ai_index), warnings_);
        obj_dissolve_.apply(material, warnings_);
        textures_.attach_textures(source, material);
        map_[ai_index] = static_cast<std::uint32_t>(out_.materials.size());
        out_.materials.push_back(std::move(material));
        return map_[ai_index];
    }

  private:
    const aiScene& scene_;
    Scene& out_;
    std::vector<std::string>& warnings_;
    io::TextureLoader textures_;
    std::vector<unsigned> map_;
    std::optional<std::set<std::string>> obj_defined_;
    io::MtlDissolve obj_dissolve_;  // OBJ only: `d` over `Tr`
    bool obj_missing_library_ = false;
};

io::LoadedScene load_any(const std::filesystem::path& path, const LoadOptions& options) {
    if (io::is_cells_file(path)) return io::load_cells_file(path, options);
    if (!is_obj(path)) return io::load_scene_with_assimp(path, options);
    io::check_input_file(path, options.max_file_bytes);
    std::variant<io::LoadedScene, io::ObjFallback> fast = io::read_obj(path, options);
    if (io::LoadedScene* loaded = std::get_if<io::LoadedScene>(&fast)) return std::move(*loaded);

    // A file the fast reader leaves to Assimp. If Assimp cannot read it either, the line that
    // looked wrong comes first: Assimp's messages name neither the line nor, often, the cause
    // ("vertex index out of range" for a coordinate that is not a number).
    const io::ObjFallback& fallback = std::get<io::ObjFallback>(fast);
    std::string color_warning;  // a vertex color outside 0..1, which neither path uses
    io::check_obj_indices(path, options, &color_warning);  // what Assimp would clamp or drop
    // Its material libraries' numbers too: Assimp fails on a short color in its own words. The
    // scan's materials serve the conversion after the import.
    const io::ObjMaterialLibraries libraries = io::scan_obj_material_libraries(
        path, io::ReferencePolicy(path, options.allow_outside_references), options);
    try {
        io::LoadedScene loaded = io::load_scene_with_assimp(path, options, &libraries);
        if (!color_warning.empty()) loaded.warnings.push_back(path.string() + ": " + color_warning);
        return loaded;
    } catch (const LimitExceeded&) {
        throw;
    } catch (const InputError& e) {
        const std::optional<std::string> detail = io::assimp_detail(e.cause());
        if (fallback.line == 0 || !detail) throw;
        throw InputError(e.file(), "malformed OBJ file: line " + std::to_string(fallback.line) +
                                       ": " + fallback.reason + " (Assimp: " + *detail + ")");
    }
}

}  // namespace

Scene load_scene(const std::filesystem::path& path, const LoadOptions& options,
                 std::vector<std::string>* warnings,
                 std::vector<std::filesystem::path>* files_read) {
    io::LoadedScene loaded = load_any(path, options);
    io::check_some_triangle_has_area(loaded.scene, path.string());
    if (warnings != nullptr)
        warnings->insert(warnings->end(), loaded.warnings.begin(), loaded.warnings.end());
    if (files_read != nullptr)
        files_read->insert(files_read->end(), loaded.files_read.begin(), loaded.files_read.end());
    return std::move(loaded.scene);
}

io::LoadedScene io::load_scene_with_assimp(const std::filesystem::path& path,
                                           const LoadOptions& options,
                                           const io::ObjMaterialLibraries* obj_libraries) {
    if (options.isolation == LoadIsolation::WorkerProcess)
        return io::load_in_worker(path, options, obj_libraries);
    return io::import_with_assimp(path, options, false, obj_libraries);
}

std::uintmax_t io::precheck_assimp_input(const std::filesystem::path& path,
                                         const LoadOptions& options) {
    const std::uintmax_t size = io::check_input_file(path, options.max_file_bytes);
    io::check_declared_counts(path, size, options);
    io::check_format_structure(path, size);
    return size;
}

io::LoadedScene io::import_with_assimp(const std::filesystem::path& path,
                                       const LoadOptions& options, bool prechecked,
                                       const io::ObjMaterialLibraries* obj_libraries) {
    const std::string file = path.string();
    if (!prechecked) io::precheck_assimp_input(path, options);

    Assimp::Importer importer;
    const io::ReferencePolicy policy(path, options.allow_outside_references);
    std::vector<std::string> refusals;
    auto* io_system = new io::ConfinedIOSystem(policy, refusals);
    if (is_obj(path))
        io_system->rewrite_material_libraries(file);
    else
        io_system->decode_uris_of(file);
    io_system->limit_file_size(options.max_file_bytes);
    importer.SetIOHandler(io_system);  // the importer owns it
    // Points and lines are not drawn: drop them while sorting primitives by type.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                                aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    // Assimp's own words only as a detail after ours (io::throw_assimp_error).
    const aiScene* ai = nullptr;
    io::AssimpWarnings assimp_warnings;
    try {
        ai = importer.ReadFile(file, 0);
        if (ai == nullptr && !refusals.empty())
            throw InputError(file, io::refusal_text(refusals.front(), "refused"));
        if (ai == nullptr) io::throw_assimp_error(path, io::one_line(importer.GetErrorString()));
        // (An OBJ's libraries were counted before the import.)
        if (!is_obj(path) && ai->mNumMaterials > options.max_materials)
            throw LimitExceeded(file, "max_materials",
                                "it defines " + std::to_string(ai->mNumMaterials) +
                                    " materials, more than max_materials (" +
                                    std::to_string(options.max_materials) + ")");
        // Checked before post-processing, which rejects faceless meshes as "invalid".
        if (count_polygons(*ai) == 0) {
            for (unsigned m = 0; m < ai->mNumMeshes; ++m)
                if (ai->mMeshes[m] != nullptr && is_skeleton_placeholder(*ai, *ai->mMeshes[m]))
                    throw InputError(
                        file,
                        "no triangles in it (no mesh, only nodes: is it really a model in the " +
                            io::format_name(path) + " format?)");
            // The geometry may be in a refused reference (an object of a scene): name it.
            if (!refusals.empty())
                throw InputError(file,
                                 "no triangles; " + io::refusal_text(refusals.front(), "refused"));
            throw InputError(file, "no triangles");
        }
        // Validation first: Debian's Assimp keeps its assertions, and triangulating a face with
        // missing indices (a short OFF body) would abort the process. No vertex joining, no
        // degenerate removal (the rasterizer handles degenerate triangles), no generated
        // normals. FlipUVs gives v = 0 at the image's first row, zraster's convention.
        ai = importer.ApplyPostProcessing(aiProcess_ValidateDataStructure | aiProcess_Triangulate |
                                          aiProcess_SortByPType | aiProcess_FlipUVs);
        if (ai == nullptr) io::throw_assimp_error(path, io::one_line(importer.GetErrorString()));
    } catch (const std::exception& e) {
        if (dynamic_cast<const InputError*>(&e)) throw;
        io::throw_assimp_error(path, io::one_line(e.what()));
    }

    const std::vector<io::NodeMesh> placements =
        io::collect_node_meshes(*ai, options.max_instances, file);
    std::size_t triangles = 0;
    std::vector<bool> referenced(ai->mNumMeshes, false);
    for (const io::NodeMesh& p : placements) {
        if (p.mesh >= ai->mNumMeshes)
            throw InputError(file, "malformed file: a node places mesh " + std::to_string(p.mesh) +
                                       ", the file has " + std::to_string(ai->mNumMeshes));
        const aiMesh& mesh = *ai->mMeshes[p.mesh];
        if (!(mesh.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
        triangles += mesh.mNumFaces;
        referenced[p.mesh] = true;
    }
    if (triangles == 0) throw InputError(file, "no triangles");
    if (triangles > options.max_triangles)
        throw LimitExceeded(file, "max_triangles",
                            "too many triangles (" + std::to_string(triangles) + ", limit " +
                                std::to_string(options.max_triangles) + ")");

    LoadedScene loaded;
    Scene& scene = loaded.scene;
    scene.name = file;
    std::vector<std::string> warnings;
    // (An OBJ's refused material libraries are warned about by the library scan instead.)
    if (!is_obj(path))
        for (const std::string& refusal : refusals)
            warnings.push_back(io::refusal_text(refusal, "not read"));
    for (std::string& warning : assimp_warnings.take()) warnings.push_back(std::move(warning));
    for (std::string& warning : io::gltf_material_type_warnings(path))
        warnings.push_back(std::move(warning));
    for (std::string& warning : io::gltf_image_uri_warnings(path))
        warnings.push_back(std::move(warning));
    MaterialTable materials(*ai, path, policy, options, scene, warnings, obj_libraries);
    // (The document is read again only when a mesh has vertex colors.)
    bool any_colors = false;
    for (unsigned m = 0; m < ai->mNumMeshes; ++m)
        any_colors |= referenced[m] && ai->mMeshes[m]->HasVertexColors(0);
    const io::GltfColorAlpha color_alpha =
        any_colors ? io::gltf_color_alpha(path) : io::GltfColorAlpha::AsRead;
    // glTF's KHR_texture_transform of each material's base color texture (Assimp's material
    // indices are glTF's, its default material appended).
    const std::vector<std::optional<io::TextureTransform>> uv_transforms =
        is_obj(path) ? std::vector<std::optional<io::TextureTransform>>{}
                     : io::gltf_base_color_transforms(path);
    std::vector<unsigned> our_mesh(ai->mNumMeshes, kUnset);
    std::vector<std::string> labels(ai->mNumMeshes);
    std::optional<std::string> recomputed;  // the first mesh whose normals were replaced
    for (unsigned m = 0; m < ai->mNumMeshes; ++m) {
        if (!referenced[m]) continue;
        labels[m] = mesh_label(*ai->mMeshes[m], m);
        bool normals_recomputed = false;
        Mesh mesh = io::convert_mesh(*ai->mMeshes[m],
                                     {labels[m], file, is_obj(path), color_alpha, !is_obj(path)},
                                     warnings, &normals_recomputed);
        if (mesh.indices.empty()) continue;
        if (normals_recomputed && !recomputed) recomputed = labels[m];
        if (const unsigned mi = ai->mMeshes[m]->mMaterialIndex;
            mi < uv_transforms.size() && uv_transforms[mi])
            io::apply_texture_transform(*uv_transforms[mi], mesh.uvs);
        mesh.material = materials.index_of(ai->mMeshes[m]->mMaterialIndex);
        our_mesh[m] = static_cast<unsigned>(scene.meshes.size());
        scene.meshes.push_back(std::move(mesh));
    }

    if (recomputed) warnings.push_back(io::recomputed_normals_warning(*recomputed));

    // A node that mirrors its mesh (a negative determinant) keeps the mesh's outside facing out:
    // glTF defines the winding by the determinant, and modelling tools draw mirrored copies the
    // same way. The renderer culls by the winding on screen, as OpenGL does, so such placements
    // draw a copy of the mesh whose triangles turn the other way (one per mesh).
    std::vector<unsigned> mirrored_mesh(ai->mNumMeshes, kUnset);
    for (const io::NodeMesh& p : placements) {
        if (our_mesh[p.mesh] == kUnset) continue;
        check_instance_finite(scene.meshes[our_mesh[p.mesh]], p.transform, labels[p.mesh], file);
        unsigned drawn = our_mesh[p.mesh];
        if (glm::determinant(glm::mat3(p.transform)) < 0.0f) {
            if (mirrored_mesh[p.mesh] == kUnset) {
                mirrored_mesh[p.mesh] = static_cast<unsigned>(scene.meshes.size());
                scene.meshes.push_back(io::with_winding_reversed(scene.meshes[drawn]));
            }
            drawn = mirrored_mesh[p.mesh];
        }
        const Mesh& mesh = scene.meshes[drawn];
        Instance instance;
        instance.mesh = drawn;
        instance.transform = p.transform;
        instance.name = p.node_name.empty() ? mesh.name : p.node_name;
        scene.instances.push_back(std::move(instance));
    }
    // One line each: they quote names and paths from the file.
    for (const std::string& w : warnings) loaded.warnings.push_back(file + ": " + io::one_line(w));
    // Images no material zraster reads uses (a clearcoat texture) are the model's files too.
    if (!is_obj(path)) io::note_gltf_images(path, policy);
    loaded.files_read = policy.files_read();
    return loaded;
}

}  // namespace zraster
