// Requests past the limits (RELIABILITY.md): a 10^6 x 10^6 image, images over --max-pixels, and
// files claiming 2^40 faces are refused quickly with exit status 2, one line naming the option or
// file, no output file, and (outside sanitizer builds, whose shadow memory needs terabytes of
// address space) within a 2 GiB address-space limit: no big allocation was attempted.
#include <zraster/image_io.hpp>
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <thread>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

#include "support/test_support.hpp"

namespace zraster::test {
namespace {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

// Runs zraster in `dir` under `ulimit -v` (2 GiB; none in sanitizer builds), stdout and stderr
// together.
CommandResult run_limited(const std::string& arguments, const std::filesystem::path& dir) {
    std::string command = "cd '" + dir.string() + "' && ";
    if (!kSanitized) command += "ulimit -v 2097152 && ";
    command += std::string("'") + ZRASTER_CLI + "' " + arguments + " 2>&1 </dev/null";
    return run_shell_line(command);
}

// Expects exit 2 within 5 s, one line of output containing `message`, and no out.png.
void expect_refused(const std::filesystem::path& dir, const std::string& arguments,
                    const std::string& message) {
    SCOPED_TRACE(arguments);
    const auto start = std::chrono::steady_clock::now();
    const CommandResult r = run_limited(arguments, dir);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

void write(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

TEST(CliLimits, ImageSizes) {
    const auto dir = temp_dir("cli-limits-size");
    expect_refused(dir, "render builtin:cube --size 1000000x1000000 -o out.png",
                   "zraster: --size: size 1000000x1000000 out of range (1..16384 per side)");
    expect_refused(dir, "render builtin:cube --size 16384x16384 -o out.png",
                   "zraster: --size: 16384x16384 is 268435456 pixels, more than --max-pixels "
                   "67108864");
    expect_refused(dir, "render builtin:cube --size 20x20 --max-pixels 399 -o out.png",
                   "more than --max-pixels 399");
    expect_refused(dir, "render builtin:cube --size 20x20 --max-pixels -5 -o out.png",
                   "--max-pixels");
    const CommandResult ok = run_zraster(
        "render builtin:cube --size 20x20 --max-pixels 400 -o "
        "out.png",
        dir);
    EXPECT_EQ(ok.exit_code, 0) << ok.output;
    // The frame's tile records, named with the scene and the flag.
    std::filesystem::remove(dir / "out.png");
    expect_refused(dir, "render soup:2000 --size 64x64 --max-bin-bytes 4096 -o out.png",
                   "(RenderLimits::max_bin_bytes): large triangles drawn over each other many "
                   "times, or a frame too large for them; raise it with --max-bin-bytes N");
    const CommandResult bins =
        run_zraster("render soup:2000 --size 64x64 --max-bin-bytes 4096 -o out.png", dir);
    EXPECT_EQ(bins.output.rfind("zraster: soup:2000: binning needs ", 0), 0u) << bins.output;
}

// Every numeric option has a range: past it, a clear refusal (or, for thread counts, a clamp
// with a warning), never a crash inside a library.
TEST(CliLimits, NumbersOutOfRange) {
    const auto dir = temp_dir("cli-limits-numbers");
    for (const char* threads : {"2147483647", "10000000", "100000000"}) {
        const CommandResult r = run_limited(
            std::string("render builtin:cube --size 32x24 -o out.png --threads ") + threads, dir);
        EXPECT_EQ(r.exit_code, 0) << threads << ": " << r.output;
        EXPECT_NE(r.output.find(std::string("warning: --threads ") + threads +
                                " is more than 4 times the"),
                  std::string::npos)
            << r.output;
        EXPECT_TRUE(std::filesystem::exists(dir / "out.png"));
        std::filesystem::remove(dir / "out.png");
    }
    expect_refused(dir, "render builtin:cube -o out.png --threads -1",
                   "zraster: --threads: must be >= 0 (0: every hardware thread), not -1");
    expect_refused(dir, "bench builtin:cube --frames 1 --warmup 2147483647",
                   "zraster: --warmup: must be in 0..1000000, not 2147483647");
    expect_refused(dir, "bench builtin:cube --frames 2000000", "zraster: --frames: must be in");
    // Within range, but more work than one run takes: 10^6 frames of 4096x4096, or of 1x1 (each
    // frame has its fixed costs).
    expect_refused(dir, "bench builtin:cube --size 4096x4096 --frames 1000000",
                   "zraster: --frames: 1000000 frames and 2 warmup frames of 4096x4096 with 12 "
                   "triangles are more work than bench takes in one run (at most 1020 frames of "
                   "these): fewer frames or a smaller --size");
    expect_refused(dir, "bench builtin:cube --size 1x1 --frames 1000000",
                   "(at most 343508 frames of these)");
    const CommandResult bench = run_limited(
        "bench builtin:cube --frames 1 --warmup 0 --threads 2147483647 --size 16x16", dir);
    EXPECT_EQ(bench.exit_code, 0) << bench.output;
    EXPECT_NE(bench.output.find("warning: --threads 2147483647"), std::string::npos)
        << bench.output;
    expect_refused(dir, "render builtin:cube -o out.png --orbit 30,20,3 --eye 1,2,3",
                   "zraster: --orbit: and --eye both place the camera");
    expect_refused(dir, "render builtin:cube -o out.png --clip-plane 0,0,0,-1",
                   "zraster: --clip-plane: the normal A,B,C of '0,0,0,-1' is zero");
}

// A mesh of 100,000 vertices placed 1,001 times: the camera fit would copy 100.1 million world
// positions (1.2 GB; a million-vertex mesh placed a thousand times asked for 12 GB and ended in
// "out of memory"). Refused before the copy, naming the limit, by render, bench and svg alike.
TEST(CliLimits, InstancedVerticesPastTheLimitAreRefusedBeforeTheCameraFit) {
    const auto dir = temp_dir("cli-limits-instanced");
    constexpr int kVertices = 100'000;
    std::string bin(std::size_t(kVertices) * 12 + 12, '\0');
    const float corner[3] = {1.0f, 0.0f, 0.0f}, top[3] = {0.0f, 1.0f, 0.0f};
    std::memcpy(&bin[std::size_t(kVertices - 2) * 12], corner, 12);
    std::memcpy(&bin[std::size_t(kVertices - 1) * 12], top, 12);
    const std::uint32_t indices[3] = {0, kVertices - 2, kVertices - 1};
    std::memcpy(&bin[std::size_t(kVertices) * 12], indices, 12);
    write(dir / "v.bin", bin);
    std::string children = "0";
    for (int i = 1; i < 1001; ++i) children += ",0";
    write(dir / "m.gltf",
          R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[1]}],)"
          R"("nodes":[{"mesh":0},{"children":[)" +
              children +
              R"(]}],)"
              R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)"
              R"("accessors":[{"bufferView":0,"componentType":5126,"count":100000,"type":"VEC3",)"
              R"("min":[0,0,0],"max":[1,1,0]},{"bufferView":1,"componentType":5125,"count":3,)"
              R"("type":"SCALAR"}],"bufferViews":[{"buffer":0,"byteLength":1200000},)"
              R"({"buffer":0,"byteOffset":1200000,"byteLength":12}],)"
              R"("buffers":[{"byteLength":1200012,"uri":"v.bin"}]})");
    for (const char* command :
         {"render m.gltf -o out.png --size 16x16",
          "bench m.gltf --frames 1 --warmup 0 --size 16x16", "svg m.gltf -o out.svg --size 16x16"})
        expect_refused(dir, command,
                       "m.gltf: 100100000 vertices over all instances (the meshes times their "
                       "placements), more than the renderer's limit of 100000000");
}

