// See gltf_schema_check.hpp.
#include "io/gltf_schema_check.hpp"

#include "io/gltf_texture_transform.hpp"

#include "io/gltf_document.hpp"

#include <zraster/error.hpp>

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace zraster::io {
namespace {

using nlohmann::json;

const json& array_of(const json& object, const char* key) {
    static const json empty = json::array();
    const auto it = object.find(key);
    return it != object.end() && it->is_array() ? *it : empty;
}

std::uint64_t element_bytes(const json& accessor) {
    const auto type = accessor.find("type");
    const auto component = accessor.find("componentType");
    if (type == accessor.end() || !type->is_string() || component == accessor.end() ||
        !component->is_number_unsigned())
        return 0;
    const std::string t = type->get<std::string>();
    const std::uint64_t n = gltf_type_components(t);
    const std::uint64_t c = component->get<std::uint64_t>();
    const std::uint64_t bytes = c == 5120 || c == 5121 ? 1 : c == 5122 || c == 5123 ? 2 : 4;
    return n * bytes;
}

// The types an attribute may have; empty for one the specification leaves open.
std::string allowed_types(const std::string& attribute) {
    if (attribute == "POSITION" || attribute == "NORMAL") return "VEC3";
    if (attribute.starts_with("TEXCOORD_")) return "VEC2";
    if (attribute.starts_with("COLOR_")) return "VEC3 or VEC4";
    return "";
}

// Extensions that change only materials and lights, which zraster's shading approximates: a
// file requiring them still draws its geometry right.
bool shading_only(const std::string& extension) {
    return extension.starts_with("KHR_materials_") || extension == "KHR_texture_transform" ||
           extension == "KHR_lights_punctual";
}

class SchemaChecker {
  public:
    SchemaChecker(const std::filesystem::path& path, const json& document)
        : path_(path), document_(document) {}

    void run() {
        extensions();
        strides();
        attributes();
        zero_accessors();
        nodes();
        scene();
        cameras();
        material_references();
    }

  private:
    [[noreturn]] void refuse(const std::string& what) const {
        throw InputError(path_.string(), "malformed glTF file: glTF " + what);
    }

    void extensions() const {
        for (const json& e : array_of(document_, "extensionsRequired"))
            if (e.is_string() && !shading_only(e.get<std::string>()))
                throw InputError(path_.string(),
                                 "the file requires the glTF extension " + e.get<std::string>() +
                                     " (extensionsRequired), which zraster does not read");
    }

    void strides() const {
        const json& views = array_of(document_, "bufferViews");
        for (std::size_t v = 0; v < views.size(); ++v) {
            if (!views[v].is_object()) continue;
            const auto stride = views[v].find("byteStride");
            if (stride == views[v].end()) continue;
            if (!stride->is_number_unsigned() || stride->get<std::uint64_t>() < 4 ||
                stride->get<std::uint64_t>() > 252 || stride->get<std::uint64_t>() % 4 != 0)
                refuse("buffer view " + std::to_string(v) + ": byteStride " + stride->dump() +
                       " is not a multiple of 4 in 4..252");
        }
        const json& accessors = array_of(document_, "accessors");
        for (std::size_t a = 0; a < accessors.size(); ++a) {
            const json& accessor = accessors[a];
            if (!accessor.is_object()) continue;
            const auto view = accessor.find("bufferView");
            if (view == accessor.end() || !view->is_number_unsigned() ||
                view->get<std::uint64_t>() >= views.size() ||
                !views[view->get<std::size_t>()].is_object())
                continue;
            const json& v = views[view->get<std::size_t>()];
            const auto stride = v.find("byteStride");
            if (stride == v.end() || !stride->is_number_unsigned()) continue;
            const std::uint64_t element = element_bytes(accessor);
            if (stride->get<std::uint64_t>() < element)
                refuse("accessor " + std::to_string(a) + ": elements of " +
                       std::to_string(element) + " bytes, " + stride->dump() +
                       " bytes apart (byteStride of buffer view " + view->dump() +
                       "): they overlap");
        }
    }

    // f(mesh index, primitive index, primitive) for every primitive that is a JSON object.
    template <typename F>
    void for_each_primitive(F&& f) const {
        const json& meshes = array_of(document_, "meshes");
        for (std::size_t m = 0; m < meshes.size(); ++m) {
            if (!meshes[m].is_object()) continue;
            const json& primitives = array_of(meshes[m], "primitives");
            for (std::size_t p = 0; p < primitives.size(); ++p)
                if (primitives[p].is_object()) f(m, p, primitives[p]);
        }
    }

    // An accessor without a bufferView holds zeros (glTF 2.0), which the importer cannot read
    // unless sparse values replace some ("data is null when extracting data from accessors").
    void zero_accessors() const {
        const json& accessors = array_of(document_, "accessors");
        const auto check = [&](const json& index, const std::string& use) {
            if (!index.is_number_unsigned() || index.get<std::uint64_t>() >= accessors.size())
                return;
            const json& accessor = accessors[index.get<std::size_t>()];
            if (accessor.is_object() && !accessor.contains("bufferView") &&
                !accessor.contains("sparse"))
                refuse(use + " reads accessor " + index.dump() +
                       ", which has no bufferView (its values would all be zero): not "
                       "supported");
        };
        for (std::size_t a = 0; a < accessors.size(); ++a) {
            if (!accessors[a].is_object()) continue;
            const auto normalized = accessors[a].find("normalized");
            const auto type = accessors[a].find("componentType");
            if (normalized != accessors[a].end() && *normalized == true &&
                type != accessors[a].end() && (*type == 5126 || *type == 5125))
                refuse("accessor " + std::to_string(a) + ": \"normalized\" is true for " +
                       (*type == 5126 ? "float" : "32-bit integer") +
                       " components (glTF 2.0 allows it for 8- and 16-bit integers only)");
        }
        for_each_primitive([&](std::size_t m, std::size_t p, const json& primitive) {
            const std::string at =
                "mesh " + std::to_string(m) + ", primitive " + std::to_string(p) + ": ";
            if (const auto attributes = primitive.find("attributes");
                attributes != primitive.end() && attributes->is_object())
                for (const char* name : {"POSITION", "NORMAL", "TANGENT"}) {
                    const auto index = attributes->find(name);
                    if (index == attributes->end() || !index->is_number_unsigned() ||
                        index->get<std::uint64_t>() >= accessors.size() ||
                        !accessors[index->get<std::size_t>()].is_object())
                        continue;
                    const json& accessor = accessors[index->get<std::size_t>()];
                    if (accessor.value("componentType", json()) == 5125)
                        refuse(at + "attribute " + name + " reads accessor " + index->dump() +
                               " of 32-bit integers (glTF 2.0: floats, or normalized 8- and "
                               "16-bit integers)");
                }
            if (const auto attributes = primitive.find("attributes");
                attributes != primitive.end() && attributes->is_object())
                for (const auto& [name, index] : attributes->items())
                    check(index, at + "attribute " + name);
            if (const auto indices = primitive.find("indices"); indices != primitive.end())
                check(*indices, at + "indices");
        });
    }

    void attributes() const {
        const json& accessors = array_of(document_, "accessors");
        for_each_primitive([&](std::size_t m, std::size_t p, const json& primitive) {
            const auto attributes = primitive.find("attributes");
            if (attributes == primitive.end() || !attributes->is_object()) return;
            for (const auto& [name, index] : attributes->items()) {
                const std::string allowed = allowed_types(name);
                if (allowed.empty() || !index.is_number_unsigned() ||
                    index.get<std::uint64_t>() >= accessors.size() ||
                    !accessors[index.get<std::size_t>()].is_object())
                    continue;
                const auto type = accessors[index.get<std::size_t>()].find("type");
                if (type == accessors[index.get<std::size_t>()].end() || !type->is_string())
                    continue;
                const std::string t = type->get<std::string>();
                if (allowed.find(t) == std::string::npos || t.size() != 4)
                    refuse("mesh " + std::to_string(m) + ", primitive " + std::to_string(p) +
                           ": attribute " + name + " is a " + t + " accessor (" + allowed +
                           " in glTF 2.0)");
            }
        });
    }

    void nodes() const {
        const json& nodes = array_of(document_, "nodes");
        for (std::size_t n = 0; n < nodes.size(); ++n) {
            if (!nodes[n].is_object()) continue;
            for (const json& child : array_of(nodes[n], "children"))
                if (!child.is_number_unsigned() || child.get<std::uint64_t>() >= nodes.size())
                    refuse("node " + std::to_string(n) + ": child " + child.dump() +
                           " is not a node of the file's " + std::to_string(nodes.size()));
            placement(n, nodes[n]);
        }
    }

    // A node's placement as glTF 2.0 defines it (the importer takes any numbers: a projective
    // matrix blanks the image, a quaternion of length 10 scales the node by 100, NaN spreads).
    void placement(std::size_t n, const json& node) const {
        const std::string name = "node " + std::to_string(n) + ": ";
        const auto numbers = [&](const char* field, std::size_t count) -> std::vector<double> {
            const auto v = node.find(field);
            if (v == node.end()) return {};
            std::vector<double> out;
            if (v->is_array() && v->size() == count)
                for (const json& x : *v)
                    if (x.is_number() && std::isfinite(x.get<double>()))
                        out.push_back(x.get<double>());
            if (out.size() != count)
                refuse(name + "\"" + field + "\" must be " + std::to_string(count) +
                       " finite numbers, not " + v->dump());
            return out;
        };
        const std::vector<double> matrix = numbers("matrix", 16);
        const std::vector<double> rotation = numbers("rotation", 4);
        const bool parts =
            !numbers("translation", 3).empty() || !rotation.empty() || !numbers("scale", 3).empty();
        if (!matrix.empty() && parts)
            refuse(name +
                   "has a \"matrix\" and translation, rotation or scale: glTF 2.0 allows "
                   "one or the other");
        if (!matrix.empty() &&
            (matrix[3] != 0.0 || matrix[7] != 0.0 || matrix[11] != 0.0 || matrix[15] != 1.0))
            refuse(name + "\"matrix\" is not affine (its last row must be 0, 0, 0, 1)");
        if (!rotation.empty()) {
            const double length = std::sqrt(rotation[0] * rotation[0] + rotation[1] * rotation[1] +
                                            rotation[2] * rotation[2] + rotation[3] * rotation[3]);
            if (!(std::abs(length - 1.0) <= 1e-3))
                refuse(name + "\"rotation\" is not a unit quaternion (length " +
                       std::to_string(length) + ")");
        }
    }

    void scene() const {
        const auto scene = document_.find("scene");
        if (scene == document_.end()) return;
        const std::size_t scenes = array_of(document_, "scenes").size();
        if (!scene->is_number_unsigned() || scene->get<std::uint64_t>() >= scenes)
            refuse("\"scene\" " + scene->dump() + " is not one of the file's " +
                   std::to_string(scenes) + " scenes");
    }

    // zraster ignores a file's cameras, but its importer validates them and would refuse the
    // file in its own terms.
    void cameras() const {
        const json& cameras = array_of(document_, "cameras");
        for (std::size_t c = 0; c < cameras.size(); ++c) {
            if (!cameras[c].is_object()) continue;
            for (const char* kind : {"perspective", "orthographic"}) {
                const auto p = cameras[c].find(kind);
                if (p == cameras[c].end() || !p->is_object()) continue;
                const auto number = [&](const char* name) -> std::optional<double> {
                    const auto v = p->find(name);
                    if (v == p->end()) return std::nullopt;
                    if (!v->is_number())
                        refuse("camera " + std::to_string(c) + ": " + name + " " + v->dump() +
                               " is not a number");
                    return v->get<double>();
                };
                const std::optional<double> znear = number("znear"), zfar = number("zfar");
                const bool perspective = std::string(kind) == "perspective";
                if (znear && !(perspective ? *znear > 0.0 : *znear >= 0.0))
                    refuse("camera " + std::to_string(c) + ": znear " + p->at("znear").dump() +
                           (perspective ? " is not above 0" : " is negative"));
                if (znear && zfar && !(*zfar > *znear))
                    refuse("camera " + std::to_string(c) + ": zfar " + p->at("zfar").dump() +
                           " is not beyond znear " + p->at("znear").dump());
                if (perspective)
                    if (const std::optional<double> yfov = number("yfov"); yfov && !(*yfov > 0.0))
                        refuse("camera " + std::to_string(c) + ": yfov " + p->at("yfov").dump() +
                               " is not above 0");
            }
        }
    }

    // A primitive's material and a material's textures name elements the file has.
    void material_references() const {
        const std::size_t materials = array_of(document_, "materials").size();
        for_each_primitive([&](std::size_t m, std::size_t p, const json& primitive) {
            const auto material = primitive.find("material");
            if (material == primitive.end()) return;
            if (!material->is_number_unsigned() || material->get<std::uint64_t>() >= materials)
                refuse("mesh " + std::to_string(m) + ", primitive " + std::to_string(p) +
                       ": material " + material->dump() + " is not one of the file's " +
                       std::to_string(materials) + " materials");
        });
        const std::size_t textures = array_of(document_, "textures").size();
        const json& all = array_of(document_, "materials");
        for (std::size_t m = 0; m < all.size(); ++m) {
            if (!all[m].is_object())
                refuse("material " + std::to_string(m) + " is not a JSON object");
            const auto check = [&](const json& owner, const char* name) {
                const auto info = owner.find(name);
                if (info == owner.end() || !info->is_object()) return;
                const auto index = info->find("index");
                if (index != info->end() &&
                    (!index->is_number_unsigned() || index->get<std::uint64_t>() >= textures))
                    refuse("material " + std::to_string(m) + ": " + name + " index " +
                           index->dump() + " is not one of the file's " + std::to_string(textures) +
                           " textures");
            };
            for (const char* name : {"normalTexture", "occlusionTexture", "emissiveTexture"})
                check(all[m], name);
            const auto pbr = all[m].find("pbrMetallicRoughness");
            if (pbr != all[m].end() && !pbr->is_object())
                refuse("material " + std::to_string(m) +
                       ": pbrMetallicRoughness is not a JSON "
                       "object");
            if (pbr != all[m].end())
                for (const char* name : {"baseColorTexture", "metallicRoughnessTexture"})
                    check(*pbr, name);
        }
    }

    const std::filesystem::path& path_;
    const json& document_;
};

}  // namespace

void check_gltf_schema(const std::filesystem::path& path, const json& document) {
    SchemaChecker(path, document).run();
    check_gltf_texture_transforms(document, path.string());
}

}  // namespace zraster::io
