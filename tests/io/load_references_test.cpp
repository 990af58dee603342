// A model's external references (glTF buffers, OBJ material libraries and textures) are read
// only from regular files inside the model's folder, once symbolic links are followed, unless
// LoadOptions::allow_outside_references says otherwise; FIFOs and devices never.
#include <zraster/load.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <string>

#include "io/io_test_util.hpp"
#include "io/load_with_warnings.hpp"
#include "io/obj_parser.hpp"
#include "support/test_support.hpp"

namespace zraster {
namespace {

// One triangle whose positions are the 36 bytes of `uri`.
std::string triangle_gltf(const std::string& uri) {
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
           R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
           R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
           R"("min":[0,0,0],"max":[1,1,0]}],"bufferViews":[{"buffer":0,"byteLength":36}],)"
           R"("buffers":[{"uri":")" +
           uri + R"(","byteLength":36}]})";
}

std::string triangle_bytes() {
    const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    return std::string(reinterpret_cast<const char*>(xyz), sizeof xyz);
}

// dir/model/ holds the models; dir/outside.bin, dir/outside.mtl and dir/outside.png lie beside.
std::filesystem::path fixture(const std::string& name) {
    const auto dir = test::temp_dir(name);
    std::filesystem::create_directory(dir / "model");
    test::write_bytes(dir / "outside.bin", triangle_bytes());
    test::write_bytes(dir / "model" / "inside.bin", triangle_bytes());
    test::write_bytes(dir / "outside.mtl", "newmtl red\nKd 1 0 0\n");
    return dir;
}

LoadOptions in_process(bool allow_outside = false) {
    LoadOptions o;
    o.isolation = LoadIsolation::InProcess;
    o.allow_outside_references = allow_outside;
    return o;
}

TEST(LoadReferences, GltfBufferInsideTheFolderLoads) {
    const auto dir = fixture("refs-inside");
    test::write_bytes(dir / "model" / "m.gltf", triangle_gltf("inside.bin"));
    EXPECT_EQ(load_scene(dir / "model" / "m.gltf", in_process()).triangle_count(), 1u);
}

TEST(LoadReferences, GltfBufferOutsideTheFolderIsRefusedByName) {
    const auto dir = fixture("refs-outside");
    const auto model = dir / "model" / "m.gltf";
    test::write_bytes(model, triangle_gltf("../outside.bin"));
    for (const LoadIsolation isolation : {LoadIsolation::InProcess, LoadIsolation::WorkerProcess}) {
        LoadOptions o = in_process();
        o.isolation = isolation;
        test::expect_input_error([&] { load_scene(model, o); }, model,
                                 "../outside.bin' is outside the model's folder");
        test::expect_input_error([&] { load_scene(model, o); }, model,
                                 "--allow-outside-references");
    }
    EXPECT_EQ(load_scene(model, in_process(true)).triangle_count(), 1u);
}

// glTF URIs may carry %XX escapes: "my%20model.bin" names "my model.bin" (the name as written
// first: a file may have a '%' in its name), and an escaped "../" is outside like any other.
TEST(LoadReferences, GltfBufferUrisAreReadWithTheirEscapesDecoded) {
    const auto dir = fixture("refs-escapes");
    test::write_bytes(dir / "model" / "my model.bin", triangle_bytes());
    test::write_bytes(dir / "model" / "100%25.bin", triangle_bytes());
    const auto spaced = dir / "model" / "spaced.gltf";
    test::write_bytes(spaced, triangle_gltf("my%20model.bin"));
    const auto literal = dir / "model" / "literal.gltf";
    test::write_bytes(literal, triangle_gltf("100%25.bin"));
    const auto escaped_up = dir / "model" / "up.gltf";
    test::write_bytes(escaped_up, triangle_gltf("%2e%2e/outside.bin"));
    for (const LoadIsolation isolation : {LoadIsolation::InProcess, LoadIsolation::WorkerProcess}) {
        LoadOptions o = in_process();
        o.isolation = isolation;
        EXPECT_EQ(load_scene(spaced, o).triangle_count(), 1u);
        EXPECT_EQ(load_scene(literal, o).triangle_count(), 1u);
        test::expect_input_error([&] { load_scene(escaped_up, o); }, escaped_up,
                                 "../outside.bin' is outside the model's folder");
    }
}