// More threads than the hardware's (up to 4 times) are used as asked, without oneTBB's own
// warning about its worker limit.
TEST(CliLimits, MoreThreadsThanTheHardwareAreHonouredQuietly) {
    const auto dir = temp_dir("cli-limits-threads");
    const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
    for (const char* visibility : {"zbuffer", "abuffer"}) {
        const CommandResult r =
            run_limited(std::string("render builtin:cube --size 32x24 -o out.png --visibility ") +
                            visibility + " --threads " + std::to_string(hardware + 1),
                        dir);
        EXPECT_EQ(r.exit_code, 0) << r.output;
        EXPECT_EQ(r.output, "") << r.output;
    }
    // batch: one job of them all (a oneTBB warning leaked there).
    write(dir / "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const CommandResult batch =
        run_limited("batch tri.obj --size 8x8 -o out.batch --progress none --jobs 1 --threads " +
                        std::to_string(hardware * 4),
                    dir);
    EXPECT_EQ(batch.exit_code, 0) << batch.output;
    EXPECT_EQ(batch.output.find("TBB"), std::string::npos) << batch.output;
}

// An empty value is refused, not taken as "not given" (CLI11 would draw with the default), for
// every subcommand; and a newline in a name does not split the one line of a refusal.
TEST(CliLimits, EmptyValuesAndNewlinesInNames) {
    const auto dir = temp_dir("cli-limits-empty");
    for (const char* arguments :
         {"render builtin:cube -o out.png --fovy ''",
          "render builtin:cube -o out.png --near=", "bench builtin:cube --frames 1 --warmup ''",
          "svg builtin:cube -o out.png --precision ''", "render '' -o out.png"})
        expect_refused(dir, arguments, ": an empty value (give one, or leave the option out)");
    expect_refused(dir, "render builtin:cube -o out.png --fovy ''",
                   "zraster: after --fovy: an empty value");
    expect_refused(dir, "bench builtin:cube --frames 1 --size 16384x16384",
                   "zraster: --size: 16384x16384 is 268435456 pixels, more than the renderer's "
                   "limit of 67108864");
    // Flags that would silently overrule one another.
    expect_refused(dir, "render builtin:cube -o out.png --msaa", "zraster: --msaa: needs --aa N");
    expect_refused(dir, "render builtin:cube -o out.png --ortho --fovy 30",
                   "zraster: --fovy: has no effect with --ortho");
    expect_refused(dir, "render builtin:cube -o out.png --infinite-far --far 10",
                   "zraster: --far: with --infinite-far the far plane is at infinity");
    expect_refused(dir, "render builtin:cube -o out.png --no-cull --cull back",
                   "zraster: --no-cull: and --cull back both set the culling");
    expect_refused(dir, "render builtin:cube -o out.png --size 3840x2160 --aa 8",
                   "zraster: --aa: 8 times --size 3840x2160 is more than 16384 pixels a side");
    expect_refused(dir, "render builtin:cube -o out.png --size 4000x4000 --aa 4",
                   "zraster: --aa: 4 times --size 4000x4000 is 256000000 pixels, more than "
                   "--max-pixels");
    expect_refused(dir, "render \"$(printf 'missing\\nfile.obj')\" -o out.png",
                   "zraster: missing file.obj: file not found");
}

// A flag that would change nothing in the frame the others ask for is refused by name; a depth
// compare that nothing passes is drawn, with a warning saying why the image is empty.
// A camera or clip planes that leave nothing of the scene in view: the background, with a
// warning giving the counts; a frame showing something says nothing.
TEST(CliLimits, AFrameWithNothingInViewWarns) {
    const auto dir = temp_dir("cli-limits-nothing-in-view");
    const std::pair<const char*, const char*> cases[] = {
        {"render builtin:cube -o a.png --size 8x8 --near 1e29 --far 1e30",
         "warning: builtin:cube: none of its 12 triangles is in view (1 of 1 instances outside "
         "the view volume, 0 triangles outside it or the clip planes, 0 covering no pixel "
         "center): the image shows only the background\n"},
        {"render builtin:cube -o a.png --size 8x8 --clip-plane 1,0,0,-5",
         "warning: builtin:cube: none of its 12 triangles is in view (0 of 1 instances outside "
         "the view volume, 12 triangles outside it or the clip planes, 0 covering no pixel "
         "center): the image shows only the background\n"},
        {"render builtin:cube -o a.png --size 8x8 --clip-plane 1,0,0,0", ""},
        // In view, but every depth rounds to the cleared far plane.
        {"render builtin:cube -o a.png --size 32x32 --near 1e-20 --far 1e30 --depth-format d16",
         "warning: builtin:cube: 6 triangles in view, but none of their fragments passed the "
         "depth test: the image shows only the background (is --depth-format d16 too coarse for "
         "the near and far planes?)\n"},
        {"render builtin:cube -o a.png --size 32x32 --depth-format d16", ""},
        // In view, but a sliver that covers no pixel center: not the depth test's doing.
        {"render sliver.obj -o a.png --size 32x32",
         "warning: sliver.obj: its 1 triangles in view cover no pixel center (too thin or too "
         "small for --size 32x32): the image shows only the background\n"},
        // The object-space algorithms and supersampling: an image of the background alone.
        {"render builtin:cube -o a.png --size 8x8 --visibility painter --near 1e29 --far 1e30",
         "warning: builtin:cube: nothing of its 12 triangles was drawn: the image shows only the "
         "background (is the camera or a clip plane leaving it out?)\n"},
        {"render builtin:cube -o a.png --size 8x8 --aa 2 --clip-plane 1,0,0,-5",
         "warning: builtin:cube: nothing of its 12 triangles was drawn: the image shows only the "
         "background (is the camera or a clip plane leaving it out?)\n"},
        {"render builtin:cube -o a.png --size 8x8 --visibility warnock", ""},
        // In view, every triangle turned away (the eye inside a closed mesh).
        {"render sphere:500 -o a.png --size 32x32 --eye 0,0,0.1 --target 0,0,-1",
         "warning: sphere:500: the 308 triangles in view all face away from the camera and were "
         "culled (--cull back): the image shows only the background (--cull none draws both "
         "sides)\n"},
        {"render sphere:500 -o a.png --size 32x32 --eye 0,0,0.1 --target 0,0,-1 --cull none", ""},
        // Every surface fully transparent (an OBJ material of d 0).
        {"render clear.obj -o a.png --size 32x32",
         "warning: clear.obj: every surface in it is fully transparent (opacity 0 or below its "
         "alpha cutoff, or vertex colors of alpha 0): the image shows only the background "
         "(--alpha-mode opaque draws them opaque)\n"},
        {"render clear.obj -o a.png --size 32x32 --alpha-mode opaque", ""},
        // A texture of alpha 0 everywhere: drawn fully transparent, not slivers.
        {"render see-through.obj -o a.png --size 32x32",
         "warning: see-through.obj: its 1 triangles in view are drawn fully transparent (their "
         "textures' or colors' alpha is 0 where they cover pixels): the image shows only the "
         "background (--alpha-mode opaque draws them opaque)\n"},
        // Every fragment cut by the alpha test: vertex colors of alpha 0.5, a MASK cutoff of 0.9.
        {"render mask.gltf -o a.png --size 32x32",
         "warning: mask.gltf: every fragment of its 1 triangles in view was cut out by the alpha "
         "test (alpha below its material's cutoff): the image shows only the background "
         "(--alpha-mode opaque draws them opaque)\n"},
        {"render mask.gltf -o a.png --size 32x32 --alpha-mode opaque", ""},
    };
    write(dir / "mask.gltf", R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
                             R"("nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":)"
                             R"({"POSITION":0,"COLOR_0":1},"material":0}]}],"materials":)"
                             R"([{"alphaMode":"MASK","alphaCutoff":0.9}],"accessors":)"
                             R"([{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
                             R"("min":[0,0,0],"max":[1,1,0]},{"bufferView":0,"byteOffset":36,)"
                             R"("componentType":5126,"count":3,"type":"VEC4"}],"bufferViews":)"
                             R"([{"buffer":0,"byteLength":84}],"buffers":[{"uri":"data:)"
                             R"(application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAA)"
                             R"(AAAAAAAAAAgD8AAAAAAACAPwAAAAAAAAAAAAAAPwAAgD8AAAAAAAAAAAAAAD8AAI)"
                             R"(A/AAAAAAAAAAAAAAA/","byteLength":84}]})");
    write(dir / "sliver.obj", "v 0 0 0\nv 1 1.1 0\nv 1 1.1001 0\nf 1 2 3\n");
    const std::vector<std::uint8_t> clear_texels(2 * 2 * 4, 0);
    write_png8(dir / "clear.png", 2, 2, 4, clear_texels);
    write(dir / "see-through.mtl", "newmtl t\nKd 1 1 1\nmap_Kd clear.png\n");
    write(dir / "see-through.obj",
          "mtllib see-through.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 "
          "0\nvt 0 1\nusemtl t\nf 1/1 2/2 3/3\n");
    write(dir / "clear.mtl", "newmtl m\nKd 1 0 0\nd 0\n");
    write(dir / "clear.obj", "mtllib clear.mtl\nusemtl m\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    for (const auto& [arguments, message] : cases) {
        SCOPED_TRACE(arguments);
        const CommandResult r = run_zraster(arguments, dir);
        EXPECT_EQ(r.exit_code, 0);
        EXPECT_EQ(r.output, message);
    }
}

