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

#include "io/assimp_material.hpp"
#include "io/obj_chunk_parser.hpp"
#include "io/obj_numbers.hpp"
#include "io/obj_scan.hpp"
#include "io/text_util.hpp"
#include "io/texture_loader.hpp"
#include "io/weld_vertices.hpp"

#include <assimp/material.h>
#include <assimp/scene.h>
#include <assimp/vector3.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <system_error>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace zraster::io {

namespace {

// The file, its chunks and its numbers (obj_scan.hpp, obj_chunk_parser.hpp, obj_numbers.hpp).
using obj::Chunk;
using obj::Event;
using obj::EventKind;
using obj::Face;
using obj::FileBytes;
using obj::has_control;
using obj::is_blank;
using obj::kHasNormal;
using obj::kHasUv;
using obj::kPolygon;
using obj::resolve_index;

constexpr std::uint32_t kNone = ~0u;

// ------------------------------------------------------------------------------------------
// Stage 3: Assimp's object and mesh bookkeeping.

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

class Structure {
  public:
    // Faces before global face number `face` go to the current mesh.
    void faces_until(std::size_t face) {
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

    void object(const std::string& name) {
        for (std::uint32_t i = 0; i < objects.size(); ++i) {
            if (objects[i].name == name) {
                object_ = i;  // the current mesh stays
                return;
            }
        }
        create_object(name);
    }

    void group(const std::string& name) {
        if (name == group_) return;
        create_object(name);
        group_ = name;
    }

    void use_material(const std::string& name) {
        if (material_ == name) return;
        material_ = name;
        known_.insert(name);  // Assimp invents a material for a name no library defined
        if (mesh_ == kNone ||
            (meshes[mesh_].material && *meshes[mesh_].material != name && meshes[mesh_].has_faces))
            create_mesh(name);
        meshes[mesh_].material = name;
    }

    std::vector<ObjectPlan> objects;
    std::vector<MeshPlan> meshes;

    // Assimp's MTL reader makes each `newmtl` the current material, and gives each material it
    // creates (a name not seen before) to the current mesh.
    void load_library(const std::vector<std::string>& materials) {
        for (const std::string& name : materials) {
            if (known_.insert(name).second && mesh_ != kNone) meshes[mesh_].material = name;
            material_ = name;
        }
    }

  private:
    void create_object(const std::string& name) {
        objects.push_back(ObjectPlan{name, {}});
        object_ = static_cast<std::uint32_t>(objects.size() - 1);
        create_mesh(name);
        if (material_) meshes[mesh_].material = material_;
    }

    void create_mesh(const std::string& name) {
        meshes.push_back(MeshPlan{name, std::nullopt, object_});
        mesh_ = static_cast<std::uint32_t>(meshes.size() - 1);
        if (object_ != kNone) objects[object_].meshes.push_back(mesh_);
    }

    std::size_t faces_ = 0;
    std::uint32_t object_ = kNone, mesh_ = kNone;
    std::optional<std::string> material_;
    std::string group_;
    std::set<std::string> known_{AI_DEFAULT_MATERIAL_NAME};
};

// ------------------------------------------------------------------------------------------
// Stage 4: meshes.

// For each value (N floats), the index of the first value with the same bits (-0 == +0, as
// weld_identical_vertices compares them). Empty when every value is the first of its kind.
template <int N>
std::vector<std::uint32_t> first_equal_values(const float* values, std::size_t count) {
    const std::size_t capacity = std::bit_ceil(std::max<std::size_t>(16, count * 2));
    std::vector<std::uint32_t> table(capacity, kNone);
    std::vector<std::uint32_t> first(count);
    bool all_first = true;
    auto key = [&](std::size_t i, int k) {
        return std::bit_cast<std::uint32_t>(values[i * N + k] + 0.0f);
    };
    for (std::size_t i = 0; i < count; ++i) {
        std::uint64_t h = 0x9E3779B97F4A7C15ull;
        for (int k = 0; k < N; ++k) {
            h ^= key(i, k);
            h *= 0xBF58476D1CE4E5B9ull;
            h ^= h >> 29;
        }
        std::size_t slot = static_cast<std::size_t>(h) & (capacity - 1);
        while (true) {
            const std::uint32_t t = table[slot];
            if (t == kNone) {
                table[slot] = static_cast<std::uint32_t>(i);
                first[i] = static_cast<std::uint32_t>(i);
                break;
            }
            bool equal = true;
            for (int k = 0; k < N; ++k) equal &= key(t, k) == key(i, k);
            if (equal) {
                first[i] = t;
                all_first = false;
                break;
            }
            slot = (slot + 1) & (capacity - 1);
        }
    }
    if (all_first) first.clear();
    return first;
}

// Assimp's triangulation of a quad: a fan from its concave corner, if it has one (the first
// corner whose two angles against the diagonal add up to more than pi), else from corner 0.
// Computed with Assimp's own vector operations, so that it decides exactly as Assimp does.
unsigned quad_fan_corner(const glm::vec3* corner[4]) {
    for (unsigned i = 0; i < 4; ++i) {
        auto ai = [&](unsigned k) {
            const glm::vec3& p = *corner[k % 4];
            return aiVector3D(p.x, p.y, p.z);
        };
        const aiVector3D v = ai(i);
        aiVector3D left = ai(i + 3) - v;
        aiVector3D diagonal = ai(i + 2) - v;
        aiVector3D right = ai(i + 1) - v;
        left.Normalize();
        diagonal.Normalize();
        right.Normalize();
        const float angle = std::acos(left * diagonal) + std::acos(right * diagonal);
        if (angle > AI_MATH_PI_F) return i;
    }
    return 0;
}

struct Attributes {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec2> uvs;
    std::vector<glm::vec3> normals;
    std::vector<std::uint32_t> first_position, first_uv, first_normal;  // empty: identity
};

struct MeshOutcome {
    Mesh mesh;
    // A non-finite position (convert_mesh's error): the global position and the mesh vertex.
    std::optional<std::pair<std::uint32_t, std::uint32_t>> non_finite;
};

// Welding: for each position, its first vertex in the mesh inline, and the others (seams,
// flat shading: the same position with other uvs or normals) in a list through `Link`s.
struct Slot {
    std::uint32_t stamp = 0;  // which mesh wrote it
    std::uint32_t uv = 0, normal = 0;
    std::uint32_t vertex = 0;
    std::uint32_t next = kNone;  // more vertices at this position
};

struct Link {
    std::uint32_t uv, normal, vertex, next;
};

class MeshBuilder {
  public:
    MeshBuilder(const std::vector<Chunk>& chunks, const std::vector<std::size_t>& face_prefix,
                const Attributes& attributes)
        : chunks_(chunks),
          face_prefix_(face_prefix),
          a_(attributes),
          slots_([&] { return std::vector<Slot>(attributes.positions.size()); }) {}

