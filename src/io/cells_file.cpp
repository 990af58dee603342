// Loading `*.cells.json` (cells_file.hpp). nlohmann::json parses; every value is checked here
// before use, and each message names the element by its JSON path.
#include "io/cells_file.hpp"

#include <zraster/error.hpp>

#include <nlohmann/json.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <memory>

#include "io/input_file_check.hpp"
#include "io/json_errors.hpp"
#include "io/json_fields.hpp"
#include "io/read_file.hpp"
#include "io/reference_policy.hpp"

namespace zraster::io {
namespace {

using nlohmann::json;

class CellsReader {
  public:
    CellsReader(const std::filesystem::path& path, const LoadOptions& options)
        : path_(path),
          file_(path.string()),
          options_(options),
          policy_(path, options.allow_outside_references) {}

    LoadedScene read() {
        check_input_file(path_, options_.max_file_bytes);
        const std::vector<std::uint8_t> bytes = read_file_bytes(path_);
        json document;
        try {
            document = json::parse(bytes.begin(), bytes.end());
        } catch (const json::exception& e) {
            fail("", "malformed JSON: " + json_error_text(e));
        }
        if (!document.is_object()) fail("", "expected a JSON object");
        if (!document.contains("zraster_cells") || document["zraster_cells"] != 1)
            fail("zraster_cells", "expected 1 (the format's version)");
        known_fields(document, "", "the file",
                     {"zraster_cells", "meshes", "instances", "cells", "portals"});
        scene_.name = file_;
        read_meshes(member(document, "meshes", "", json::value_t::object),
                    document.contains("instances") ? document["instances"] : json());
        read_instances(member(document, "instances", "", json::value_t::array));
        read_cells(member(document, "cells", "", json::value_t::array));
        if (document.contains("portals"))
            read_portals(member(document, "portals", "", json::value_t::array));
        check_every_instance_in_a_cell();
        std::vector<Bounds3f> boxes;
        std::vector<std::string> names;
        for (const Instance& instance : scene_.instances) {
            boxes.push_back(scene_.meshes[instance.mesh].bounds.transformed(instance.transform));
            names.push_back(instance.name);
        }
        validate_cell_graph(graph_, boxes, names, file_);
        scene_.cells = std::make_shared<const CellGraph>(std::move(graph_));
        // The mesh files themselves, and what their loaders read.
        std::vector<std::filesystem::path> files_read = policy_.files_read();
        files_read.insert(files_read.end(), files_read_.begin(), files_read_.end());
        std::sort(files_read.begin(), files_read.end());
        files_read.erase(std::unique(files_read.begin(), files_read.end()), files_read.end());
        return {std::move(scene_), std::move(warnings_), std::move(files_read)};
    }

  private:
    [[noreturn]] void fail(const std::string& where, const std::string& cause) const {
        throw InputError(file_, where.empty() ? cause : where + ": " + cause);
    }
    // A refusal by LoadOptions::max_instances, the budget's name kept for the front end.
    [[noreturn]] void over_limit(const std::string& where, const std::string& cause) const {
        throw LimitExceeded(file_, "max_instances", where + ": " + cause);
    }

    // A field the format does not have (docs/portals.md): a typo such as "translation" would
    // leave the instance where it is without a word.
    void known_fields(const json& object, const std::string& where, const char* what,
                      std::initializer_list<std::string_view> known) const {
        if (const auto field = unknown_field(object, known)) {
            std::string list;
            for (const std::string_view k : known)
                list += (list.empty() ? "" : ", ") + std::string(k);
            fail(where.empty() ? "(top level)" : where, "\"" + *field + "\" is not a field of " +
                                                            what + " (" + list +
                                                            ": docs/portals.md)");
        }
    }

    const json& member(const json& object, const char* key, const std::string& where,
                       json::value_t type) const {
        const std::string at = where.empty() ? key : where + "." + key;
        if (!object.contains(key))
            fail(where.empty() ? "(top level)" : where, std::string("missing \"") + key + "\"");
        const json& value = object[key];
        const bool ok =
            type == json::value_t::number_float ? value.is_number() : value.type() == type;
        if (!ok) fail(at, std::string("expected ") + type_name(type));
        return value;
    }

    static const char* type_name(json::value_t type) {
        switch (type) {
            case json::value_t::object:
                return "an object";
            case json::value_t::array:
                return "an array";
            case json::value_t::string:
                return "a string";
            default:
                return "a number";
        }
    }

    double number(const json& value, const std::string& at) const {
        if (!value.is_number()) fail(at, "expected a number");
        const double x = value.get<double>();
        if (!std::isfinite(x) || std::abs(x) > 1e30) fail(at, "not a finite number (|x| <= 1e30)");
        return x;
    }