// A path past the system's 4095 bytes: the one line still ends with the cause (the quote is
// cut in its middle, not at its end).
TEST(CliLimits, APathPastTheSystemsLimitKeepsItsCause) {
    const auto dir = temp_dir("cli-limits-long-path");
    std::string path = ".";
    for (int level = 0; level < 17; ++level) path += "/" + std::string(250, 'd');
    for (const std::string flag : {"-o", "--depth-out"}) {
        const std::string output = flag == "-o" ? "" : " -o a.png";
        const CommandResult r = run_zraster(
            "render builtin:cube --size 8x8" + output + " " + flag + " " + path + "/o.png", dir);
        EXPECT_EQ(r.exit_code, 2);
        EXPECT_EQ(r.output.find('\n'), r.output.size() - 1);
        EXPECT_TRUE(
            r.output.ends_with("/o.png: cannot write: the path is 4274 bytes long, more "
                               "than the limit of 4095\n"))
            << r.output.substr(r.output.size() - std::min<std::size_t>(r.output.size(), 200));
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "a.png"));
}

// Flags that change nothing in the scene given (a service may pass them to every file): a
// warning naming the flag and the scene, the image as without them; none where they act.
TEST(CliLimits, FlagsWithoutEffectInTheSceneWarn) {
    const auto dir = temp_dir("cli-limits-no-effect-scene");
    // A transparent triangle (MTL d 0.5), untextured.
    write(dir / "glass.mtl", "newmtl glass\nKd 1 0 0\nd 0.5\n");
    write(dir / "glass.obj",
          "mtllib glass.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl glass\nf 1 2 3\n");
    const std::pair<const char*, const char*> warned[] = {
        {"render builtin:cube -o a.png --size 8x8 --texture-filter nearest",
         "warning: --texture-filter: builtin:cube has no textured surface: the filter changes "
         "nothing\n"},
        {"render builtin:cube -o a.png --size 8x8 --alpha-mode opaque",
         "warning: --alpha-mode opaque: every surface of builtin:cube is opaque already: it "
         "changes nothing\n"},
        {"render glass.obj -o a.png --size 8x8 --texture-filter bilinear",
         "warning: --texture-filter: glass.obj has no textured surface: the filter changes "
         "nothing\n"},
        {"render builtin:sphere -o a.png --size 8x8 --shading flat --interpolation linear",
         "warning: --interpolation linear: with --shading flat, builtin:sphere interpolates "
         "nothing (no texture, no vertex colors, no normal output): it changes nothing\n"},
    };
    for (const auto& [arguments, message] : warned) {
        SCOPED_TRACE(arguments);
        const CommandResult r = run_zraster(arguments, dir);
        EXPECT_EQ(r.exit_code, 0);
        EXPECT_EQ(r.output, message);
    }
    for (const char* arguments : {"render builtin:default -o a.png --size 8x8 --texture-filter "
                                  "nearest",
                                  "render glass.obj -o a.png --size 8x8 --alpha-mode opaque",
                                  "render builtin:sphere -o a.png --size 8x8 --shading flat "
                                  "--interpolation linear --normal-out n.png",
                                  "render builtin:default -o a.png --size 8x8 --shading flat "
                                  "--interpolation linear"}) {
        SCOPED_TRACE(arguments);
        const CommandResult r = run_zraster(arguments, dir);
        EXPECT_EQ(r.exit_code, 0);
        EXPECT_EQ(r.output, "");
    }
}

