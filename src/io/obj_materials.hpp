// Materials: the MTL libraries an OBJ file names, and the scene's materials made from them.
//
// The MTL files themselves are read by Assimp, so that a material is exactly what the Assimp path
// makes of it: on first use of a material, Assimp reads a small generated OBJ that repeats the
// file's mtllib (resolved) and usemtl statements in order, and its material is converted as the
// Assimp path converts it. What is decided here is what Assimp's importer does not tell: which
// file each mtllib statement reads (as written, relative to the OBJ's directory, else
// "<obj name>.mtl"), the names it defines (which change the current material, see
// obj_structure.hpp), and the warnings the Assimp path gives for missing libraries and undefined
// materials (as scan_obj_material_libraries and load_scene's MaterialTable give them).
#pragma once
#include <zraster/scene.hpp>

#include "io/mtl_dissolve.hpp"
#include "io/obj_chunk_parser.hpp"
#include "io/obj_parser.hpp"
#include "io/reference_policy.hpp"
#include "io/texture_loader.hpp"

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

struct aiMaterial;
struct aiScene;
namespace Assimp {
class Importer;
}

namespace zraster::io::obj {

// What Assimp reads for one mtllib statement: the library as named (relative to the OBJ's
// directory), else "<obj name>.mtl", else nothing; and the materials it defines, in order.
struct LibraryLoad {
    std::string name;
    std::optional<std::filesystem::path> file;
    bool substitute = false;             // file is "<obj name>.mtl"
    std::string warning;                 // when file is not the library named
    std::vector<std::string> materials;  // its names; empty where an earlier entry read the file
};

// The o, g, usemtl and mtllib statements of the whole file, in order, and what each mtllib
// statement reads.
struct Statements {
    std::vector<const Event*> events;    // into the chunks
    std::vector<LibraryLoad> libraries;  // one per mtllib statement
    ReferencePolicy policy;              // which library and texture files may be read
    MtlDissolve dissolve;                // `d` values a later `Tr` hid from Assimp
    std::vector<std::string> notices;    // library statements ignored (`decal`)
};

// Collects the statements of `chunks` (whose first_line is set) and resolves and scans the
// libraries, each file once (for their `newmtl` names and MTL `d` over `Tr`). Returns the mtllib
// line when a library's `newmtl` names could be read differently by Assimp's MTL reader and the
// Assimp path's library check.
std::optional<ObjFallback> read_statements(const std::filesystem::path& obj_path,
                                           const std::vector<Chunk>& chunks,
                                           const ReferencePolicy& policy,
                                           const LoadOptions& options, Statements& out);

// The scene's materials, made on first use of each usemtl name. The constructor adds the
// warnings for missing libraries.
class Materials {
  public:
    Materials(const std::filesystem::path& obj_path, const Statements& statements,
              const LoadOptions& options, Scene& scene, std::vector<std::string>& warnings);
    ~Materials();
    Materials(const Materials&) = delete;
    Materials& operator=(const Materials&) = delete;

    // Our index for a usemtl name (nullopt: none), converting it on first use. Returns
    // nullopt when Assimp cannot read the material libraries (its error is then the file's).
    std::optional<std::uint32_t> index_of(const std::optional<std::string>& name);

  private:
    const aiMaterial* assimp_material(const std::string& name);

    std::filesystem::path path_;
    const std::vector<const Event*>& events_;
    const std::vector<LibraryLoad>& libraries_;
    const MtlDissolve& dissolve_;
    ReferencePolicy policy_;
    LoadOptions options_;  // the texture budget
    Scene& scene_;
    std::vector<std::string>& warnings_;
    std::set<std::string> defined_;
    bool missing_library_ = false;
    std::map<std::string, std::uint32_t> map_;
    std::unique_ptr<Assimp::Importer> importer_;
    const aiScene* ai_ = nullptr;
    std::map<std::string, const aiMaterial*> by_name_;  // ai_'s materials
    std::optional<TextureLoader> textures_;
    std::vector<std::string> refusals_;  // files the confined Assimp was refused
};

}  // namespace zraster::io::obj
