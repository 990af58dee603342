// libFuzzer target, structure-aware: the input drives a generator that writes a structurally
// valid glTF 2.0 file (JSON) into the model folder of reference_fixtures.hpp and loads it. The
// generator makes what random bytes rarely spell: node graphs whose nodes share children (DAGs
// of any depth and fan-out, placing a mesh fan_out^depth times), cycles, many meshes and
// primitives, accessors with huge declared counts, and buffer and image URIs naming files
// inside the folder, missing ones, "../" escapes, absolute and file:// paths, percent-encoded
// escapes, data: URIs, links out of the folder, a FIFO, a loop of links, a directory, devices.
//
// Oracles (besides the sanitizers): refused with one line naming the file (a budget's refusal
// names its LoadOptions field, no Assimp internals as the cause), or a scene that keeps every
// promise of load.hpp, places at most max_instances instances and holds nothing of the secret
// files outside the folder (unless the input allowed outside references); then drawn at 24x16.
// A FIFO or device read would hang: libFuzzer's timeout.
#include <fuzzer/FuzzedDataProvider.h>
#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_support.hpp"
#include "reference_fixtures.hpp"

namespace {

using nlohmann::json;
using namespace zraster;

// Three float positions then three uint16 indices, as a data: URI (base64).
const char* kTriangleDataUri =
    "data:application/octet-stream;base64,"
    "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIA";

std::uint64_t pick_count(FuzzedDataProvider& in, std::uint64_t usual) {
    switch (in.ConsumeIntegralInRange(0, 7)) {
        case 0:
            return in.ConsumeIntegral<std::uint32_t>();
        case 1:
            return std::uint64_t{1} << in.ConsumeIntegralInRange(20, 62);
        case 2:
            return 0;
        default:
            return usual;
    }
}

std::string pick_uri(FuzzedDataProvider& in, const std::vector<std::string>& names) {
    const int choice = in.ConsumeIntegralInRange(0, int(names.size()) + 1);
    if (choice == int(names.size())) return kTriangleDataUri;
    if (choice == int(names.size()) + 1) return in.ConsumeRandomLengthString(40);
    return names[std::size_t(choice)];
}

json generate(FuzzedDataProvider& in) {
    static const std::vector<std::string> buffers = fuzz::reference_names(".bin");
    static const std::vector<std::string> images = fuzz::reference_names(".png");
    json gltf;
    gltf["asset"] = {{"version", "2.0"}};
    // Buffers: 42 bytes (a triangle), views of its positions and indices.
    const int buffer_count = in.ConsumeIntegralInRange(1, 3);
    for (int b = 0; b < buffer_count; ++b) {
        json buffer = {{"byteLength", pick_count(in, 42)}};
        if (b > 0 || in.ConsumeBool()) buffer["uri"] = pick_uri(in, buffers);
        gltf["buffers"].push_back(buffer);
        gltf["bufferViews"].push_back(
            {{"buffer", b}, {"byteOffset", 0}, {"byteLength", pick_count(in, 36)}});
        gltf["bufferViews"].push_back(
            {{"buffer", b}, {"byteOffset", pick_count(in, 36)}, {"byteLength", 6}});
    }
    const int view_count = 2 * buffer_count;
    const int accessor_pairs = in.ConsumeIntegralInRange(1, 3);
    for (int a = 0; a < accessor_pairs; ++a) {
        const int view = 2 * in.ConsumeIntegralInRange(0, buffer_count - 1);
        gltf["accessors"].push_back({{"bufferView", view},
                                     {"componentType", 5126},
                                     {"count", pick_count(in, 3)},
                                     {"type", "VEC3"},
                                     {"min", {0, 0, 0}},
                                     {"max", {1, 1, 0}}});
        gltf["accessors"].push_back({{"bufferView", view + 1},
                                     {"componentType", 5123},
                                     {"count", pick_count(in, 3)},
                                     {"type", "SCALAR"}});
    }
    (void)view_count;
    // Images, textures, materials.
    const int image_count = in.ConsumeIntegralInRange(0, 3);
    for (int i = 0; i < image_count; ++i) {
        gltf["images"].push_back({{"uri", pick_uri(in, images)}});
        gltf["textures"].push_back({{"source", in.ConsumeIntegralInRange(0, image_count)}});
        json material;
        material["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", i}};
        gltf["materials"].push_back(material);
    }
    // Meshes of several primitives.
    const int mesh_count = in.ConsumeIntegralInRange(1, 8);
    for (int m = 0; m < mesh_count; ++m) {
        json mesh;
        const int primitives = in.ConsumeIntegralInRange(1, 6);
        for (int p = 0; p < primitives; ++p) {
            const int a = 2 * in.ConsumeIntegralInRange(0, accessor_pairs - 1);
            json primitive = {{"attributes", {{"POSITION", a}}}};
            if (in.ConsumeBool()) primitive["indices"] = a + 1;
            if (image_count > 0 && in.ConsumeBool())
                primitive["material"] = in.ConsumeIntegralInRange(0, image_count - 1);
            mesh["primitives"].push_back(primitive);
        }
        gltf["meshes"].push_back(mesh);
    }
    // The node graph: layers of nodes, each holding children from the layer below (shared:
    // fan-out multiplies placements), a few back edges (cycles), any mesh.
    const int layers = in.ConsumeIntegralInRange(1, 12);
    std::vector<std::vector<int>> layer_nodes(static_cast<std::size_t>(layers));
    int node_count = 0;
    for (int l = 0; l < layers; ++l) {
        const int width = in.ConsumeIntegralInRange(1, 4);
        for (int w = 0; w < width; ++w) layer_nodes[std::size_t(l)].push_back(node_count++);
    }
    gltf["nodes"] = json::array();
    for (int l = 0; l < layers; ++l) {
        for (const int n : layer_nodes[std::size_t(l)]) {
            json node = json::object();
            if (l == 0 || in.ConsumeIntegralInRange(0, 3) == 0)
                node["mesh"] =
                    in.ConsumeIntegralInRange(0, mesh_count - 1 + (in.ConsumeBool() ? 0 : 2));
            if (l > 0) {
                const auto& below = layer_nodes[std::size_t(l - 1)];
                const int fan_out = in.ConsumeIntegralInRange(1, 12);
                for (int c = 0; c < fan_out; ++c)
                    node["children"].push_back(
                        below[std::size_t(in.ConsumeIntegralInRange(0, int(below.size()) - 1))]);
            }
            if (in.ConsumeIntegralInRange(0, 15) == 0)  // a cycle, or a child out of range
                node["children"].push_back(in.ConsumeIntegralInRange(0, node_count));
            switch (in.ConsumeIntegralInRange(0, 7)) {
                case 0:
                    node["translation"] = {in.ConsumeFloatingPoint<double>(), 0, 0};
                    break;
                case 1:
                    node["scale"] = {1e20, 1e20, 1e20};
                    break;
                default:
                    break;
            }
            (void)n;
            gltf["nodes"].push_back(node);
        }
    }
    json roots = json::array();
    for (const int n : layer_nodes.back()) roots.push_back(n);
    if (in.ConsumeBool()) roots.push_back(layer_nodes.back().front());  // a root twice
    gltf["scenes"] = json::array({{{"nodes", roots}}});
    gltf["scene"] = 0;
    return gltf;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider in(data, size);
    const std::filesystem::path path = fuzz::reference_model_dir() / "graph.gltf";
    LoadOptions options = fuzz::fuzz_load_options();
    options.max_instances = 2000;  // shared children past it are refused, cheaply
    options.allow_outside_references = in.ConsumeIntegralInRange(0, 7) == 0;
    const json gltf = generate(in);
    fuzz::write_file(path, gltf.dump(-1, ' ', false, json::error_handler_t::replace));

    const std::optional<Scene> scene = fuzz::load_reference_model(path, options);
    if (scene && scene->instances.size() > options.max_instances)
        fuzz::fail(std::to_string(scene->instances.size()) + " instances, past max_instances");
    return 0;
}