TEST(CliLimits, FlagsWithoutEffectAreRefused) {
    const auto dir = temp_dir("cli-limits-no-effect");
    const std::pair<const char*, const char*> cases[] = {
        {"render builtin:cube -o out.png --visibility abuffer --no-depth-test",
         "zraster: --no-depth-test: sets the z-buffer's depth test, which --visibility abuffer "
         "does not use\n"},
        {"render builtin:cube -o out.png --visibility bsp --depth-compare greater",
         "zraster: --depth-compare: sets the z-buffer's depth test, which --visibility bsp does "
         "not use\n"},
        {"render builtin:cube -o out.png --visibility painter --depth-format d16",
         "zraster: --depth-format: sets the z-buffer's depth test, which --visibility painter "
         "does not use\n"},
        {"render builtin:cube -o out.png --aa 4 --msaa --no-depth-write",
         "zraster: --no-depth-write: sets the z-buffer's depth test, which --msaa does not use "
         "(its samples keep the nearest surface)\n"},
        {"render builtin:cube -o out.png --visibility painter --reversed-z",
         "zraster: --reversed-z: stores depth reversed, which changes only the --depth-out image "
         "with --visibility painter: give --depth-out, or leave it out\n"},
        {"svg builtin:cube -o out.svg --reversed-z",
         "zraster: --reversed-z: stores depth reversed: svg orders polygons (--order), it keeps "
         "no depth buffer\n"},
        {"render builtin:cube -o out.png --edge-color 255,0,0",
         "zraster: --edge-color: colors the edges of --wireframe or --hidden-line: give one of "
         "them\n"},
        {"render builtin:cube -o out.png --shading unlit --light-dir 0,0,1",
         "zraster: --light-dir: lights nothing with --shading unlit (colors are drawn as they "
         "are)\n"},
        {"render builtin:cube -o out.png --no-textures --texture-filter nearest",
         "zraster: --texture-filter: filters textures, which --no-textures turns off\n"},
        {"render builtin:cube -o out.png --ortho --interpolation linear",
         "zraster: --interpolation: linear: with --ortho every interpolation is linear on screen "
         "already (no perspective to correct for): it changes nothing\n"},
        {"batch builtin:cube -o out.png --visibility warnock --no-depth-test",
         "zraster: --no-depth-test: sets the z-buffer's depth test, which --visibility warnock "
         "does not use\n"},
        {"render builtin:cube -o out.png --visibility painter --occlusion-cull",
         "zraster: --occlusion-cull: is a stage of the z-buffer's pipeline, which --visibility "
         "painter does not use\n"},
        {"render builtin:cube -o out.png --aa 4 --msaa --shading-strategy deferred",
         "zraster: --shading-strategy: is a stage of the z-buffer's pipeline, which --msaa does "
         "not use\n"},
        {"render builtin:cube -o out.png --shading unlit --infinite-viewer",
         "zraster: --infinite-viewer: shapes highlights, which --shading unlit does not draw\n"},
        {"svg builtin:cube -o out.svg --edge-width 2",
         "zraster: --edge-width: styles the outlines --edges draws: give --edges\n"},
        {"svg builtin:cube -o out.svg --edge-color 9,9,9",
         "zraster: --edge-color: styles the outlines --edges draws: give --edges\n"},
        {"svg builtin:cube -o out.svg --depth-compare less",
         "zraster: --depth-compare: sets the z-buffer's depth test: svg orders polygons "
         "(--order), it keeps no depth buffer\n"},
        {"render builtin:cube -o out.png --no-depth-test --depth-format d16",
         "zraster: --depth-format: sets the depth test, which --no-depth-test turns off (nothing "
         "is tested, nothing written)\n"},
        {"render builtin:cube -o out.png --no-depth-test --no-depth-write",
         "zraster: --no-depth-write: sets the depth test, which --no-depth-test turns off "
         "(nothing is tested, nothing written)\n"},
        {"render builtin:cube -o out.png --wireframe --depth-compare always",
         "zraster: --depth-compare: sets the depth test: --wireframe draws every edge, with no "
         "depth test\n"},
        {"render builtin:cube -o out.png --wireframe --light-dir 0,0,1",
         "zraster: --light-dir: shades surfaces, which --wireframe does not fill (it draws the "
         "edges alone)\n"},
        {"render builtin:cube -o out.png --wireframe --no-textures",
         "zraster: --no-textures: sets the surfaces' textures, which --wireframe does not fill\n"},
        {"render builtin:cube -o out.png --view depth --shading flat",
         "zraster: --shading: shades the image, which --view depth replaces\n"},
        {"render builtin:cube -o out.png --view normals --point-light 0,2,0",
         "zraster: --point-light: shades the image, which --view normals replaces\n"},
        {"render builtin:cube -o out.png --visibility warnock --front-to-back",
         "zraster: --front-to-back: is a stage of the z-buffer's pipeline, which --visibility "
         "warnock does not use\n"},
        {"render builtin:cube -o out.png --ortho --infinite-far",
         "zraster: --infinite-far: moves a perspective projection's far plane to infinity: "
         "--ortho keeps its far plane\n"},
        {"render builtin:cube -o out.png --z-out z.npy --sensor kinect --sensor-seed 3",
         "zraster: --sensor-seed: seeds --sensor-noise, which is 0: there is no noise to seed\n"},
    };
    for (const auto& [arguments, message] : cases) {
        SCOPED_TRACE(arguments);
        const CommandResult r = run_zraster(arguments, dir);
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_EQ(r.output, message);
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir));
    // The same flags where they act are taken.
    for (const char* arguments :
         {"render builtin:cube -o a.png --size 8x8 --depth-compare lequal --depth-format d16",
          "render builtin:cube -o a.png --size 8x8 --view hiz --light-dir 0,0,1",
          "render builtin:cube -o a.png --size 8x8 --wireframe --cull none",
          "render builtin:cube -o a.png --size 8x8 --z-out z.npy --sensor kinect --sensor-noise "
          "0.5 --sensor-seed 3",
          "render builtin:cube -o a.png --size 8x8 --aa 2 --depth-compare lequal",
          "render builtin:cube -o a.png --size 8x8 --wireframe --edge-color 255,0,0",
          "render builtin:cube -o a.png --size 8x8 --shading flat --light-dir 0,0,1",
          "svg builtin:cube -o a.svg --edges --edge-width 2 --edge-color 9,9,9"}) {
        SCOPED_TRACE(arguments);
        const CommandResult r = run_zraster(arguments, dir);
        EXPECT_EQ(r.exit_code, 0) << r.output;
        EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
    }
    // Compares that pass nothing against the cleared buffer: drawn (the background), and said.
    for (const auto& [arguments, cause] :
         std::initializer_list<std::pair<const char*, const char*>>{
             {"--reversed-z --depth-compare less",
              "passes nothing nearer than the cleared depth buffer (0, the far plane with "
              "--reversed-z): the image shows only the background; reversed-Z needs greater or "
              "gequal"},
             {"--depth-compare greater",
              "passes nothing nearer than the cleared depth buffer (1, the far plane): the image "
              "shows only the background; greater and gequal need --reversed-z"}}) {
        SCOPED_TRACE(arguments);
        const CommandResult r =
            run_zraster(std::string("render builtin:cube -o w.png --size 8x8 ") + arguments, dir);
        EXPECT_EQ(r.exit_code, 0) << r.output;
        EXPECT_EQ(
            r.output,
            std::string("warning: --depth-compare ") +
                (std::string(arguments).find("less") != std::string::npos ? "less " : "greater ") +
                cause + "\n");
    }
}

// Every camera and lighting number has a range (docs/limits.md), the same for the flags and for
// the cameras of a --views-json file, whose messages name the file, camera and field.
// Whole numbers are decimal: CLI11 alone read "010" as octal 8 and "0x10" as 16.
// Procedural buildings: 16,384 rooms a side (a row of 32,768 was refused by its own cell checks:
// the rooms' float bounds no longer meet the portals exactly) and 65,536 rooms in all.
TEST(CliLimits, BuildingSizes) {
    const auto dir = temp_dir("cli-limits-building");
    for (const char* spec : {"building:1x16385", "building:32768x1", "building:257x256"})
        expect_refused(dir, std::string("render ") + spec + " --size 8x8 -o out.png",
                       std::string("zraster: ") + spec +
                           ": R x C out of range (at least 1 x 1, at most 16384 a side and 65536 "
                           "rooms)\n");
}