    MeshOutcome build(const MeshPlan& plan, std::uint32_t stamp) const {
        MeshOutcome out;
        Mesh& mesh = out.mesh;
        mesh.name = plan.name;
        std::vector<Slot>& slots = slots_.local();
        std::vector<Link> links;
        mesh.indices.reserve(plan.triangles * 3);
        const std::size_t vertices = std::min(plan.triangles * 3, a_.positions.size());
        mesh.positions.reserve(vertices);
        if (plan.uvs) mesh.uvs.reserve(vertices);
        if (plan.normals) mesh.normals.reserve(vertices);
        // Corners without uv or normal indices in a mesh that has them: Assimp leaves those
        // zero, which FlipUVs makes (0, 1), and a zero normal is replaced by a computed one.
        constexpr std::uint32_t kAbsent = kNone - 1;
        bool absent = false;

        std::size_t chunk = static_cast<std::size_t>(
            std::upper_bound(face_prefix_.begin(), face_prefix_.end(), plan.face_begin) -
            face_prefix_.begin() - 1);
        for (std::size_t f = plan.face_begin; f < plan.face_end; ++f) {
            while (f >= face_prefix_[chunk + 1]) ++chunk;
            const Chunk& c = chunks_[chunk];
            const Face& face = c.faces[f - face_prefix_[chunk]];
            if (face.kind != kPolygon) continue;
            const bool has_uv = face.attributes & kHasUv, has_normal = face.attributes & kHasNormal;
            absent |= (plan.uvs && !has_uv) || (plan.normals && !has_normal);
            // Assimp's split of a quad: a fan from this corner.
            unsigned fan = 0;
            if (face.corners == 4) {
                const glm::vec3* corner_positions[4];
                for (unsigned k = 0; k < 4; ++k)
                    corner_positions[k] =
                        &a_.positions[static_cast<std::uint32_t>(c.corner_v[face.first + k])];
                fan = quad_fan_corner(corner_positions);
            }
            const unsigned first_corner = plan.mixed ? fan : 0;  // see MeshPlan::mixed
            std::uint32_t ids[4];
            for (unsigned j = 0; j < face.corners; ++j) {
                const unsigned k = (first_corner + j) % face.corners;
                const std::size_t corner = face.first + k;
                const auto v = static_cast<std::uint32_t>(c.corner_v[corner]);
                const auto t = has_uv ? static_cast<std::uint32_t>(c.corner_t[corner]) : 0u;
                const auto n = has_normal ? static_cast<std::uint32_t>(c.corner_n[corner]) : 0u;
                const std::uint32_t kv = a_.first_position.empty() ? v : a_.first_position[v];
                const std::uint32_t kt = !plan.uvs             ? 0u
                                         : !has_uv             ? kAbsent
                                         : a_.first_uv.empty() ? t
                                                               : a_.first_uv[t];
                const std::uint32_t kn = !plan.normals             ? 0u
                                         : !has_normal             ? kAbsent
                                         : a_.first_normal.empty() ? n
                                                                   : a_.first_normal[n];
                Slot& slot = slots[kv];
                std::uint32_t id = 0;
                bool created = false;
                if (slot.stamp != stamp) {
                    id = static_cast<std::uint32_t>(mesh.positions.size());
                    slot = Slot{stamp, kt, kn, id, kNone};
                    created = true;
                } else if (slot.uv == kt && slot.normal == kn) {
                    id = slot.vertex;
                } else {
                    std::uint32_t l = slot.next;
                    while (l != kNone && (links[l].uv != kt || links[l].normal != kn))
                        l = links[l].next;
                    if (l != kNone) {
                        id = links[l].vertex;
                    } else {
                        id = static_cast<std::uint32_t>(mesh.positions.size());
                        links.push_back(Link{kt, kn, id, slot.next});
                        slot.next = static_cast<std::uint32_t>(links.size() - 1);
                        created = true;
                    }
                }
                if (created) {
                    const glm::vec3& p = a_.positions[v];
                    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
                        out.non_finite = {v, id};
                        return out;
                    }
                    mesh.positions.push_back(p);
                    if (plan.uvs) mesh.uvs.push_back(has_uv ? a_.uvs[t] : glm::vec2(0.0f, 1.0f));
                    if (plan.normals)
                        mesh.normals.push_back(has_normal ? a_.normals[n]
                                                          : glm::vec3(std::nanf("")));
                }
                ids[k] = id;
            }
            if (face.corners == 3) {
                mesh.indices.push_back(ids[0]);
                mesh.indices.push_back(ids[1]);
                mesh.indices.push_back(ids[2]);
            } else {
                for (unsigned k : {fan, fan + 1, fan + 2, fan, fan + 2, fan + 3})
                    mesh.indices.push_back(ids[k % 4]);
            }
        }