    template <int N>
    glm::vec<N, double> vector(const json& value, const std::string& at) const {
        if (!value.is_array() || value.size() != N)
            fail(at, "expected an array of " + std::to_string(N) + " numbers");
        glm::vec<N, double> v;
        for (int k = 0; k < N; ++k) v[k] = number(value[k], at + "[" + std::to_string(k) + "]");
        return v;
    }

    // Each mesh file is loaded once, however its name is spelled ("./x.obj", "d/../x.obj": 1,000
    // spellings of a 100,000-triangle file were 1,000 loads and 3 GB), and the triangles the
    // instances will place are counted as the files load: past max_triangles the file is refused
    // before the rest are read.
    void read_meshes(const json& meshes, const json& instances) {
        std::map<std::string, std::uint64_t> uses;  // instances naming each mesh
        if (instances.is_array())
            for (const json& instance : instances)
                if (instance.is_object() && instance.contains("mesh") &&
                    instance["mesh"].is_string())
                    ++uses[instance["mesh"].get<std::string>()];
        std::map<std::filesystem::path, std::shared_ptr<LoadedScene>> by_file;
        std::uint64_t placed = 0;  // triangles the instances place, of the meshes read so far
        for (const auto& [name, value] : meshes.items()) {
            const std::string at = "meshes." + name;
            if (!value.is_string()) fail(at, "expected a file name");
            std::filesystem::path file = value.get<std::string>();
            if (file.is_relative()) file = path_.parent_path() / file;
            const ReferencePolicy::Check check = policy_.check(file);
            if (check.verdict == ReferencePolicy::Verdict::Missing)
                fail(at, "mesh file '" + file.string() + "' not found");
            if (check.verdict == ReferencePolicy::Verdict::Refused)
                fail(at, check.reason + ": refused" + check.advice());
            if (is_cells_file(file)) fail(at, "a cells file cannot place another cells file");
            std::error_code ec;
            const std::filesystem::path canonical = std::filesystem::canonical(file, ec);
            std::shared_ptr<LoadedScene>& loaded = by_file[ec ? file : canonical];
            if (!loaded) {
                loaded = std::make_shared<LoadedScene>();
                loaded->scene = load_scene(file, options_, &loaded->warnings, &files_read_);
            }
            meshes_[name] = loaded;
            const auto count = uses.find(name);
            if (count == uses.end()) continue;
            placed += std::min<std::uint64_t>(loaded->scene.triangle_count(),
                                              ~std::uint64_t{0} / count->second) *
                      count->second;
            if (placed > options_.max_triangles)
                throw LimitExceeded(file_, "max_triangles",
                                    at + ": with the meshes before it, its " +
                                        std::to_string(count->second) +
                                        " instances place more than max_triangles (" +
                                        std::to_string(options_.max_triangles) + ") triangles");
        }
    }

    glm::mat4 transform(const json& instance, const std::string& at) const {
        if (instance.contains("matrix")) {
            // Either a matrix or the parts (docs/portals.md): with both, one would be ignored.
            for (const char* part : {"translate", "rotate_y_degrees", "scale"})
                if (instance.contains(part))
                    fail(at, std::string("has both \"matrix\" and \"") + part +
                                 "\" (the transform is a matrix or translate, rotate_y_degrees "
                                 "and scale, not both: docs/portals.md)");
            const json& m = instance["matrix"];
            if (!m.is_array() || m.size() != 16)
                fail(at + ".matrix", "expected 16 numbers (rows of a 4x4 matrix)");
            glm::dmat4 matrix;
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 4; ++c)
                    matrix[c][r] =
                        number(m[4 * r + c], at + ".matrix[" + std::to_string(4 * r + c) + "]");
            return glm::mat4(matrix);
        }
        glm::dmat4 t(1.0);
        if (instance.contains("translate"))
            t = glm::translate(t, vector<3>(instance["translate"], at + ".translate"));
        if (instance.contains("rotate_y_degrees"))
            t = glm::rotate(
                t, glm::radians(number(instance["rotate_y_degrees"], at + ".rotate_y_degrees")),
                glm::dvec3(0, 1, 0));
        if (instance.contains("scale")) {
            const json& s = instance["scale"];
            const glm::dvec3 scale =
                s.is_array() ? vector<3>(s, at + ".scale") : glm::dvec3(number(s, at + ".scale"));
            if (scale.x == 0.0 || scale.y == 0.0 || scale.z == 0.0)
                fail(at + ".scale", "must not be 0");
            t = glm::scale(t, scale);
        }
        return glm::mat4(t);
    }