TEST(CliLimits, WholeNumbersAreReadInDecimal) {
    const auto dir = temp_dir("cli-limits-decimal");
    const CommandResult ten =
        run_limited("render builtin:cube --size 3x3 --max-pixels 010 -o out.png", dir);
    EXPECT_EQ(ten.exit_code, 0) << ten.output;  // 9 pixels <= 10 (octal 010 is 8)
    std::filesystem::remove(dir / "out.png");
    expect_refused(dir, "render builtin:cube --size 3x3 --max-pixels 0010 --aa 02 -o out.png",
                   "zraster: --aa: 2 times --size 3x3 is 36 pixels, more than --max-pixels 10\n");
    expect_refused(dir, "render builtin:cube --size 3x3 --threads 0x10 -o out.png",
                   "zraster: --threads: expected a whole number in decimal, got '0x10'\n");
    expect_refused(dir, "svg builtin:cube --precision 010 -o out.svg",
                   "zraster: --precision: must be 0..6, not 10\n");
    // Not whole numbers (CLI11 alone called 1e3 "not in range", and '1 ' not convertible).
    expect_refused(dir, "render builtin:cube --max-texture-side 1e3 -o out.png",
                   "zraster: --max-texture-side: expected a whole number, got '1e3'\n");
    expect_refused(dir, "bench builtin:cube --frames '1 '",
                   "zraster: --frames: expected a whole number, got '1 '\n");
    expect_refused(dir, "render builtin:cube --threads 2.0 -o out.png",
                   "zraster: --threads: expected a whole number, got '2.0'\n");
    // Numbers are decimal too (strtod took hex; a trailing space was "Could not convert").
    expect_refused(dir, "render builtin:cube --fovy '60 ' -o out.png",
                   "zraster: --fovy: expected a decimal number, got '60 '\n");
    expect_refused(dir, "render builtin:cube --fovy 0x1p5 -o out.png",
                   "zraster: --fovy: expected a decimal number, got '0x1p5'\n");
    // Digits past the option's type (CLI11: "Could not convert: --threads = ...").
    expect_refused(dir, "render builtin:cube --threads 9223372036854775808 -o out.png",
                   "zraster: --threads: '9223372036854775808' is past the largest number it takes "
                   "(--help gives its range)\n");
    // An option of another command, or a word no option takes (CLI11: "The following arguments
    // were not expected: 4 --aa", reversed and without the command).
    expect_refused(dir, "svg builtin:cube --aa 4 -o out.svg",
                   "zraster: --aa: not an option of zraster svg (zraster svg --help lists its "
                   "options)\n");
    expect_refused(dir, "render builtin:cube -o out.png extra",
                   "zraster: 'extra': an argument zraster render does not take (zraster render "
                   "--help lists what it takes)\n");
    // Out of range, in one wording (CLI11's "Value 0 not in range 1 to 65536"), and NaN, which
    // CLI11's range check let through.
    expect_refused(dir, "render builtin:cube --max-texture-side 0 -o out.png",
                   "zraster: --max-texture-side: '0' is outside its range, 1 to 65536\n");
    for (const char* seconds : {"nan", "-nan", "5s", "0"})
        expect_refused(
            dir, std::string("render builtin:cube --max-load-seconds ") + seconds + " -o out.png",
            std::string("zraster: --max-load-seconds: '") + seconds +
                "' is not a number of seconds from 1 to 1000000\n");
    // An option given twice (CLI11: "At Most 1 required but received 2").
    expect_refused(dir, "render builtin:cube -o out.png -o out.png",
                   "zraster: --output: given 2 times: give it once\n");
}

TEST(CliLimits, CameraNumbersHaveRanges) {
    const auto dir = temp_dir("cli-limits-ranges");
    const std::pair<const char*, const char*> cases[] = {
        {"--orbit 0,0,1e30", "--orbit: distance must be in (0, 1e6] scene radii, not 1e+30"},
        {"--orbit 0,0,1e-300", "--orbit: the eye and the target are the same point"},
        {"--orbit 0,95,1", "--orbit: elevation must be in -90..90 degrees, not 95"},
        {"--orbit 1e7,0,1", "--orbit: azimuth must be in -1e6..1e6 degrees, not 10000000"},
        {"--fovy 1e-9", "--fovy: must be in 0.001..179.999 degrees, not 1e-09"},
        {"--near 1e-30", "--near: must be in 1e-20..1e30 scene units, not 1e-30"},
        {"--far 1e38", "--far: must be in 1e-20..1e30 scene units, not 1e+38"},
        {"--near 5 --far 1", "--near: 5 is not below --far 1: the view needs near < far"},
        // One given, the other from the camera fit (the scene's name was blamed).
        {"--near 1e30",
         "--near: 1e+30 is not below the far plane 5.21347 of the camera: the "
         "view needs near < far (give --far too)"},
        {"--far 1e-20",
         "--far: 1e-20 is not beyond the near plane 1.71473 of the camera: the "
         "view needs near < far (give --near too)"},
        {"--clip-plane 1,0,0,0 --clip-plane 1,0,0,0 --clip-plane 1,0,0,0 --clip-plane 1,0,0,0 "
         "--clip-plane 1,0,0,0 --clip-plane 1,0,0,0 --clip-plane 1,0,0,0",
         "--clip-plane: given 7 times: at most 6 planes"},
        {"--visibility abuffer --aa 16",
         "--aa: with --visibility abuffer must be 1, 2, 4 or 8 (its mask's samples a pixel side)"},
        {"--ortho --ortho-height 1e31",
         "--ortho-height: must be in 1e-20..1e30 scene units, not 1e+31"},
        {"--up 1e-40,0,0", "--up: the direction is zero (or shorter than 1e-30)"},
        {"--up 1e31,0,0", "--up: 1e+31 is beyond the +-1e30 a direction may use"},
        {"--eye 1,2,3 --target 1,2,3", "--target: the eye and the target are the same point"},
        {"--eye 0,0,3 --target 0,0,0 --up 0,0,-2",
         "--target: the up direction is parallel to the view direction (from the eye to the "
         "target)"},
        {"--light-dir 1e300,0,0", "--light-dir: 1e+300 is beyond the +-1e30 a direction may use"},
        {"--point-light 1e39,0,0",
         "--point-light: 1e+39 is beyond the +-1e32 a camera or light may use"},
        {"--clip-plane 1e-40,0,0,0",
         "--clip-plane: the normal A,B,C of '1e-40,0,0,0' is zero: the plane keeps "
         "everything or nothing"},
        {"--clip-plane 1e31,0,0,0", "--clip-plane: 1e+31 is beyond the +-1e30 a direction may use"},
        {"--clip-plane 1,0,0,1e31", "--clip-plane: D = 1e+31 is beyond the +-1e30 a plane may use"},
        {"--intrinsics 1e12,1e12,4,4 --size 8x8",
         "--intrinsics: fx must be in 0.001..1e9 pixels, not 1000000000000"},
        {"--intrinsics 100,100,1e10,4 --size 8x8",
         "--intrinsics: cx must be within +-1e9 pixels, not 10000000000"},
    };
    for (const auto& [flags, message] : cases)
        expect_refused(dir, std::string("render builtin:cube -o out.png ") + flags,
                       std::string("zraster: ") + message + "\n");
    write(dir / "tri.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    const std::pair<const char*, const char*> views[] = {
        {R"([{"orbit": [0, 95, 1]}])",
         "camera 0: \"orbit\": elevation must be in -90..90 degrees, not 95"},
        {R"([{"eye": [1e39, 0, 0], "target": [0, 0, 0]}])",
         "camera 0: \"eye\": 1e+39 is beyond the +-1e32 a camera or light may use"},
        {R"([{"eye": [3, 3, 3], "target": [0, 0, 0], "fovy": 0}])",
         "camera 0: \"fovy\": must be in 0.001..179.999 degrees, not 0"},
        {R"([{"eye": [3, 3, 3], "target": [0, 0, 0], "up": [0, 0, 0]}])",
         "camera 0: \"up\": the direction is zero (or shorter than 1e-30)"},
        {R"([{"eye": [3, 3, 3], "target": [0, 0, 0], "near": 2, "far": 1}])",
         "camera 0: \"near\": must be below \"far\""},
    };
    for (const auto& [json, message] : views) {
        write(dir / "views.json", json);
        const CommandResult r =
            run_limited("batch tri.off --views-json views.json --size 8x8 -o out.batch", dir);
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_EQ(r.output, std::string("zraster: views.json: ") + message + "\n");
        EXPECT_FALSE(std::filesystem::exists(dir / "out.batch"));
    }
    // In range, they render.
    const CommandResult ok = run_limited(
        "render builtin:cube --size 8x8 -o out.png --orbit 1e6,90,1e6 --fovy 0.001 --near 1e-20 "
        "--far 1e30 --up 1e30,0,0 --light-dir 0,1e30,0 --point-light 1e32,0,0",
        dir);
    EXPECT_EQ(ok.exit_code, 0) << ok.output;
}

