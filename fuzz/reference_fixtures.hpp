// The scratch folders of the structure-aware loader fuzzers (fuzz_gltf_graph, fuzz_obj_mtl): a
// model folder holding good companions and special files a hostile model may name, and beside
// it, outside the model's folder, "secret" files whose bytes are recognisable in a loaded scene.
// The oracle: a scene loaded without LoadOptions::allow_outside_references holds no secret
// geometry, material or texture (nothing was read outside the folder).
//
//   work/secret.bin    a triangle at x = y = z = kSecretCoordinate (3 floats x 3, 3 uint16)
//   work/secret.png    a 4x4 PNG of kSecretTexel only
//   work/secret.mtl    material "secret" of base color kSecretColor
//   work/model/        in.bin (a triangle), in.png (a checkerboard), in.mtl; fifo (a FIFO),
//                      loop-a <-> loop-b (a loop of symbolic links), folder (a directory),
//                      out.bin, out.png, out.mtl (links to the secrets), in-link.bin (a link
//                      to in.bin), empty (an empty file)
#pragma once
#include <zraster/error.hpp>
#include <zraster/load.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include <sys/stat.h>

#include "fuzz_support.hpp"

namespace zraster::fuzz {

inline constexpr float kSecretCoordinate = 7777.0f;
inline constexpr std::array<std::uint8_t, 4> kSecretTexel = {17, 34, 51, 68};
inline constexpr float kSecretColor[3] = {0.125f, 0.375f, 0.625f};

inline std::string triangle_buffer(float at) {
    const float positions[9] = {at, at, at, at + 1, at, at, at, at + 1, at};
    const std::uint16_t indices[3] = {0, 1, 2};
    std::string bin(reinterpret_cast<const char*>(positions), sizeof positions);
    bin.append(reinterpret_cast<const char*>(indices), sizeof indices);
    return bin;
}

// The model folder, created once per process (the work directory's "model").
inline const std::filesystem::path& reference_model_dir() {
    static const std::filesystem::path model = [] {
        const std::filesystem::path& work = work_dir();
        const std::filesystem::path m = work / "model";
        std::filesystem::create_directories(m);
        write_file(work / "secret.bin", triangle_buffer(kSecretCoordinate));
        std::vector<std::uint8_t> rgba;
        for (int i = 0; i < 16; ++i)
            rgba.insert(rgba.end(), kSecretTexel.begin(), kSecretTexel.end());
        write_png8(work / "secret.png", 4, 4, 4, rgba);
        write_file(work / "secret.mtl", "newmtl secret\nKd 0.125 0.375 0.625\nmap_Kd secret.png\n");
        write_file(m / "in.bin", triangle_buffer(0.0f));
        write_texture_fixture(m / "in.png");
        write_file(m / "in.mtl", "newmtl m\nKd 0.5 0.6 0.7\nmap_Kd in.png\nnewmtl n\nKd 1 0 0\n");
        write_file(m / "empty", "");
        if (::mkfifo((m / "fifo").c_str(), 0600) != 0) fail("mkfifo failed");
        std::filesystem::create_symlink("loop-b", m / "loop-a");
        std::filesystem::create_symlink("loop-a", m / "loop-b");
        std::filesystem::create_directory(m / "folder");
        std::filesystem::create_symlink(work / "secret.bin", m / "out.bin");
        std::filesystem::create_symlink(work / "secret.png", m / "out.png");
        std::filesystem::create_symlink(work / "secret.mtl", m / "out.mtl");
        std::filesystem::create_symlink("in.bin", m / "in-link.bin");
        return m;
    }();
    return model;
}

// Names a generated model may use for an external file of kind `extension` (".bin", ".png",
// ".mtl"): inside, missing, special files, escapes, absolute paths, links out.
inline std::vector<std::string> reference_names(const std::string& extension) {
    const std::string secret = (work_dir() / ("secret" + extension)).string();
    return {"in" + extension,
            "missing" + extension,
            "../secret" + extension,
            "../../../../../../.." + secret,
            secret,
            "file://" + secret,
            "%2E%2E/secret" + extension,
            "sub/../../secret" + extension,
            "out" + extension,
            "fifo",
            "loop-a",
            "folder",
            "empty",
            "/dev/zero",
            "/dev/null",
            "/proc/self/mem",
            extension == ".bin" ? "in-link.bin" : "in" + extension,
            "./in" + extension,
            "folder/../in" + extension,
            ""};
}

// The secrets in a loaded scene: geometry at kSecretCoordinate, a material of kSecretColor, a
// texture of kSecretTexel only.
inline void check_nothing_read_outside(const Scene& scene) {
    for (const Mesh& mesh : scene.meshes)
        for (const glm::vec3& p : mesh.positions)
            if (p.x == kSecretCoordinate || p.y == kSecretCoordinate || p.z == kSecretCoordinate)
                fail("a position from secret.bin, outside the model's folder");
    for (const Material& m : scene.materials) {
        if (m.base_color.x == kSecretColor[0] && m.base_color.y == kSecretColor[1] &&
            m.base_color.z == kSecretColor[2])
            fail("material '" + m.name + "' from secret.mtl, outside the model's folder");
        for (const auto& texture : {m.base_color_texture, m.opacity_texture}) {
            if (texture == nullptr || texture->levels() == 0) continue;
            const std::span<const std::uint8_t> rgba = texture->level_rgba(0);
            bool all_secret = !rgba.empty();
            for (std::size_t i = 0; i + 3 < rgba.size() && all_secret; i += 4)
                all_secret = std::equal(kSecretTexel.begin(), kSecretTexel.end(),
                                        rgba.begin() + std::ptrdiff_t(i));
            if (all_secret) fail("a texture from secret.png, outside the model's folder");
        }
    }
}

// A refusal: one line naming the file; a budget's refusal names a LoadOptions field.
inline void check_load_refusal(const InputError& e, const std::string& file) {
    check_input_error(e, file);
    if (const auto* limit = dynamic_cast<const LimitExceeded*>(&e)) {
        static const std::set<std::string> fields{"max_instances",          "max_triangles",
                                                  "max_file_bytes",         "max_geometry_bytes",
                                                  "max_triangulation_work", "max_materials"};
        if (!fields.contains(limit->limit())) fail("LimitExceeded names '" + limit->limit() + "'");
    }
    for (const char* internal : {"aiMesh", "No suitable reader", "Failed to determine"})
        if (e.cause().find(internal) != std::string::npos &&
            e.cause().find("(Assimp: ") == std::string::npos)
            fail("Assimp's internals as the cause: " + std::string(e.what()));
}

// The generated model at `path` through load_scene, checked: refused with one line naming it,
// or a scene that keeps load.hpp's promises, holds nothing from outside its folder (unless
// allowed) and renders. The scene, or nothing when refused.
inline std::optional<Scene> load_reference_model(const std::filesystem::path& path,
                                                 const LoadOptions& options) {
    Scene scene;
    std::vector<std::string> warnings;
    try {
        scene = load_scene(path, options, &warnings);
    } catch (const InputError& e) {
        check_load_refusal(e, path.string());
        return std::nullopt;
    }
    check_loaded_scene(scene, warnings);
    if (!options.allow_outside_references) check_nothing_read_outside(scene);
    check_renders(scene, "a loaded scene");
    return scene;
}

}  // namespace zraster::fuzz
