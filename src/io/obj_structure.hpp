// Objects, groups and meshes: how the o, g, usemtl and mtllib statements cut the file's faces
// into meshes, and which of those meshes a scene gets.
//
// Assimp 5.2's OBJ importer keeps a current object, a current mesh and a current material, and
// each statement changes them in its own way (Structure's functions say how). The statements of
// every chunk are replayed here in file order, which gives each mesh a contiguous range of the
// file's faces; the meshes themselves are built afterwards, in parallel (obj_mesh_builder.hpp).
#pragma once
#include "io/obj_chunk_parser.hpp"
#include "io/obj_materials.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

namespace zraster::io::obj {

// No object, mesh or value.
constexpr std::uint32_t kNone = ~0u;

struct ObjectPlan {
    std::string name;
    std::vector<std::uint32_t> meshes;
};

struct MeshPlan {
    std::string name;
    std::optional<std::string> material;
    std::uint32_t object = kNone;  // kNone: created with no current object, never output
    bool has_faces = false;
    std::size_t face_begin = 0, face_end = 0;  // global face numbers, l and p included
    std::size_t triangles = 0;                 // once counted
    bool uvs = false, normals = false;         // some polygon has uv or normal indices
    // Also line or point elements: Assimp's SortByPType then copies the triangles' vertices
    // into a mesh of their own, triangle by triangle, which orders a quad's corners from the
    // one its triangles fan from.
    bool mixed = false;
};

// Assimp's object and mesh bookkeeping, one statement at a time.
class Structure {
  public:
    Structure();

    // Faces before global face number `face` go to the current mesh; faces before any object
    // create "defaultobject".
    void faces_until(std::size_t face);
    // `o`: reuses an object of that name without changing the current mesh, or creates one.
    void object(const std::string& name);
    // `g`: creates an object named by the whole rest of the line when it differs from the
    // active group.
    void group(const std::string& name);
    // `usemtl`: starts a mesh named after the material when the current mesh has faces and
    // another material, otherwise sets the current mesh's material.
    void use_material(const std::string& name);
    // Reading an MTL library: Assimp's MTL reader makes each `newmtl` the current material, and
    // gives each material it creates (a name not seen before) to the current mesh.
    void load_library(const std::vector<std::string>& materials);

    std::vector<ObjectPlan> objects;
    std::vector<MeshPlan> meshes;

  private:
    void create_object(const std::string& name);
    void create_mesh(const std::string& name);

    std::size_t faces_ = 0;
    std::uint32_t object_ = kNone, mesh_ = kNone;
    std::optional<std::string> material_;
    std::string group_;
    std::set<std::string> known_;  // names Assimp has a material for, its default one too
    std::unordered_map<std::string, std::uint32_t> first_object_;  // name -> its first object
};

// The statements of every chunk replayed in file order; `face_prefix[k]` is the number of faces
// before chunk k (one more entry than chunks), `libraries` one per mtllib statement.
Structure replay_statements(const std::vector<Chunk>& chunks,
                            const std::vector<std::size_t>& face_prefix,
                            const std::vector<LibraryLoad>& libraries);

// The meshes Assimp outputs, in order: objects in order, each object's meshes in order, those
// with polygons (a mesh of only lines or points is dropped). Counts their triangles and sets
// their uvs, normals and mixed flags.
struct OutputMeshes {
    std::vector<std::uint32_t> meshes;  // into Structure::meshes
    std::size_t triangles = 0;
};
OutputMeshes output_meshes(Structure& structure, const std::vector<Chunk>& chunks,
                           const std::vector<std::size_t>& face_prefix);

}  // namespace zraster::io::obj