TEST(CliLimits, FilesClaimingTwoToTheFortyFaces) {
    const auto dir = temp_dir("cli-limits-faces");
    write(dir / "huge.ply",
          "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
          "property float z\nelement face 1099511627776\nproperty list uchar int "
          "vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    expect_refused(dir, "render huge.ply -o out.png",
                   "zraster: huge.ply: truncated or malformed file: the PLY header declares "
                   "1099511627776 face records");
    write(dir / "binary.ply",
          "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
          "property float y\nproperty float z\nelement face 1099511627776\nproperty list uchar "
          "int vertex_indices\nend_header\n" +
              std::string(49, '\0'));
    expect_refused(dir, "render binary.ply -o out.png", "declares 1099511627776 face records");
    write(dir / "huge.off", "OFF\n3 1099511627776 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    expect_refused(dir, "render huge.off -o out.png",
                   "zraster: huge.off: truncated or malformed file: the OFF header declares "
                   "1099511627776 face records");
    // Binary STL counts are 32-bit: the most it can claim is 2^32 - 1 facets.
    std::string stl(80, ' ');
    stl += std::string("\xff\xff\xff\xff", 4);
    stl += std::string(50, '\0');
    write(dir / "huge.stl", stl);
    expect_refused(dir, "render huge.stl -o out.png", "zraster: huge.stl: ");
    write(dir / "huge.gltf",
          R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":12,"uri":)"
          R"("data:application/octet-stream;base64,AAAAAAAAAAAAAAAA"}],"bufferViews":)"
          R"([{"buffer":0,"byteLength":12}],"accessors":[{"bufferView":0,"componentType":5126,)"
          R"("count":1099511627776,"type":"VEC3"}],"meshes":[{"primitives":[{"attributes":)"
          R"({"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0})");
    expect_refused(dir, "render huge.gltf -o out.png", "zraster: huge.gltf: ");
}

// The object-space algorithms' budgets: random triangles as big as the scene, which split
// without end, are refused by the default BSP budget; every budget names its option, and the
// svg command has them too.
// The loader's budgets (LoadOptions) end in the flag that raises them, whether the file was
// refused in the command's process or in the importer's worker process.
TEST(CliLimits, LoaderBudgetsNameTheirFlags) {
    const auto dir = temp_dir("cli-limits-loader");
    std::string nodes = R"({"mesh":0})";
    for (int level = 1; level <= 3; ++level)
        nodes += R"(,{"children":[)" + std::to_string(level - 1) + "," + std::to_string(level - 1) +
                 "]}";
    write(dir / "shared.gltf",
          R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[3]}],"nodes":[)" + nodes +
              R"(],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
              R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
              R"("min":[0,0,0],"max":[1,1,0]}],"bufferViews":[{"buffer":0,"byteLength":36}],)"
              R"("buffers":[{"uri":"data:application/octet-stream;base64,)"
              R"(AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA","byteLength":36}]})");
    write(dir / "two.ply",
          "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
          "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
          "end_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 2\n");
    write(dir / "m.mtl", "newmtl a\nKd 1 0 0\nnewmtl b\nKd 0 1 0\n");
    write(dir / "materials.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
    for (const std::string isolation : {"", "--load-in-process "}) {
        expect_refused(dir, isolation + "render shared.gltf --max-instances 7 -o out.png",
                       "zraster: shared.gltf: the node graph places more than 7 meshes "
                       "(max_instances; nodes sharing children multiply); raise it with "
                       "--max-instances N\n");
        expect_refused(dir, isolation + "render two.ply --max-triangles 1 -o out.png",
                       "zraster: two.ply: too many triangles (2, limit 1); raise it with "
                       "--max-triangles N\n");
        expect_refused(dir, isolation + "info two.ply --max-triangles 1",
                       "zraster: two.ply: too many triangles (2, limit 1); raise it with "
                       "--max-triangles N\n");
        expect_refused(dir, isolation + "render materials.obj --max-materials 1 -o out.png",
                       "zraster: materials.obj: its material libraries define 2 materials, "
                       "more than max_materials (1); raise it with --max-materials N\n");
    }
    EXPECT_EQ(
        run_limited("render materials.obj --max-materials 2 --size 8x8 -o out.png", dir).exit_code,
        0);
    // Within the budgets the same files load.
    const CommandResult r =
        run_limited("render shared.gltf --max-instances 8 --size 8x8 -o out.png", dir);
    EXPECT_EQ(r.exit_code, 0) << r.output;
}

// 400 random triangles in [-1, 1]^3 as ASCII PLY, the same file everywhere (a 64-bit LCG).
void write_random_soup(const std::filesystem::path& path) {
    std::string ply =
        "ply\nformat ascii 1.0\nelement vertex 1200\nproperty float x\n"
        "property float y\nproperty float z\nelement face 400\n"
        "property list uchar int vertex_indices\nend_header\n";
    std::uint64_t state = 12345;
    const auto next = [&] {
        state = state * 6364136223846793005u + 1442695040888963407u;
        return double(state >> 11) / double(std::uint64_t{1} << 53) * 2.0 - 1.0;
    };
    for (int v = 0; v < 1200; ++v) {
        const double x = next(), y = next(), z = next();
        ply += std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
    }
    for (int f = 0; f < 400; ++f)
        ply += "3 " + std::to_string(3 * f) + " " + std::to_string(3 * f + 1) + " " +
               std::to_string(3 * f + 2) + "\n";
    write(path, ply);
}

