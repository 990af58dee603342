// OutputFiles: a run's outputs are checked before any work and written all or nothing.
#include <zraster/error.hpp>
#include <zraster/image_io.hpp>
#include <zraster/output_files.hpp>

#include <algorithm>
#include <string>

#include "io/io_test_util.hpp"
#include "support/test_support.hpp"

namespace zraster {
namespace {

std::vector<std::uint8_t> bytes_of(const std::string& text) {
    return {text.begin(), text.end()};
}

// Every name in dir, hidden ones too (temporaries and backups must not be left), sorted.
std::vector<std::string> names_in(const std::filesystem::path& dir) {
    std::vector<std::string> names = test::list_directory(dir);
    std::sort(names.begin(), names.end());
    return names;
}

// The message of the InputError fn throws ("" when it throws none).
template <class Fn>
std::string error_of(Fn&& fn) {
    try {
        fn();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(OutputFiles, WritesEveryOutputAndNothingElse) {
    const auto dir = test::temp_dir("io-outputs-all");
    test::write_bytes(dir / "b.npy", "old");
    OutputFiles out;
    out.check(dir / "a.png", "-o");
    out.check(dir / "b.npy", "--depth-out");
    out.add(dir / "a.png", bytes_of("first"));
    out.add(dir / "b.npy", bytes_of("second"));
    out.commit();
    EXPECT_EQ(test::read_bytes(dir / "a.png"), "first");
    EXPECT_EQ(test::read_bytes(dir / "b.npy"), "second");
    EXPECT_EQ(names_in(dir), (std::vector<std::string>{"a.png", "b.npy"}));
}

TEST(OutputFiles, TheSameFileTwiceIsRefusedWhateverItsSpelling) {
    const auto dir = test::temp_dir("io-outputs-same");
    std::filesystem::create_directory(dir / "sub");
    std::filesystem::create_symlink(dir / "sub", dir / "link");
    OutputFiles out;
    out.check(dir / "x.png", "-o");
    const std::string same = error_of([&] { out.check(dir / "x.png", "--depth-out"); });
    EXPECT_NE(same.find("--depth-out"), std::string::npos) << same;
    EXPECT_NE(same.find("is the same file as -o"), std::string::npos) << same;
    EXPECT_NE(error_of([&] { out.check(dir / "sub" / ".." / "x.png", "--normal-out"); }), "");
    {
        // Relative spellings of one new file.
        const auto cwd = std::filesystem::current_path();
        std::filesystem::current_path(dir);
        OutputFiles relative;
        relative.check("new.png", "-o");
        const std::string dot = error_of([&] { relative.check("./new.png", "--depth-out"); });
        std::filesystem::current_path(cwd);
        EXPECT_NE(dot.find("is the same file as -o new.png"), std::string::npos) << dot;
    }
    out.check(dir / "sub" / "y.png", "--normal-out");
    EXPECT_NE(error_of([&] { out.check(dir / "link" / "y.png", "--id-out"); }), "");
    // An existing file reached through a symbolic link to it.
    test::write_bytes(dir / "z.npy", "z");
    std::filesystem::create_symlink(dir / "z.npy", dir / "z-link.npy");
    out.check(dir / "z.npy", "--id-out");
    EXPECT_NE(error_of([&] { out.check(dir / "z-link.npy", "--extra"); }), "");
    EXPECT_EQ(names_in(dir), (std::vector<std::string>{"link", "sub", "z-link.npy", "z.npy"}));
}

TEST(OutputFiles, BadPathsAreRefusedByNameBeforeAnyWork) {
    const auto dir = test::temp_dir("io-outputs-bad");
    OutputFiles out;
    const std::string long_name =
        error_of([&] { out.check(dir / (std::string(300, 'n') + ".png"), "-o"); });
    EXPECT_NE(long_name.find("-o "), std::string::npos) << long_name;
    EXPECT_NE(long_name.find("file name is 304 bytes long, more than the file system's limit"),
              std::string::npos)
        << long_name;
    const std::string missing = error_of([&] { out.check(dir / "none" / "a.png", "-o"); });
    EXPECT_NE(missing.find("does not exist"), std::string::npos) << missing;
    std::filesystem::create_directory(dir / "d.png");
    EXPECT_NE(error_of([&] { out.check(dir / "d.png", "-o"); }).find("is a directory"),
              std::string::npos);
    EXPECT_NE(error_of([&] { out.check("/dev/null", "-o"); }).find("not a regular file"),
              std::string::npos);
    EXPECT_NE(error_of([&] { out.check("", "-o"); }).find("empty"), std::string::npos);
    EXPECT_EQ(names_in(dir), std::vector<std::string>{"d.png"});
}

TEST(OutputFiles, AFailedWriteLeavesEveryTargetAsItWas) {
    const auto dir = test::temp_dir("io-outputs-fail");
    test::write_bytes(dir / "a.png", "old a");
    OutputFiles out;
    out.check(dir / "a.png", "-o");
    out.check(dir / "b.npy", "--depth-out");
    out.check(dir / "c.png", "--normal-out");
    out.add(dir / "a.png", bytes_of("new a"));
    out.add(dir / "b.npy", bytes_of("new b"));
    out.add(dir / "c.png", bytes_of("new c"));
    // After the checks, something takes c.png's place: the last rename fails.
    std::filesystem::create_directory(dir / "c.png");
    test::write_bytes(dir / "c.png" / "inside", "x");
    const std::string error = error_of([&] { out.commit(); });
    EXPECT_NE(error.find("c.png: cannot write"), std::string::npos) << error;
    EXPECT_NE(error.find("no output of this run was written"), std::string::npos) << error;
    EXPECT_EQ(test::read_bytes(dir / "a.png"), "old a");   // put back
    EXPECT_FALSE(std::filesystem::exists(dir / "b.npy"));  // removed again
    EXPECT_EQ(names_in(dir), (std::vector<std::string>{"a.png", "c.png"}));
}

TEST(OutputFiles, AddNeedsACheckedPath) {
    OutputFiles out;
    EXPECT_THROW(out.add("unchecked.png", bytes_of("x")), std::logic_error);
}

TEST(OutputFiles, EncodersGiveTheWritersBytes) {
    const auto dir = test::temp_dir("io-outputs-encode");
    const std::vector<std::uint8_t> rgb(4 * 3 * 3, 77);
    write_png8(dir / "w.png", 4, 3, 3, rgb);
    const std::vector<std::uint8_t> encoded = encode_png8(4, 3, 3, rgb);
    EXPECT_EQ(test::read_bytes(dir / "w.png"), std::string(encoded.begin(), encoded.end()));
    const std::vector<float> depth(12, 0.25f);
    write_npy(dir / "w.npy", 4, 3, depth);
    const std::vector<std::uint8_t> npy = encode_npy(4, 3, depth);
    EXPECT_EQ(test::read_bytes(dir / "w.npy"), std::string(npy.begin(), npy.end()));
}

}  // namespace
}  // namespace zraster