// An escaped NUL would end the name where the system reads it ("ok.bin%00../x" opened ok.bin):
// such a URI is taken as written, a file that does not exist.
TEST(LoadReferences, AnEscapedNulIsNotDecoded) {
    const auto dir = fixture("refs-escaped-nul");
    test::write_bytes(dir / "model" / "ok.bin", triangle_bytes());
    const auto model = dir / "model" / "nul.gltf";
    test::write_bytes(model, triangle_gltf("ok.bin%00../outside.bin"));
    for (const LoadIsolation isolation : {LoadIsolation::InProcess, LoadIsolation::WorkerProcess}) {
        LoadOptions o = in_process();
        o.isolation = isolation;
        test::expect_input_error([&] { load_scene(model, o); }, model,
                                 "'ok.bin%00../outside.bin', is missing or cannot be read");
    }
}

TEST(LoadReferences, AbsolutePathsAndSymbolicLinksOutAreRefused) {
    const auto dir = fixture("refs-links");
    // An absolute URI (Assimp 5.2 joins it to the model's folder when the model's path is
    // absolute, so it is then merely missing): never read.
    const auto absolute = dir / "model" / "absolute.gltf";
    test::write_bytes(absolute, triangle_gltf((dir / "outside.bin").string()));
    EXPECT_THROW(load_scene(absolute, in_process()), InputError);
    std::filesystem::create_symlink(dir / "outside.bin", dir / "model" / "link.bin");
    const auto linked = dir / "model" / "linked.gltf";
    test::write_bytes(linked, triangle_gltf("link.bin"));
    test::expect_input_error([&] { load_scene(linked, in_process()); }, linked,
                             "is outside the model's folder");
    // A link that stays inside is fine.
    std::filesystem::create_symlink(dir / "model" / "inside.bin", dir / "model" / "in-link.bin");
    const auto inner = dir / "model" / "inner.gltf";
    test::write_bytes(inner, triangle_gltf("in-link.bin"));
    EXPECT_EQ(load_scene(inner, in_process()).triangle_count(), 1u);
}

TEST(LoadReferences, AFifoIsRefusedNotWaitedOn) {
    const auto dir = fixture("refs-fifo");
    ASSERT_EQ(::mkfifo((dir / "model" / "fifo.bin").c_str(), 0600), 0);
    const auto model = dir / "model" / "fifo.gltf";
    test::write_bytes(model, triangle_gltf("fifo.bin"));
    for (const bool allow : {false, true})
        test::expect_input_error([&] { load_scene(model, in_process(allow)); }, model,
                                 "is not a regular file");
}

TEST(LoadReferences, ObjLibrariesAndTexturesOutsideAreNotReadWithAWarning) {
    const auto dir = fixture("refs-obj");
    const auto model = dir / "model" / "m.obj";
    test::write_bytes(model,
                      "mtllib ../outside.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");
    const io::LoadedScene fast = test::load_with_warnings(model, in_process());
    const io::LoadedScene assimp = io::load_scene_with_assimp(model, in_process());
    for (const io::LoadedScene* loaded : {&fast, &assimp}) {
        ASSERT_FALSE(loaded->warnings.empty());
        EXPECT_NE(loaded->warnings[0].find("material library '../outside.mtl' not read"),
                  std::string::npos)
            << loaded->warnings[0];
        EXPECT_NE(loaded->warnings[0].find("is outside the model's folder"), std::string::npos)
            << loaded->warnings[0];
        EXPECT_EQ(loaded->scene.materials.size(), 1u);  // the default material only
    }
    EXPECT_EQ(fast.warnings, assimp.warnings);
    // Allowed: the library's red material is read.
    std::vector<std::string> allowed_warnings;
    const Scene allowed = load_scene(model, in_process(true), &allowed_warnings);
    EXPECT_EQ(allowed.materials.size(), 2u);
    EXPECT_TRUE(allowed_warnings.empty()) << allowed_warnings[0];

    // A texture outside: the material keeps its color, with a warning naming the file.
    test::write_bytes(dir / "model" / "tex.mtl", "newmtl t\nKd 1 1 1\nmap_Kd ../outside.png\n");
    test::write_bytes(dir / "outside.png", "not read anyway");
    const auto textured = dir / "model" / "t.obj";
    test::write_bytes(
        textured, "mtllib tex.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl t\nf 1/1 2/1 3/1\n");
    std::vector<std::string> t_warnings;
    const Scene t = load_scene(textured, in_process(), &t_warnings);
    ASSERT_EQ(t_warnings.size(), 1u);
    EXPECT_NE(t_warnings[0].find("texture '../outside.png' not read"), std::string::npos)
        << t_warnings[0];
    EXPECT_EQ(t.materials.at(1).base_color_texture, nullptr);
}