TEST(CliLimits, VisibilityAlgorithmBudgets) {
    const auto dir = temp_dir("cli-limits-budgets");
    write_random_soup(dir / "soup.ply");
    const std::string render = "render soup.ply --size 160x120 --no-cull -o out.png ";
    expect_refused(dir, render + "--visibility bsp",
                   "zraster: soup.ply: BSP tree: more than 71936 polygons after");
    expect_refused(dir, render + "--visibility bsp", "; raise it with --max-bsp-polygons N");
    expect_refused(dir, render + "--visibility painter --max-painter-comparisons 10000",
                   "zraster: soup.ply: painter's algorithm: more than 10000 polygon comparisons "
                   "for ");
    expect_refused(dir, render + "--visibility painter --max-painter-comparisons 10000",
                   "; raise it with --max-painter-comparisons N");
    expect_refused(dir, render + "--visibility warnock --max-warnock-classifications 5000",
                   "zraster: soup.ply: Warnock's algorithm: more than 5000 polygon-region "
                   "classifications for ");
    expect_refused(dir, render + "--visibility abuffer --max-abuffer-fragments 100",
                   "zraster: soup.ply: A-buffer: more than 100 fragments (polygon-pixel pairs of "
                   "24 bytes, the limit): render fewer pixels or polygons, or raise the limit; "
                   "raise it with --max-abuffer-fragments N");
    expect_refused(dir, render + "--visibility bsp --max-bsp-polygons -3", "--max-bsp-polygons");
    expect_refused(dir, render + "--visibility painter --max-painter-comparisons 1e9",
                   "expected a whole number, got '1e9'");
    // The svg command shares them (no out.svg either).
    const CommandResult svg =
        run_limited("svg soup.ply --size 160x120 --no-cull --order bsp -o out.svg", dir);
    EXPECT_EQ(svg.exit_code, 2) << svg.output;
    EXPECT_NE(svg.output.find("; raise it with --max-bsp-polygons N"), std::string::npos)
        << svg.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.svg"));
    // Raised far enough, the same run is drawn.
    const CommandResult ok =
        run_limited(render + "--visibility warnock --max-warnock-classifications 0", dir);
    EXPECT_EQ(ok.exit_code, 0) << ok.output;

    // The polygons kept by projection and the pixels the back-to-front orders fill: exactly
    // what the run needs passes, one less is refused naming the flag.
    const std::string cube = "render builtin:cube --size 64x64 -o out.png --visibility ";
    const CommandResult counted = run_limited(cube + "painter --stats", dir);
    ASSERT_EQ(counted.exit_code, 0) << counted.output;
    const auto number_after = [&](const std::string& text, const std::string& key) {
        const std::size_t at = text.find(key);
        EXPECT_NE(at, std::string::npos) << text;
        return at == std::string::npos ? 0ull : std::stoull(text.substr(at + key.size()));
    };
    const unsigned long long polygons = number_after(counted.output, "painter: ");
    const unsigned long long filled = number_after(counted.output, "fragments shaded ");
    ASSERT_GT(polygons, 1u);
    ASSERT_GT(filled, 1u);
    std::filesystem::remove(dir / "out.png");
    for (const char* visibility : {"painter", "warnock", "abuffer"}) {
        const std::string flag = " --max-projected-polygons ";
        EXPECT_EQ(run_limited(cube + visibility + flag + std::to_string(polygons), dir).exit_code,
                  0);
        std::filesystem::remove(dir / "out.png");
        expect_refused(dir, cube + visibility + flag + std::to_string(polygons - 1),
                       "more than " + std::to_string(polygons - 1) + " polygons in view");
        expect_refused(dir, cube + visibility + flag + std::to_string(polygons - 1),
                       "; raise it with --max-projected-polygons N");
    }
    for (const char* visibility : {"painter", "bsp"}) {
        const std::string flag = " --max-painted-fragments ";
        EXPECT_EQ(run_limited(cube + visibility + flag + std::to_string(filled), dir).exit_code, 0);
        std::filesystem::remove(dir / "out.png");
        expect_refused(dir, cube + visibility + flag + std::to_string(filled - 1),
                       "more than " + std::to_string(filled - 1) + " pixels filled drawing ");
        expect_refused(dir, cube + visibility + flag + std::to_string(filled - 1),
                       "; raise it with --max-painted-fragments N");
    }
    const CommandResult bsp = run_limited(cube + "bsp --stats", dir);
    ASSERT_EQ(bsp.exit_code, 0) << bsp.output;
    std::filesystem::remove(dir / "out.png");
    // ("bsp: 12 input polygons, 6 nodes, depth 6, 0 splits, 405 classifications")
    const unsigned long long tests = number_after(bsp.output, "splits, ");
    ASSERT_GT(tests, 1u);
    EXPECT_EQ(
        run_limited(cube + "bsp --max-bsp-classifications " + std::to_string(tests), dir).exit_code,
        0);
    std::filesystem::remove(dir / "out.png");
    expect_refused(dir, cube + "bsp --max-bsp-classifications " + std::to_string(tests - 1),
                   "polygon-plane classifications");
    expect_refused(dir, cube + "bsp --max-bsp-classifications " + std::to_string(tests - 1),
                   "; raise it with --max-bsp-classifications N");
    expect_refused(dir, cube + "painter --max-painted-fragments 1.5", "--max-painted-fragments");
    expect_refused(dir, cube + "painter --max-projected-polygons -1", "--max-projected-polygons");
}

// The paths that rasterize every triangle whole (--view overdraw's count, --no-depth-test,
// --msaa) are budgeted by the samples the triangles' bounding boxes cover: exactly what the run
// needs passes, one less is refused naming the scene and the flag.
TEST(CliLimits, CoveredSamplesExactly) {
    const auto dir = temp_dir("cli-limits-covered-samples");
    const std::string cube = "render builtin:cube --size 64x64 -o out.png ";
    for (const char* path : {"--view overdraw", "--no-depth-test", "--aa 4 --msaa"}) {
        SCOPED_TRACE(path);
        const std::string run = cube + path + " --max-covered-samples ";
        const CommandResult counted = run_limited(run + "1", dir);
        ASSERT_EQ(counted.exit_code, 2) << counted.output;
        EXPECT_EQ(counted.output.rfind("zraster: builtin:cube: ", 0), 0u) << counted.output;
        const std::string key = "bounding boxes cover ";
        const std::size_t at = counted.output.find(key);
        ASSERT_NE(at, std::string::npos) << counted.output;
        const unsigned long long needed = std::stoull(counted.output.substr(at + key.size()));
        ASSERT_GT(needed, 1u);
        const CommandResult exact = run_limited(run + std::to_string(needed), dir);
        EXPECT_EQ(exact.exit_code, 0) << exact.output;
        std::filesystem::remove(dir / "out.png");
        expect_refused(dir, run + std::to_string(needed - 1),
                       "more than the limit of " + std::to_string(needed - 1) +
                           " (RenderLimits::max_covered_samples)");
        expect_refused(dir, run + std::to_string(needed - 1),
                       "; raise it with --max-covered-samples N");
    }
    expect_refused(dir, cube + "--view overdraw --max-covered-samples 0", "--max-covered-samples");
    expect_refused(dir, cube + "--msaa --aa 4 --max-covered-samples 1e9",
                   "--max-covered-samples: expected a whole number, got '1e9'");
}

