// What Assimp changes in a file without failing becomes a load warning in the user's terms.
#include <zraster/load.hpp>

#include "io/io_test_util.hpp"
#include "support/test_support.hpp"

#include <cstdint>
#include <cstring>

namespace zraster {
namespace {

std::string chunk_3ds(std::uint16_t id, const std::string& body) {
    std::string out(6, '\0');
    const std::uint32_t length = static_cast<std::uint32_t>(6 + body.size());
    std::memcpy(out.data(), &id, 2);
    std::memcpy(out.data() + 2, &length, 4);
    return out + body;
}

template <typename T>
std::string bytes_of_values(std::initializer_list<T> values) {
    std::string out;
    for (T v : values) out.append(reinterpret_cast<const char*>(&v), sizeof v);
    return out;
}

// A 3DS file of one triangle (0,0,0) (1,0,0) (0,1,0) whose face names vertices a, b, c.
std::string triangle_3ds(std::uint16_t a, std::uint16_t b, std::uint16_t c) {
    const std::string vertices =
        bytes_of_values<std::uint16_t>({3}) + bytes_of_values<float>({0, 0, 0, 1, 0, 0, 0, 1, 0});
    const std::string faces = bytes_of_values<std::uint16_t>({1, a, b, c, 0});
    const std::string mesh = chunk_3ds(0x4110, vertices) + chunk_3ds(0x4120, faces);
    const std::string object = chunk_3ds(0x4000, std::string("tri", 4) + chunk_3ds(0x4100, mesh));
    const std::string version = bytes_of_values<std::uint32_t>({3});
    return chunk_3ds(0x4D4D, chunk_3ds(0x0002, version) +
                                 chunk_3ds(0x3D3D, chunk_3ds(0x3D3E, version) + object));
}

std::vector<std::string> warnings_of(const std::filesystem::path& path, LoadIsolation isolation) {
    LoadOptions options;
    options.isolation = isolation;
    std::vector<std::string> warnings;
    load_scene(path, options, &warnings);
    return warnings;
}

TEST(AssimpWarnings, ThreeDsFaceIndexPastTheVerticesIsAWarningNotSilence) {
    const auto good =
        test::write_fixture("io-assimp-warnings-good", "good.3ds", triangle_3ds(0, 1, 2));
    const auto bad =
        test::write_fixture("io-assimp-warnings-bad", "bad.3ds", triangle_3ds(0, 1, 9));
    for (const LoadIsolation isolation : {LoadIsolation::InProcess, LoadIsolation::WorkerProcess}) {
        EXPECT_TRUE(warnings_of(good, isolation).empty());
        const std::vector<std::string> warnings = warnings_of(bad, isolation);
        ASSERT_EQ(warnings.size(), 1u);
        EXPECT_EQ(warnings[0], bad.string() +
                                   ": a 3DS face names a vertex past its mesh's vertices: Assimp "
                                   "moved it to the last vertex, the face may be drawn wrong");
    }
}

}  // namespace
}  // namespace zraster