        // As convert_mesh: unusable normals are replaced by normals computed over shared
        // positions (the same whether computed on Assimp's per-corner vertices or these).
        // Vertices that become equal are then welded, as welding after that replacement does.
        // (Texture coordinates are always finite here: see uv().)
        bool reweld = absent;
        if (std::any_of(mesh.normals.begin(), mesh.normals.end(),
                        [](const glm::vec3& n) { return std::isnan(n.x); })) {
            const std::vector<glm::vec3> computed = normals_over_shared_positions(mesh);
            for (std::size_t i = 0; i < mesh.normals.size(); ++i)
                if (std::isnan(mesh.normals[i].x)) mesh.normals[i] = computed[i];
            reweld = true;
        }
        if (reweld) weld_identical_vertices(mesh);
        if (mesh.normals.empty()) mesh.normals = normals_over_shared_positions(mesh);
        update_bounds(mesh);
        return out;
    }

  private:
    const std::vector<Chunk>& chunks_;
    const std::vector<std::size_t>& face_prefix_;
    const Attributes& a_;
    mutable tbb::enumerable_thread_specific<std::vector<Slot>> slots_;
};

// ------------------------------------------------------------------------------------------
// Stage 5: materials, as load_scene's MaterialTable and scan_obj_material_libraries do them.

// `line` is the rest of a line after `keyword` and blanks, when the trimmed line starts with it.
bool directive(const std::string& line, std::string_view keyword, std::string& argument) {
    const std::string_view text = trim(line);
    if (!text.starts_with(keyword) || text.size() <= keyword.size()) return false;
    if (text[keyword.size()] != ' ' && text[keyword.size()] != '\t') return false;
    argument = std::string(trim(text.substr(keyword.size())));
    return !argument.empty();
}

bool is_file(const std::filesystem::path& p) {
    std::error_code ec;
    return std::filesystem::is_regular_file(p, ec);
}

// What Assimp reads for one mtllib statement: the library as named (relative to the OBJ's
// directory), else "<obj name>.mtl", else nothing; and the materials it defines, in order.
struct LibraryLoad {
    std::string name;
    std::optional<std::filesystem::path> file;
    bool substitute = false;  // file is "<obj name>.mtl"
    std::vector<std::string> materials;
};

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

class Materials {
  public:
    Materials(const std::filesystem::path& obj_path, const std::vector<const Event*>& events,
              const std::vector<LibraryLoad>& libraries, Scene& scene,
              std::vector<std::string>& warnings)
        : path_(obj_path),
          events_(events),
          libraries_(libraries),
          scene_(scene),
          warnings_(warnings) {
        // As scan_obj_material_libraries: each library name once.
        std::filesystem::path substitute = obj_path;
        substitute.replace_extension(".mtl");
        std::set<std::string> seen;
        for (const LibraryLoad& l : libraries_) {
            if (!seen.insert(l.name).second) continue;
            if (l.file && !l.substitute) {
                defined_.insert(l.materials.begin(), l.materials.end());
            } else if (l.file) {
                warnings_.push_back("material library '" + l.name + "' not found, using '" +
                                    substitute.filename().string() + "'");
                missing_library_ = true;
                defined_.insert(l.materials.begin(), l.materials.end());
            } else {
                warnings_.push_back("material library '" + l.name +
                                    "' not found, using the default material");
                missing_library_ = true;
            }
        }
    }