// What the loader read besides the model is reported (canonical), so that a command can keep its
// outputs off it; what it refused is not.
// The files a model names that exist: read, or refused for lying outside the folder (an output
// must not replace those either).
TEST(LoadReferences, FilesReadAreReported) {
    const auto dir = fixture("refs-files-read");
    const auto folder = std::filesystem::canonical(dir / "model");
    const std::vector<std::filesystem::path> obj_named{
        folder / "in.mtl", std::filesystem::canonical(dir) / "outside.mtl"};
    test::write_bytes(dir / "model" / "m.gltf", triangle_gltf("inside.bin"));
    test::write_bytes(dir / "model" / "in.mtl", "newmtl red\nKd 1 0 0\n");
    test::write_bytes(
        dir / "model" / "m.obj",
        "mtllib in.mtl\nmtllib ../outside.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\n"
        "f 1 2 3\n");
    for (const LoadIsolation isolation : {LoadIsolation::InProcess, LoadIsolation::WorkerProcess}) {
        LoadOptions options;
        options.isolation = isolation;
        std::vector<std::filesystem::path> gltf_files, obj_files;
        load_scene(dir / "model" / "m.gltf", options, nullptr, &gltf_files);
        EXPECT_EQ(gltf_files, std::vector<std::filesystem::path>{folder / "inside.bin"});
        load_scene(dir / "model" / "m.obj", options, nullptr, &obj_files);
        EXPECT_EQ(obj_files, obj_named);
    }
    // Assimp's OBJ path reports the same as zraster's reader.
    EXPECT_EQ(io::load_scene_with_assimp(dir / "model" / "m.obj", in_process()).files_read,
              obj_named);
}

// The triangle of triangle_gltf("inside.bin") with a base-color texture whose image is `uri`.
std::string textured_gltf(const std::string& uri) {
    std::string text = triangle_gltf("inside.bin");
    const std::string attributes = R"("attributes":{"POSITION":0}})";
    text.replace(text.find(attributes), attributes.size(),
                 R"("attributes":{"POSITION":0},"material":0})");
    text.pop_back();  // the closing brace
    return text + R"(,"materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}],)" +
           R"("textures":[{"source":0}],"images":[{"uri":")" + uri + R"("}]})";
}

