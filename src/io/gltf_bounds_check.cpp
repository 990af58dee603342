#include "io/gltf_bounds_check.hpp"

#include "io/gltf_decode_budget.hpp"
#include "io/gltf_document.hpp"
#include "io/gltf_schema_check.hpp"
#include "io/reference_policy.hpp"
#include "io/text_util.hpp"
#include "io/uri_escapes.hpp"

#include <zraster/error.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <utility>

#include <system_error>
#include <vector>

namespace zraster::io {

namespace {

using nlohmann::json;

// A non-negative integer member, or `fallback` when absent; nullopt when malformed (Assimp then
// reports the document itself).
std::optional<std::uint64_t> unsigned_member(const json& object, const char* key,
                                             std::uint64_t fallback) {
    const auto it = object.find(key);
    if (it == object.end()) return fallback;
    if (!it->is_number_unsigned()) return std::nullopt;
    return it->get<std::uint64_t>();
}

// The same for a member defaulting to 0, as a flag and an out value.
bool read_unsigned(const json& object, const char* key, std::uint64_t& value) {
    const auto member = unsigned_member(object, key, 0);
    value = member.value_or(0);
    return member.has_value();
}

std::uint64_t component_bytes(std::uint64_t type) {
    switch (type) {
        case 5120:  // BYTE
        case 5121:  // UNSIGNED_BYTE
            return 1;
        case 5122:  // SHORT
        case 5123:  // UNSIGNED_SHORT
            return 2;
        case 5125:  // UNSIGNED_INT
        case 5126:  // FLOAT
            return 4;
        default:
            return 0;
    }
}

// Bytes a base64 data: URI decodes to.
std::optional<std::uint64_t> data_uri_bytes(const std::string& uri) {
    const std::size_t comma = uri.find(',');
    if (comma == std::string::npos || uri.find(";base64", 0) > comma) return std::nullopt;
    std::uint64_t chars = uri.size() - comma - 1, padding = 0;
    for (std::size_t i = uri.size(); i > comma + 1 && uri[i - 1] == '='; --i) ++padding;
    return chars / 4 * 3 - std::min<std::uint64_t>(padding, 2) + (chars % 4 ? chars % 4 - 1 : 0);
}

class Checker {
  public:
    Checker(const std::filesystem::path& path, const json& document,
            std::optional<std::uint64_t> glb_binary, const LoadOptions& options)
        : path_(path),
          document_(document),
          glb_binary_(glb_binary),
          options_(options),
          policy_(path, options.allow_outside_references) {}

    // Returns the nodes the importer makes of the scene's node graph (see instances()).
    GltfImporterCounts run() {
        buffers();
        views();
        accessors();
        return instances();
    }

  private:
    [[noreturn]] void refuse(const std::string& what) const {
        throw InputError(path_.string(), "malformed glTF file: glTF " + what);
    }

    const json& array(const char* key) const {
        static const json empty = json::array();
        const auto it = document_.find(key);
        return it != document_.end() && it->is_array() ? *it : empty;
    }

    void buffers() {
        const json& list = array("buffers");
        for (std::size_t i = 0; i < list.size(); ++i) {
            const json& b = list[i];
            // A plain integer, not an optional: GCC 12 misreads the optional as uninitialized.
            std::uint64_t length = 0;
            const bool valid = b.is_object() && read_unsigned(b, "byteLength", length);
            buffer_bytes_.push_back(valid ? length : 0);
            if (!valid) continue;
            std::optional<std::uint64_t> data;
            const auto uri = b.find("uri");
            if (uri == b.end()) {
                if (i == 0) data = glb_binary_;
            } else if (uri->is_string()) {
                const std::string text = uri->get<std::string>();
                // Assimp joins a buffer's URI to the model's folder whatever it is: an absolute
                // path or a file: URL names a file it never opens (and could not be allowed).
                std::string scheme = text.substr(0, 5);
                for (char& c : scheme) c = char(std::tolower(static_cast<unsigned char>(c)));
                if (text.starts_with('/') || scheme == "file:")
                    throw InputError(
                        path_.string(),
                        "buffer " + std::to_string(i) + "'s URI '" + one_line(text) +
                            (scheme == "file:" ? "' is a file: URL" : "' is an absolute path") +
                            ": glTF buffers are read relative to the model's folder "
                            "only (a relative URI such as 'data.bin')");
                if (text.starts_with("data:")) {
                    data = data_uri_bytes(text);
                } else if (const auto file = uri_file(path_.parent_path(), text);
                           policy_.check(file).verdict == ReferencePolicy::Verdict::Readable) {
                    // (A refused file is left to the loader, which names it.)
                    std::error_code ec;
                    const auto size = std::filesystem::file_size(file, ec);
                    if (!ec) data = size;
                }
            }
            // A missing file or an undecodable URI is Assimp's to report; a short one is ours.
            if (data && length > *data)
                refuse("buffer " + std::to_string(i) + " declares " + std::to_string(length) +
                       " bytes, its data holds " + std::to_string(*data));
        }
    }