    // Our index for a usemtl name (nullopt: none), converting it on first use. Returns
    // nullopt when Assimp cannot read the material libraries (its error is then the file's).
    std::optional<std::uint32_t> index_of(const std::optional<std::string>& name) {
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
                Material material = convert_material(*source);
                if (auto reference = base_color_texture_reference(*source))
                    material.base_color_texture = textures_->load(*reference);
                index = static_cast<std::uint32_t>(scene_.materials.size());
                scene_.materials.push_back(std::move(material));
            }
        }
        map_[*name] = index;
        return index;
    }

  private:
    // The material as Assimp's OBJ importer makes it: it reads the libraries from a generated
    // OBJ that repeats the file's mtllib (resolved) and usemtl statements in order.
    const aiMaterial* assimp_material(const std::string& name) {
        if (!importer_) {
            std::size_t library = 0;
            std::string text;
            for (const Event* e : events_) {
                if (e->kind == EventKind::Library) {
                    const LibraryLoad& l = libraries_[library++];
                    if (l.file)
                        text += "mtllib " + std::filesystem::absolute(*l.file).string() + "\n";
                } else if (e->kind == EventKind::Material) {
                    text += "usemtl " + e->text + "\n";
                }
            }
            text += "v 0 0 0\nf 1 1 1\n";
            importer_ = std::make_unique<Assimp::Importer>();
            try {
                ai_ = importer_->ReadFileFromMemory(text.data(), text.size(), 0, "obj");
            } catch (const std::exception&) {
                ai_ = nullptr;
            }
            if (ai_ != nullptr) textures_.emplace(*ai_, path_, warnings_);
        }
        if (ai_ == nullptr) return nullptr;
        for (unsigned i = 0; i < ai_->mNumMaterials; ++i)
            if (ai_->mMaterials[i] != nullptr && material_name(*ai_->mMaterials[i]) == name)
                return ai_->mMaterials[i];
        return nullptr;
    }

    std::filesystem::path path_;
    const std::vector<const Event*>& events_;
    const std::vector<LibraryLoad>& libraries_;
    Scene& scene_;
    std::vector<std::string>& warnings_;
    std::set<std::string> defined_;
    bool missing_library_ = false;
    std::map<std::string, std::uint32_t> map_;
    std::unique_ptr<Assimp::Importer> importer_;
    const aiScene* ai_ = nullptr;
    std::optional<TextureLoader> textures_;
};

}  // namespace