// In model/: a loop of links, a FIFO, a directory; outside.* beside model/. Each refusal says its
// own cause; only "outside the model's folder" names the flag that lifts it, and only where
// lifting it would help.
TEST(LoadReferences, EachRefusalSaysItsCauseAndOnlyOutsideNamesTheFlag) {
    const auto dir = fixture("refs-causes");
    const auto model_dir = dir / "model";
    std::filesystem::create_symlink("loop-b", model_dir / "loop-a");
    std::filesystem::create_symlink("loop-a", model_dir / "loop-b");
    ASSERT_EQ(::mkfifo((model_dir / "fifo").c_str(), 0600), 0);
    std::filesystem::create_directory(model_dir / "folder");
    // Outside the folder and a device: the flag would not help, so it is not named.
    std::filesystem::create_symlink("/dev/zero", model_dir / "zero");
    struct Case {
        std::string name, cause;
        bool advice;
    };
    const Case cases[] = {
        {"loop-a", "is a loop of symbolic links", false},
        {"fifo", "is not a regular file (a FIFO, socket or device)", false},
        {"zero", "is not a regular file (a FIFO, socket or device)", false},
        {"folder", "is a directory", false},
        {"../outside.bin", "is outside the model's folder", true},
    };
    const std::string flag = "--allow-outside-references";
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        for (const bool allow : {false, true}) {
            const bool advice = c.advice && !allow;
            // A glTF buffer: an error.
            const auto buffer = model_dir / "buffer.gltf";
            test::write_bytes(buffer, triangle_gltf(c.name));
            if (c.advice && allow) {
                EXPECT_EQ(load_scene(buffer, in_process(allow)).triangle_count(), 1u);
            } else {
                test::expect_input_error([&] { load_scene(buffer, in_process(allow)); }, buffer,
                                         "'" + (model_dir / c.name).string() + "' " + c.cause);
                try {
                    load_scene(buffer, in_process(allow));
                } catch (const InputError& e) {
                    EXPECT_EQ(e.cause().find(flag) != std::string::npos, advice) << e.what();
                }
            }
            if (c.advice && allow) continue;  // read: outside.bin is no image, another warning
            // A glTF image, an OBJ material library and an OBJ texture: warnings.
            const auto image = model_dir / "image.gltf";
            test::write_bytes(image, textured_gltf(c.name));
            test::write_bytes(model_dir / "m.mtl", "newmtl t\nKd 1 1 1\nmap_Kd " + c.name + "\n");
            const auto library = model_dir / "library.obj";
            test::write_bytes(
                library, "mtllib " + c.name + "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl t\nf 1 2 3\n");
            const auto texture = model_dir / "texture.obj";
            test::write_bytes(texture,
                              "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl t\n"
                              "f 1/1 2/1 3/1\n");
            for (const auto& path : {image, library, texture}) {
                SCOPED_TRACE(path.filename().string());
                std::vector<std::string> warnings;
                load_scene(path, in_process(allow), &warnings);
                ASSERT_EQ(warnings.size(), 1u);
                EXPECT_NE(warnings[0].find(c.cause), std::string::npos) << warnings[0];
                EXPECT_EQ(warnings[0].find(flag) != std::string::npos, advice) << warnings[0];
                EXPECT_EQ(warnings[0].find("not found"), std::string::npos) << warnings[0];
            }
        }
    }
    // A missing file is "not found", with no advice either.
    const auto missing = model_dir / "missing.obj";
    test::write_bytes(model_dir / "m.mtl", "newmtl t\nKd 1 1 1\nmap_Kd nothing.png\n");
    test::write_bytes(missing,
                      "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl t\nf 1/1 2/1 3/1\n");
    std::vector<std::string> warnings;
    load_scene(missing, in_process(), &warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("texture 'nothing.png' not found"), std::string::npos)
        << warnings[0];
    // Without read permission (meaningless for root, who reads anything).
    if (::geteuid() != 0) {
        test::write_bytes(model_dir / "secret.png", "x");
        std::filesystem::permissions(model_dir / "secret.png", std::filesystem::perms::none);
        test::write_bytes(model_dir / "m.mtl", "newmtl t\nKd 1 1 1\nmap_Kd secret.png\n");
        warnings.clear();
        load_scene(missing, in_process(), &warnings);
        ASSERT_EQ(warnings.size(), 1u);
        EXPECT_NE(warnings[0].find("cannot be read (Permission denied)"), std::string::npos)
            << warnings[0];
        EXPECT_EQ(warnings[0].find(flag), std::string::npos) << warnings[0];
    }
}

// Image URIs Assimp drops without a word (empty, a data: URI it cannot decode, one of no data)
// warn as a texture not found does.
TEST(LoadReferences, ImageUrisTheImporterDropsWarn) {
    const auto dir = fixture("refs-image-uris");
    const std::pair<const char*, const char*> cases[] = {
        {"", "image 0's uri '' is empty: its texture is not used"},
        {"data:image/png;base64,", "image 0's uri 'data:image/png;base64,' holds no data"},
        {"data:../outside.png", "image 0's uri 'data:../outside.png' is not a base64 data URI"},
        {"ok.png%00../outside.png", "texture 'ok.png%00../outside.png' not found"},
    };
    int k = 0;
    for (const auto& [uri, warning] : cases) {
        SCOPED_TRACE(uri);
        const auto model = dir / "model" / ("m" + std::to_string(k++) + ".gltf");
        test::write_bytes(model, textured_gltf(uri));
        for (const LoadIsolation isolation :
             {LoadIsolation::InProcess, LoadIsolation::WorkerProcess}) {
            LoadOptions o = in_process();
            o.isolation = isolation;
            std::vector<std::string> warnings;
            load_scene(model, o, &warnings);
            ASSERT_EQ(warnings.size(), 1u);
            EXPECT_NE(warnings[0].find(warning), std::string::npos) << warnings[0];
        }
    }
}

}  // namespace
}  // namespace zraster
