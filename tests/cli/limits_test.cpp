// Requests past the limits (RELIABILITY.md): a 10^6 x 10^6 image, images over --max-pixels, and
// files claiming 2^40 faces are refused quickly with exit status 2, one line naming the option or
// file, no output file, and (outside sanitizer builds, whose shadow memory needs terabytes of
// address space) within a 2 GiB address-space limit: no big allocation was attempted.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
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
    FILE* pipe = popen(command.c_str(), "r");
    std::string out;
    std::array<char, 4096> buffer;
    while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe))
        out.append(buffer.data(), n);
    const int status = pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
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

}  // namespace
}  // namespace zraster::test