    // Each instance places every instance of its mesh file (materials and meshes appended).
    void read_instances(const json& instances) {
        if (instances.size() > options_.max_instances)
            over_limit("instances", std::to_string(instances.size()) +
                                        " instances, more than max_instances " +
                                        std::to_string(options_.max_instances));
        std::map<const LoadedScene*, std::uint32_t> mesh_base;
        for (std::size_t k = 0; k < instances.size(); ++k) {
            const std::string at = "instances[" + std::to_string(k) + "]";
            const json& instance = instances[k];
            if (!instance.is_object()) fail(at, "expected an object");
            known_fields(instance, at, "an instance",
                         {"name", "mesh", "matrix", "translate", "rotate_y_degrees", "scale"});
            const std::string name =
                member(instance, "name", at, json::value_t::string).get<std::string>();
            const std::string mesh =
                member(instance, "mesh", at, json::value_t::string).get<std::string>();
            if (instance_ranges_.contains(name))
                fail(at + ".name", "'" + name + "' is named twice");
            const auto found = meshes_.find(mesh);
            if (found == meshes_.end())
                fail(at + ".mesh", "no mesh named '" + mesh + "' in \"meshes\"");
            const Scene& source = found->second->scene;
            // (Names spelling one file share its meshes.)
            const LoadedScene* key = found->second.get();
            if (!mesh_base.contains(key)) mesh_base[key] = append_meshes(*found->second);
            const glm::mat4 placement = transform(instance, at);
            const auto first = std::uint32_t(scene_.instances.size());
            for (const Instance& placed : source.instances) {
                Instance out = placed;
                out.mesh += mesh_base[key];
                out.transform = placement * placed.transform;
                out.name = source.instances.size() == 1 ? name : name + "/" + placed.name;
                scene_.instances.push_back(std::move(out));
                placed_by_.push_back(k);
            }
            if (scene_.instances.size() > options_.max_instances)
                over_limit(at, "the scene places more than " +
                                   std::to_string(options_.max_instances) +
                                   " instances (max_instances)");
            instance_ranges_[name] = {first, std::uint32_t(scene_.instances.size())};
        }
    }

    // validate_cell_graph refuses this too, naming the scene's instance; here the message names
    // the JSON element that placed it.
    void check_every_instance_in_a_cell() const {
        if (graph_.cells.empty()) return;  // validate_cell_graph says there are none
        std::vector<std::uint8_t> listed(scene_.instances.size(), 0);
        for (const Cell& cell : graph_.cells)
            for (const std::uint32_t i : cell.instances) listed[i] = 1;
        for (std::size_t i = 0; i < listed.size(); ++i)
            if (listed[i] == 0)
                fail("instances[" + std::to_string(placed_by_[i]) + "]",
                     "'" + scene_.instances[i].name +
                         "' is in no cell (list an instance in every cell its bounds touch)");
    }

    std::uint32_t append_meshes(const LoadedScene& loaded) {
        const Scene& source = loaded.scene;
        const auto material_base = std::uint32_t(scene_.materials.size());
        scene_.materials.insert(scene_.materials.end(), source.materials.begin(),
                                source.materials.end());
        const auto mesh_base = std::uint32_t(scene_.meshes.size());
        for (Mesh mesh : source.meshes) {
            mesh.material += material_base;
            scene_.meshes.push_back(std::move(mesh));
        }
        warnings_.insert(warnings_.end(), loaded.warnings.begin(), loaded.warnings.end());
        return mesh_base;
    }

    void read_cells(const json& cells) {
        if (cells.size() > graph_.limits.max_cells)
            fail("cells", std::to_string(cells.size()) + " cells, more than the limit of " +
                              std::to_string(graph_.limits.max_cells));
        for (std::size_t k = 0; k < cells.size(); ++k) {
            const std::string at = "cells[" + std::to_string(k) + "]";
            const json& value = cells[k];
            if (!value.is_object()) fail(at, "expected an object");
            known_fields(value, at, "a cell", {"name", "box", "planes", "instances"});
            Cell cell;
            cell.name = member(value, "name", at, json::value_t::string).get<std::string>();
            if (cell_index_.contains(cell.name))
                fail(at + ".name", "'" + cell.name + "' is named twice");
            cell.volume = volume(value, at);
            const json& names = member(value, "instances", at, json::value_t::array);
            for (std::size_t i = 0; i < names.size(); ++i) {
                const std::string where = at + ".instances[" + std::to_string(i) + "]";
                if (!names[i].is_string()) fail(where, "expected an instance name");
                const auto range = instance_ranges_.find(names[i].get<std::string>());
                if (range == instance_ranges_.end())
                    fail(where, "no instance named '" + names[i].get<std::string>() + "'");
                for (std::uint32_t n = range->second.first; n < range->second.second; ++n)
                    cell.instances.push_back(n);
            }
            cell_index_[cell.name] = std::uint32_t(graph_.cells.size());
            graph_.cells.push_back(std::move(cell));
        }
    }