// ------------------------------------------------------------------------------------------

std::variant<Scene, ObjFallback> read_obj(const std::filesystem::path& path,
                                          const LoadOptions& options) {
    const std::string file = path.string();
    const FileBytes bytes(path);
    if (bytes.size() == 0) throw InputError(file, "empty file");
    if (bytes.size() < 16) return ObjFallback{0, "Assimp refuses OBJ files under 16 bytes"};

    // Stage 1.
    std::vector<Chunk> chunks = obj::parse_chunks(bytes.data(), bytes.size());

    const std::size_t n = chunks.size();
    std::vector<std::size_t> v_prefix(n + 1), t_prefix(n + 1), n_prefix(n + 1), face_prefix(n + 1);
    for (std::size_t k = 0; k < n; ++k) {
        Chunk& c = chunks[k];
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
    if (total_v >= kNone || total_t >= kNone || total_n >= kNone)
        return ObjFallback{0, "more than 2^32 - 1 vertices"};

    // Stage 2: resolve indices in place, gather the attributes.
    Attributes attributes;
    attributes.positions.resize(total_v);
    attributes.uvs.resize(total_t);
    attributes.normals.resize(total_n);
    struct Resolution {
        std::optional<std::pair<std::uint32_t, std::string>> error, fallback;  // line, what
    };
    std::vector<Resolution> resolutions(n);
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t k) {
        Chunk& c = chunks[k];
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
        for (const Face& face : c.faces) {
            for (std::size_t corner = face.first; corner < face.first + face.corners; ++corner) {
                const std::int64_t v = resolve_index(c.corner_v[corner], v_prefix[k], total_v);
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
                if (face.attributes & kHasUv) {
                    const std::int64_t t = resolve_index(c.corner_t[corner], t_prefix[k], total_t);
                    if (t < 0 && !r.fallback)
                        r.fallback = {face.line, "texture coordinate index out of range"};
                    c.corner_t[corner] = static_cast<std::int32_t>(t);
                }
                if (face.attributes & kHasNormal) {
                    const std::int64_t m = resolve_index(c.corner_n[corner], n_prefix[k], total_n);
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
    std::vector<const Event*> events;
    std::vector<LibraryLoad> libraries;
    {
        const std::filesystem::path dir = path.parent_path();
        std::filesystem::path substitute = path;
        substitute.replace_extension(".mtl");
        std::map<std::filesystem::path, std::vector<std::string>> read;
        for (std::size_t k = 0; k < n; ++k) {
            for (const Event& e : chunks[k].events) {
                events.push_back(&e);
                if (e.kind != EventKind::Library) continue;
                LibraryLoad l{e.text, std::nullopt, false, {}};
                if (is_file(dir / e.text)) {
                    l.file = dir / e.text;
                } else if (is_file(substitute)) {
                    l.file = substitute;
                    l.substitute = true;
                }
                if (l.file) {
                    auto it = read.find(*l.file);
                    if (it == read.end()) {
                        std::optional<std::vector<std::string>> names = library_materials(*l.file);
                        if (!names)
                            return ObjFallback{chunks[k].first_line + e.line + 1,
                                               "material library " + l.file->string() +
                                                   " that Assimp may read differently"};
                        it = read.emplace(*l.file, std::move(*names)).first;
                    }
                    l.materials = it->second;
                }
                libraries.push_back(std::move(l));
            }
        }
    }
    Structure structure;
    {
        std::size_t library = 0;
        for (std::size_t k = 0; k < n; ++k) {
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
    }
    structure.faces_until(face_prefix[n]);

    // The meshes Assimp outputs, in order: objects in order, each object's meshes in order,
    // those with polygons (a mesh of only lines or points is dropped).
    std::vector<std::uint32_t> output;
    std::size_t triangles = 0;
    for (const ObjectPlan& object : structure.objects) {
        for (std::uint32_t m : object.meshes) {
            const MeshPlan& plan = structure.meshes[m];
            if (!plan.has_faces) continue;
            std::size_t mesh_triangles = 0;
            std::size_t k = static_cast<std::size_t>(
                std::upper_bound(face_prefix.begin(), face_prefix.end(), plan.face_begin) -
                face_prefix.begin() - 1);
            for (std::size_t f = plan.face_begin; f < plan.face_end; ++f) {
                while (f >= face_prefix[k + 1]) ++k;
                const Face& face = chunks[k].faces[f - face_prefix[k]];
                if (face.kind != kPolygon) {
                    structure.meshes[m].mixed = true;
                    continue;
                }
                mesh_triangles += face.corners - 2u;
                structure.meshes[m].uvs |= (face.attributes & kHasUv) != 0;
                structure.meshes[m].normals |= (face.attributes & kHasNormal) != 0;
            }
            if (mesh_triangles == 0) continue;
            triangles += mesh_triangles;
            structure.meshes[m].triangles = mesh_triangles;
            output.push_back(m);
        }
    }
    if (triangles == 0) throw InputError(file, "no triangles");
    if (triangles > options.max_triangles)
        throw InputError(file, "too many triangles (" + std::to_string(triangles) + ", limit " +
                                   std::to_string(options.max_triangles) + ")");

    // Stage 4.
    bool uses_uvs = false, uses_normals = false;
    for (const Chunk& c : chunks) {
        for (const Face& face : c.faces) {
            uses_uvs |= (face.attributes & kHasUv) != 0;
            uses_normals |= (face.attributes & kHasNormal) != 0;
        }
    }
    tbb::parallel_invoke(
        [&] {
            attributes.first_position =
                first_equal_values<3>(&attributes.positions.data()->x, total_v);
        },
        [&] {
            if (uses_uvs)
                attributes.first_uv = first_equal_values<2>(&attributes.uvs.data()->x, total_t);
        },
        [&] {
            if (uses_normals)
                attributes.first_normal =
                    first_equal_values<3>(&attributes.normals.data()->x, total_n);
        });

    const MeshBuilder builder(chunks, face_prefix, attributes);
    std::vector<MeshOutcome> built(output.size());
    tbb::parallel_for(std::size_t{0}, output.size(), [&](std::size_t i) {
        built[i] = builder.build(structure.meshes[output[i]], static_cast<std::uint32_t>(i + 1));
    });
    for (std::size_t i = 0; i < built.size(); ++i) {
        if (!built[i].non_finite) continue;
        // The first mesh with one, as convert_mesh reports it, and the line of its `v`.
        const auto [position, vertex] = *built[i].non_finite;
        const std::size_t k = static_cast<std::size_t>(
            std::upper_bound(v_prefix.begin(), v_prefix.end(), position) - v_prefix.begin() - 1);
        std::size_t line = 0;
        for (const auto& [index, local_line] : chunks[k].non_finite_positions)
            if (v_prefix[k] + index == position) line = chunks[k].first_line + local_line + 1;
        const std::string& name = structure.meshes[output[i]].name;
        throw InputError(file, "line " + std::to_string(line) +
                                   ": non-finite vertex coordinates (mesh " +
                                   (name.empty() ? "#" + std::to_string(i) : name) + ", vertex " +
                                   std::to_string(vertex) + ")");
    }

    // Stage 5.
    Scene scene;
    scene.source = file;
    std::vector<std::string> warnings;
    Materials materials(path, events, libraries, scene, warnings);
    for (std::size_t i = 0; i < built.size(); ++i) {
        const MeshPlan& plan = structure.meshes[output[i]];
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