    void views() {
        const json& list = array("bufferViews");
        for (std::size_t i = 0; i < list.size(); ++i) {
            const json& v = list[i];
            view_bytes_.push_back(0);
            view_stride_.push_back(0);
            if (!v.is_object()) continue;
            const auto buffer = unsigned_member(v, "buffer", ~std::uint64_t{0});
            const auto offset = unsigned_member(v, "byteOffset", 0);
            const auto length = unsigned_member(v, "byteLength", 0);
            const auto stride = unsigned_member(v, "byteStride", 0);
            if (!buffer || !offset || !length || !stride || *buffer >= buffer_bytes_.size())
                continue;
            const std::uint64_t size = buffer_bytes_[*buffer];
            if (*offset > size || *length > size - *offset)
                refuse("buffer view " + std::to_string(i) + " spans bytes " +
                       std::to_string(*offset) + " + " + std::to_string(*length) + " of buffer " +
                       std::to_string(*buffer) + ", which holds " + std::to_string(size));
            view_bytes_.back() = *length;
            view_stride_.back() = *stride;
        }
    }

    // `count` elements of `element` bytes, `stride` apart, from `offset` in buffer view `view`.
    void range(const std::string& what, const json& holder, std::uint64_t count,
               std::uint64_t element, bool strided) {
        const auto view = unsigned_member(holder, "bufferView", ~std::uint64_t{0});
        const auto offset = unsigned_member(holder, "byteOffset", 0);
        if (!view || !offset || *view >= view_bytes_.size() || count == 0 || element == 0) return;
        const std::uint64_t size = view_bytes_[*view];
        const std::uint64_t stride =
            strided && view_stride_[*view] > 0 ? view_stride_[*view] : element;
        const bool fits = *offset <= size && element <= size - *offset &&
                          (count - 1) <= (size - *offset - element) / stride;
        if (!fits)
            refuse(what + " reads " + std::to_string(count) + " elements of " +
                   std::to_string(element) + " bytes from byte " + std::to_string(*offset) +
                   " of buffer view " + std::to_string(*view) + ", which holds " +
                   std::to_string(size));
    }

    void accessors() {
        const json& list = array("accessors");
        for (std::size_t i = 0; i < list.size(); ++i) {
            const json& a = list[i];
            if (!a.is_object()) continue;
            const auto count = unsigned_member(a, "count", 0);
            const auto type = unsigned_member(a, "componentType", 0);
            const auto kind = a.find("type");
            if (!count || !type || kind == a.end() || !kind->is_string()) continue;
            const std::uint64_t element =
                component_bytes(*type) * gltf_type_components(kind->get<std::string>());
            const std::string name = "accessor " + std::to_string(i);
            range(name, a, *count, element, true);
            const auto sparse = a.find("sparse");
            if (sparse == a.end() || !sparse->is_object()) continue;
            const auto sparse_count = unsigned_member(*sparse, "count", 0);
            const auto indices = sparse->find("indices");
            const auto values = sparse->find("values");
            if (!sparse_count) continue;
            if (indices != sparse->end() && indices->is_object()) {
                const auto index_type = unsigned_member(*indices, "componentType", 0);
                if (index_type)
                    range(name + " (sparse indices)", *indices, *sparse_count,
                          component_bytes(*index_type), false);
            }
            if (values != sparse->end() && values->is_object())
                range(name + " (sparse values)", *values, *sparse_count, element, false);
        }
    }