    CellVolume volume(const json& cell, const std::string& at) const {
        if (cell.contains("box") == cell.contains("planes"))
            fail(at, "give either \"box\" ([[x0, y0, z0], [x1, y1, z1]]) or \"planes\"");
        if (cell.contains("box")) {
            const json& box = cell["box"];
            if (!box.is_array() || box.size() != 2)
                fail(at + ".box", "expected [[x0, y0, z0], [x1, y1, z1]]");
            const glm::dvec3 lo = vector<3>(box[0], at + ".box[0]"),
                             hi = vector<3>(box[1], at + ".box[1]");
            if (!glm::all(glm::lessThan(lo, hi)))
                fail(at + ".box", "the first corner must be below the second on every axis");
            return box_volume(lo, hi);
        }
        const json& planes = cell["planes"];
        if (!planes.is_array() || planes.size() > graph_.limits.max_cell_planes)
            fail(at + ".planes", "expected an array of at most " +
                                     std::to_string(graph_.limits.max_cell_planes) +
                                     " planes [a, b, c, d] (inside: a x + b y + c z + d >= 0)");
        std::vector<glm::dvec4> list;
        for (std::size_t i = 0; i < planes.size(); ++i)
            list.push_back(vector<4>(planes[i], at + ".planes[" + std::to_string(i) + "]"));
        try {
            return convex_volume(list);
        } catch (const InputError& e) {
            fail(at + ".planes", e.cause());
        }
    }

    void read_portals(const json& portals) {
        if (portals.size() > graph_.limits.max_portals)
            fail("portals", std::to_string(portals.size()) + " portals, more than the limit of " +
                                std::to_string(graph_.limits.max_portals));
        for (std::size_t k = 0; k < portals.size(); ++k) {
            const std::string at = "portals[" + std::to_string(k) + "]";
            const json& value = portals[k];
            if (!value.is_object()) fail(at, "expected an object");
            known_fields(value, at, "a portal", {"cells", "corners"});
            Portal portal;
            const json& cells = member(value, "cells", at, json::value_t::array);
            if (cells.size() != 2) fail(at + ".cells", "expected the names of two cells");
            for (std::size_t c = 0; c < 2; ++c) {
                const std::string where = at + ".cells[" + std::to_string(c) + "]";
                if (!cells[c].is_string()) fail(where, "expected a cell name");
                const auto found = cell_index_.find(cells[c].get<std::string>());
                if (found == cell_index_.end())
                    fail(where, "no cell named '" + cells[c].get<std::string>() + "'");
                portal.cells[c] = found->second;
            }
            const json& corners = member(value, "corners", at, json::value_t::array);
            if (corners.size() > graph_.limits.max_portal_corners)
                fail(at + ".corners", std::to_string(corners.size()) +
                                          " corners, more than the limit of " +
                                          std::to_string(graph_.limits.max_portal_corners));
            for (std::size_t c = 0; c < corners.size(); ++c)
                portal.corners.push_back(
                    vector<3>(corners[c], at + ".corners[" + std::to_string(c) + "]"));
            graph_.portals.push_back(std::move(portal));
        }
    }

    const std::filesystem::path path_;
    const std::string file_;
    const LoadOptions& options_;
    const ReferencePolicy policy_;
    Scene scene_;
    std::vector<std::string> warnings_;  // of the meshes placed
    CellGraph graph_;
    std::map<std::string, std::shared_ptr<LoadedScene>> meshes_;
    std::vector<std::filesystem::path> files_read_;  // by the mesh files' loaders
    std::vector<std::size_t> placed_by_;  // per scene instance: its element of "instances"
    std::map<std::string, std::pair<std::uint32_t, std::uint32_t>> instance_ranges_;
    std::map<std::string, std::uint32_t> cell_index_;
};

}  // namespace

bool is_cells_file(const std::filesystem::path& path) {
    std::string name = path.filename().string();
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return name.size() > 11 && name.ends_with(".cells.json");
}

LoadedScene load_cells_file(const std::filesystem::path& path, const LoadOptions& options) {
    return CellsReader(path, options).read();
}

}  // namespace zraster::io