// The frame's memory estimate (RenderLimits::max_frame_bytes) from the command: exactly the
// estimate renders, a byte less is refused naming the scene and the flag, before the camera fit
// copies the scene (its world positions) for render, the classic visibility paths, bench and
// the viewer alike; the flag takes a size.
TEST(CliLimits, FrameMemoryExactly) {
    const auto dir = temp_dir("cli-limits-frame-memory");
    // sphere:2000 placed once; 64x64 targets.
    const Scene scene = make_procedural_scene("sphere:2000");
    const std::uint64_t geometry =
        estimated_frame_bytes(scene.vertex_count(), scene.triangle_count(), 0);
    const std::uint64_t frame =
        estimated_frame_bytes(scene.vertex_count(), scene.triangle_count(), 64 * 64);
    const std::string run = "render sphere:2000 --size 64x64 -o out.png --max-frame-bytes ";
    const CommandResult exact = run_limited(run + std::to_string(frame), dir);
    EXPECT_EQ(exact.exit_code, 0) << exact.output;
    std::filesystem::remove(dir / "out.png");
    expect_refused(dir, run + std::to_string(frame - 1),
                   "zraster: sphere:2000: the frame needs about ");
    expect_refused(dir, run + std::to_string(frame - 1),
                   "; raise it with --max-frame-bytes SIZE (bytes, or with a unit: 512M, 16G)");
    // Before the camera fit: the scene alone is past the limit (no target samples named).
    expect_refused(dir, run + std::to_string(geometry - 1),
                   std::to_string(scene.vertex_count()) + " vertices and " +
                       std::to_string(scene.triangle_count()) + " triangles over all instances)");
    for (const char* other : {"--visibility painter", "--visibility warnock", "--aa 2 --msaa"})
        expect_refused(dir, run + std::to_string(frame - 1) + " " + other,
                       "--max-frame-bytes SIZE");
    expect_refused(dir, "bench sphere:2000 --size 64x64 --frames 1 --max-frame-bytes 1K",
                   "--max-frame-bytes SIZE");
    // Multisampling's sample buffers count: 2896^2 x 64 samples (its pixel limit raised).
    expect_refused(dir,
                   "render builtin:cube --size 2896x2896 --aa 8 --msaa --max-pixels "
                   "9999999999999999999 -o out.png",
                   "536756224 target samples), more than max_frame_bytes (4096 MiB)");
    // A small limit is told in bytes, as given.
    expect_refused(dir, run + "1K", "more than max_frame_bytes (1024 bytes)");
    expect_refused(dir, run + "0", "--max-frame-bytes: must be more than 0 bytes");
    expect_refused(dir, run + "lots",
                   "--max-frame-bytes: expected a size in bytes like 4G, 512M or 1000000, got "
                   "'lots'");
}

// A fragment budget raised past what the machine holds: the A-buffer's allocation fails under
// the 2 GiB address-space limit and the run ends naming the budget (exit 2), not with "out of
// memory" (exit 1). Before, the pool doubled to 3.3 GB and the command said "out of memory".
TEST(CliLimits, AnABufferPastTheMachinesMemoryNamesTheBudget) {
    if (kSanitized) GTEST_SKIP() << "no address-space limit in sanitizer builds";
    const auto dir = temp_dir("cli-limits-abuffer-memory");
    write_random_soup(dir / "soup.ply");
    const CommandResult r = run_limited(
        "render soup.ply --size 4096x4096 --no-cull --aa 2 --visibility abuffer "
        "--max-abuffer-fragments 4000000000 -o out.png",
        dir);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << r.output;
    EXPECT_NE(r.output.find("zraster: soup.ply: A-buffer: out of memory after "), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("the budget max_abuffer_fragments is 4000000000"), std::string::npos)
        << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

// Any other request past the machine's memory (limits raised past their defaults) is the user's
// to change: exit 2 saying what to lower, not exit 1 (an internal error).
TEST(CliLimits, RaisedLimitsPastTheMachinesMemoryAreExitTwo) {
    if (kSanitized) GTEST_SKIP() << "no address-space limit in sanitizer builds";
    const auto dir = temp_dir("cli-limits-out-of-memory");
    const CommandResult r = run_limited(
        "render builtin:cube --size 1024x1024 --aa 16 --max-pixels 9999999999999999999 "
        "--max-bin-bytes 9999999999999999999 --max-frame-bytes 1T -o out.png",
        dir);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_EQ(r.output.rfind("zraster: out of memory: the run needs more than this machine", 0), 0u)
        << r.output;
    EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

// A BSP polygon budget raised past what the process may use (about 400 bytes a polygon at the
// tree's peak) is refused before the tree is built, naming the flag to lower and how far: under
// the 2 GiB address-space limit, 2^31 / 400 = 5,368,709 polygons. (A random soup with every
// budget at its maximum split for 29 s to 6.6 GB, then ran out of memory.)
TEST(CliLimits, ABspBudgetPastTheMachinesMemoryIsRefusedBeforeBuilding) {
    if (kSanitized) GTEST_SKIP() << "no address-space limit in sanitizer builds";
    const auto dir = temp_dir("cli-limits-bsp-memory");
    const std::string bsp = "render builtin:cube --size 64x64 -o out.png --visibility bsp ";
    expect_refused(dir, bsp + "--max-bsp-polygons 9999999999999999999",
                   "zraster: builtin:cube: BSP tree: the budget of 9999999999999999999 polygons "
                   "(max_bsp_polygons) is more than the memory this process may use holds at "
                   "about 400 bytes each: lower --max-bsp-polygons to at most 5368709 (0: "
                   "automatic)");
    const CommandResult exact = run_limited(bsp + "--max-bsp-polygons 5368709", dir);
    EXPECT_EQ(exact.exit_code, 0) << exact.output;
    std::filesystem::remove(dir / "out.png");
    expect_refused(dir, bsp + "--max-bsp-polygons 5368710", "at most 5368709");
}

// Coordinates beyond what single-precision matrices can frame: a triangle at 3e38 (the fitted
// camera overflowed and the image was empty, exit 0) and an eye at 1e39 (the message blamed
// near and far).
TEST(CliLimits, CoordinatesBeyondTheSupportedRange) {
    const auto dir = temp_dir("cli-limits-coordinates");
    write(dir / "far.ply",
          "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
          "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
          "end_header\n3e38 0 0\n0 3e38 0\n0 0 3e38\n3 0 1 2\n");
    expect_refused(dir, "render far.ply -o out.png",
                   "zraster: far.ply: coordinates reach 3e+38, beyond the +-1e30 a camera can "
                   "frame");
    expect_refused(dir, "render builtin:cube --eye 1e39,0,0 -o out.png",
                   "zraster: --eye: 1e39,0,0 is beyond the +-1e32 a camera may use");
    expect_refused(dir, "render builtin:cube --target 0,-2e32,0 -o out.png", "zraster: --target: ");
}

}  // namespace
}  // namespace zraster::test