    // Meshes placed by the scene's node graph, counted without expanding it: a node places its
    // own mesh once per path from a root to it. Refuses a cycle and a count past the budget.
    // Returns the nodes the importer makes: it copies a node once per path to it too, meshes or
    // not (saturated at 2^64 - 1), and the paths to each node.
    GltfImporterCounts instances() {
        const json& nodes = array("nodes");
        const json& meshes = array("meshes");
        const std::uint64_t limit = options_.max_instances;
        std::vector<std::uint64_t> placed(nodes.size(), 0), copies(nodes.size(), 0);
        const auto add = [](std::uint64_t a, std::uint64_t b) {
            return a > UINT64_MAX - b ? UINT64_MAX : a + b;
        };
        std::vector<std::uint8_t> state(nodes.size(), 0);  // 0 new, 1 on the path, 2 done
        std::vector<std::size_t> finished;                 // children before their parents
        const auto child_list = [&](std::size_t n) -> const json* {
            const auto it = nodes[n].is_object() ? nodes[n].find("children") : nodes[n].end();
            return it != nodes[n].end() && it->is_array() ? &*it : nullptr;
        };
        for (std::size_t root = 0; root < nodes.size(); ++root) {
            // Post-order with an explicit stack: a hostile file can nest deeper than the call
            // stack allows.
            std::vector<std::pair<std::size_t, std::size_t>> stack;  // node, next child
            if (state[root] == 0) stack.emplace_back(root, 0);
            while (!stack.empty()) {
                auto& [n, next] = stack.back();
                if (next == 0 && state[n] == 0) state[n] = 1;
                const json* children = child_list(n);
                if (children && next < children->size()) {
                    const json& c = (*children)[next++];
                    if (!c.is_number_unsigned() || c.get<std::uint64_t>() >= nodes.size())
                        continue;  // Assimp reports it
                    const auto child = static_cast<std::size_t>(c.get<std::uint64_t>());
                    if (state[child] == 1)
                        refuse("node " + std::to_string(child) + " is its own ancestor");
                    if (state[child] == 0) stack.emplace_back(child, 0);
                    continue;
                }
                std::uint64_t total = 0;
                const auto mesh = nodes[n].is_object() ? nodes[n].find("mesh") : nodes[n].end();
                if (mesh != nodes[n].end() && mesh->is_number_unsigned() &&
                    mesh->get<std::uint64_t>() < meshes.size()) {
                    const json& m = meshes[mesh->get<std::size_t>()];
                    const auto primitives = m.is_object() ? m.find("primitives") : m.end();
                    total = primitives != m.end() && primitives->is_array()
                                ? std::max<std::uint64_t>(1, primitives->size())
                                : 1;
                }
                std::uint64_t below = 1;
                if (children)
                    for (const json& c : *children)
                        if (c.is_number_unsigned() && c.get<std::uint64_t>() < nodes.size()) {
                            total = std::min(limit + 1, total + placed[c.get<std::size_t>()]);
                            below = add(below, copies[c.get<std::size_t>()]);
                        }
                placed[n] = std::min(limit + 1, total);
                copies[n] = below;
                state[n] = 2;
                finished.push_back(n);
                stack.pop_back();
            }
        }
        // What the scene places: its root nodes (every node if it names no scene).
        std::uint64_t total = 0, made = 0;
        std::vector<std::uint64_t> paths(nodes.size(), 0);
        const json& scenes = array("scenes");
        const auto scene_index = unsigned_member(document_, "scene", 0).value_or(0);
        if (scene_index < scenes.size() && scenes[scene_index].is_object()) {
            const auto roots = scenes[scene_index].find("nodes");
            if (roots != scenes[scene_index].end() && roots->is_array())
                for (const json& r : *roots)
                    if (r.is_number_unsigned() && r.get<std::uint64_t>() < nodes.size()) {
                        total = std::min(limit + 1, total + placed[r.get<std::size_t>()]);
                        made = add(made, copies[r.get<std::size_t>()]);
                        paths[r.get<std::size_t>()] = add(paths[r.get<std::size_t>()], 1);
                    }
        }
        // Parents before their children: a node's paths reach each of its children.
        for (auto n = finished.rbegin(); n != finished.rend(); ++n)
            if (const json* children = child_list(*n); children && paths[*n] > 0)
                for (const json& c : *children)
                    if (c.is_number_unsigned() && c.get<std::uint64_t>() < nodes.size())
                        paths[c.get<std::size_t>()] = add(paths[c.get<std::size_t>()], paths[*n]);
        if (total > limit)
            throw LimitExceeded(path_.string(), "max_instances",
                                "the node graph places more than " + std::to_string(limit) +
                                    " meshes (max_instances; nodes sharing children multiply)");
        return {made, std::move(paths), glb_binary_};
    }

    const std::filesystem::path& path_;
    const json& document_;
    std::optional<std::uint64_t> glb_binary_;
    const LoadOptions& options_;
    ReferencePolicy policy_;
    std::vector<std::uint64_t> buffer_bytes_, view_bytes_, view_stride_;
};

// The deepest nesting of arrays and objects in `text` (strings skipped), stopping past `limit`;
// `at` is where it first went past `limit`.
std::size_t json_depth(const std::string& text, std::size_t limit, std::size_t& at) {
    std::size_t depth = 0, deepest = 0;
    bool in_string = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
            if (depth > limit) {
                at = i;
                return depth;
            }
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

}  // namespace

void check_gltf_bounds(const std::filesystem::path& path, const std::string& json_text,
                       std::optional<std::uint64_t> glb_binary, const LoadOptions& options) {
    // Assimp's JSON parser recurses once per level: 200,000 nested arrays in "extras" (a 400 KB
    // file) overflowed its stack (SIGSEGV, in process). glTF's own structure nests fewer than 20.
    std::size_t at = 0;
    if (json_depth(json_text, kMaxGltfJsonDepth, at) > kMaxGltfJsonDepth)
        throw InputError(path.string(),
                         "malformed glTF file: its JSON nests arrays and objects more than " +
                             std::to_string(kMaxGltfJsonDepth) + " levels deep (at byte " +
                             std::to_string(at) + " of the JSON; glTF needs fewer than 20)");
    const json document = json::parse(json_text, nullptr, false);
    if (document.is_discarded() || !document.is_object()) return;
    check_gltf_schema(path, document);
    const GltfImporterCounts nodes = Checker(path, document, glb_binary, options).run();
    check_gltf_decode_budget(path, document, options, nodes);
}

}  // namespace zraster::io
