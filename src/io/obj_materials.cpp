// Materials of an OBJ file (see obj_materials.hpp).
#include "io/obj_materials.hpp"

#include "io/confined_io_system.hpp"
#include "io/mtl_numbers_check.hpp"
#include "io/obj_material_libraries.hpp"

#include "io/assimp_material.hpp"
#include "io/obj_scan.hpp"
#include "io/text_util.hpp"

#include <assimp/material.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <fstream>
#include <system_error>

namespace zraster::io::obj {

namespace {

// The `newmtl` names of an MTL file as both Assimp's MTL reader and the Assimp path's library
// check take them. nullopt where they could differ ("Newmtl", an indented newmtl, a lone CR),
// or where Assimp would apply a statement before the first newmtl to the current material.
std::optional<std::vector<std::string>> library_materials(const std::filesystem::path& mtl) {
    std::ifstream in(mtl, std::ios::binary);
    std::string line, name;
    std::vector<std::string> names;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (has_control(line.data(), line.data() + line.size())) return std::nullopt;
        if (line.empty() || line[0] == '#') continue;
        const bool checked = directive(line, "newmtl", name);
        const bool read = line.size() >= 2 && (line[0] == 'n' || line[0] == 'N') && line[1] == 'e';
        if (checked != read) return std::nullopt;
        if (read)
            names.push_back(name);
        else if (names.empty() && !is_blank(line[0]))
            return std::nullopt;
    }
    return names;
}

}  // namespace

std::optional<ObjFallback> read_statements(const std::filesystem::path& obj_path,
                                           const std::vector<Chunk>& chunks,
                                           const ReferencePolicy& policy,
                                           const LoadOptions& options, Statements& out) {
    out.policy = policy;
    std::set<std::filesystem::path> read;
    std::size_t materials = 0;  // newmtl statements of the libraries read
    for (const Chunk& chunk : chunks) {
        for (const Event& e : chunk.events) {
            out.events.push_back(&e);
            if (e.kind != EventKind::Library) continue;
            const MaterialLibraryChoice choice = resolve_material_library(obj_path, e.text, policy);
            LibraryLoad l{e.text, choice.file, choice.substitute, choice.warning, {}};
            // A library named again keeps no copy of its names: the first entry holds them (a
            // file may name one library thousands of times).
            if (l.file && read.insert(*l.file).second) {
                check_material_library(obj_path, *l.file, options);
                std::optional<std::vector<std::string>> names = library_materials(*l.file);
                if (!names)
                    return ObjFallback{chunk.first_line + e.line + 1,
                                       "material library " + l.file->string() +
                                           " that Assimp may read differently"};
                l.materials = std::move(*names);
                materials += l.materials.size();
                check_material_count(obj_path, materials, options);
                check_mtl_numbers(obj_path, *l.file, &out.notices);
                note_named_textures(*l.file, policy);
                out.dissolve.read(*l.file);
            }
            out.libraries.push_back(std::move(l));
        }
    }
    return std::nullopt;
}

Materials::Materials(const std::filesystem::path& obj_path, const Statements& statements,
                     const LoadOptions& options, Scene& scene, std::vector<std::string>& warnings)
    : path_(obj_path),
      events_(statements.events),
      libraries_(statements.libraries),
      dissolve_(statements.dissolve),
      policy_(statements.policy),
      options_(options),
      scene_(scene),
      warnings_(warnings) {
    warnings_.insert(warnings_.end(), statements.notices.begin(), statements.notices.end());
    // As scan_obj_material_libraries: each library name once.
    std::set<std::string> seen;
    for (const LibraryLoad& l : libraries_) {
        if (!seen.insert(l.name).second) continue;
        if (!l.warning.empty()) {
            warnings_.push_back(l.warning);
            missing_library_ = true;
        }
        if (l.file) defined_.insert(l.materials.begin(), l.materials.end());
    }
}

Materials::~Materials() = default;

std::optional<std::uint32_t> Materials::index_of(const std::optional<std::string>& name) {
    if (!name) return 0;
    if (auto it = map_.find(*name); it != map_.end()) return it->second;
    std::uint32_t index = 0;
    if (*name == AI_DEFAULT_MATERIAL_NAME || *name == "%%%DEFAULT") {
        index = 0;  // Assimp's placeholders
    } else if (!defined_.contains(*name)) {
        if (!missing_library_)
            warnings_.push_back("material '" + *name +
                                "' is not defined, using the default material");
    } else {
        const aiMaterial* source = assimp_material(*name);
        if (source == nullptr) return std::nullopt;
        if (!is_placeholder_material(*source)) {
            Material material = convert_material(*source, Material{}.name, warnings_);
            dissolve_.apply(material, warnings_);
            textures_->attach_textures(*source, material);
            index = static_cast<std::uint32_t>(scene_.materials.size());
            scene_.materials.push_back(std::move(material));
        }
    }
    map_[*name] = index;
    return index;
}

// The material as Assimp's OBJ importer makes it: it reads the libraries from a generated OBJ
// that repeats the file's mtllib (resolved, each library once) and usemtl statements in order.
const aiMaterial* Materials::assimp_material(const std::string& name) {
    if (!importer_) {
        std::size_t library = 0;
        std::string text;
        // Each library once: a file may name the same one thousands of times, and Assimp would
        // read (and keep the materials of) every repetition.
        std::set<std::string> named;
        // Each usemtl name once between two libraries: Assimp looks a name up among the
        // materials it has in a linear search, so N names used once each took time quadratic
        // in N (20,000: 12 s). A name used again reads the same material.
        std::set<std::string> used;
        for (const Event* e : events_) {
            if (e->kind == EventKind::Library) {
                const LibraryLoad& l = libraries_[library++];
                if (!l.file) continue;
                const std::string file = std::filesystem::absolute(*l.file).string();
                if (named.insert(file).second) {
                    text += "mtllib " + file + "\n";
                    used.clear();
                }
            } else if (e->kind == EventKind::Material && used.insert(e->text).second) {
                text += "usemtl " + e->text + "\n";
            }
        }
        text += "v 0 0 0\nf 1 1 1\n";
        importer_ = std::make_unique<Assimp::Importer>();
        auto* io_system = new ConfinedIOSystem(policy_, refusals_);
        io_system->rewrite_material_libraries("");  // the OBJ is in memory
        importer_->SetIOHandler(io_system);         // owned by importer_
        try {
            ai_ = importer_->ReadFileFromMemory(text.data(), text.size(), 0, "obj");
        } catch (const std::exception&) {
            ai_ = nullptr;
        }
        if (ai_ != nullptr) {
            textures_.emplace(*ai_, path_, policy_, options_, warnings_);
            // By name, the first of a name (a linear search per name was quadratic too).
            for (unsigned i = 0; i < ai_->mNumMaterials; ++i)
                if (ai_->mMaterials[i] != nullptr)
                    by_name_.emplace(material_name(*ai_->mMaterials[i]), ai_->mMaterials[i]);
        }
    }
    if (ai_ == nullptr) return nullptr;
    const auto it = by_name_.find(name);
    return it == by_name_.end() ? nullptr : it->second;
}

}  // namespace zraster::io::obj
