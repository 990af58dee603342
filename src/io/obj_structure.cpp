// Objects, groups and meshes (see obj_structure.hpp).
#include "io/obj_structure.hpp"

#include <assimp/material.h>

namespace zraster::io::obj {

Structure::Structure() : known_{AI_DEFAULT_MATERIAL_NAME} {}

void Structure::faces_until(std::size_t face) {
    if (face <= faces_) return;
    if (object_ == kNone) create_object("defaultobject");
    MeshPlan& mesh = meshes[mesh_];
    if (!mesh.has_faces) {
        mesh.has_faces = true;
        mesh.face_begin = faces_;
    }
    mesh.face_end = face;
    faces_ = face;
}

void Structure::object(const std::string& name) {
    // The first object of that name, found by a map: a file of hundreds of thousands of `o`
    // lines made a search through every object per line quadratic.
    if (const auto it = first_object_.find(name); it != first_object_.end()) {
        object_ = it->second;  // the current mesh stays
        return;
    }
    create_object(name);
}

void Structure::group(const std::string& name) {
    if (name == group_) return;
    create_object(name);
    group_ = name;
}

void Structure::use_material(const std::string& name) {
    if (material_ == name) return;
    material_ = name;
    known_.insert(name);  // Assimp invents a material for a name no library defined
    if (mesh_ == kNone ||
        (meshes[mesh_].material && *meshes[mesh_].material != name && meshes[mesh_].has_faces))
        create_mesh(name);
    meshes[mesh_].material = name;
}

void Structure::load_library(const std::vector<std::string>& materials) {
    for (const std::string& name : materials) {
        if (known_.insert(name).second && mesh_ != kNone) meshes[mesh_].material = name;
        material_ = name;
    }
}

void Structure::create_object(const std::string& name) {
    objects.push_back(ObjectPlan{name, {}});
    object_ = static_cast<std::uint32_t>(objects.size() - 1);
    first_object_.try_emplace(name, object_);
    create_mesh(name);
    if (material_) meshes[mesh_].material = material_;
}

void Structure::create_mesh(const std::string& name) {
    meshes.push_back(MeshPlan{name, std::nullopt, object_});
    mesh_ = static_cast<std::uint32_t>(meshes.size() - 1);
    if (object_ != kNone) objects[object_].meshes.push_back(mesh_);
}

Structure replay_statements(const std::vector<Chunk>& chunks,
                            const std::vector<std::size_t>& face_prefix,
                            const std::vector<LibraryLoad>& libraries) {
    Structure structure;
    std::size_t library = 0;
    for (std::size_t k = 0; k < chunks.size(); ++k) {
        for (const Event& e : chunks[k].events) {
            structure.faces_until(face_prefix[k] + e.faces_before);
            switch (e.kind) {
                case EventKind::Object:
                    structure.object(e.text);
                    break;
                case EventKind::Group:
                    structure.group(e.text);
                    break;
                case EventKind::Material:
                    structure.use_material(e.text);
                    break;
                case EventKind::Library:
                    structure.load_library(libraries[library++].materials);
                    break;
            }
        }
    }
    structure.faces_until(face_prefix[chunks.size()]);
    return structure;
}

OutputMeshes output_meshes(Structure& structure, const std::vector<Chunk>& chunks,
                           const std::vector<std::size_t>& face_prefix) {
    OutputMeshes output;
    for (const ObjectPlan& object : structure.objects) {
        for (std::uint32_t m : object.meshes) {
            MeshPlan& plan = structure.meshes[m];
            if (!plan.has_faces) continue;
            std::size_t mesh_triangles = 0;
            std::size_t k = chunk_holding(face_prefix, plan.face_begin);
            for (std::size_t f = plan.face_begin; f < plan.face_end; ++f) {
                while (f >= face_prefix[k + 1]) ++k;
                const Face& face = chunks[k].faces[f - face_prefix[k]];
                if (face.kind != kPolygon) {
                    plan.mixed = true;
                    continue;
                }
                mesh_triangles += face.corners - 2u;
                plan.uvs |= (face.attributes & kHasUv) != 0;
                plan.normals |= (face.attributes & kHasNormal) != 0;
            }
            if (mesh_triangles == 0) continue;
            output.triangles += mesh_triangles;
            plan.triangles = mesh_triangles;
            output.meshes.push_back(m);
        }
    }
    return output;
}

}  // namespace zraster::io::obj
