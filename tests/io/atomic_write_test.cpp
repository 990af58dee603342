// Every writer replaces its output atomically: a failure leaves nothing behind, success leaves
// exactly the new file (no temporaries).
#include <zraster/image_io.hpp>

#include "io/io_test_util.hpp"
#include "support/test_support.hpp"

namespace zraster {
namespace {

const std::vector<std::uint8_t> kPixels(2 * 2 * 3, 200);

TEST(AtomicWrite, MissingDirectoryThrowsAndLeavesNothing) {
    const auto dir = test::temp_dir("io-atomic-missing");
    const auto path = dir / "no" / "such" / "dir" / "out.png";
    test::expect_input_error([&] { write_png8(path, 2, 2, 3, kPixels); }, path,
                             "cannot write: No such file or directory");
    test::expect_input_error([&] { write_png16_gray(path, 1, 1, std::vector<std::uint16_t>{1}); },
                             path, "cannot write: No such file or directory");
    test::expect_input_error([&] { write_npy(path, 1, 1, std::vector<float>{1}); }, path,
                             "cannot write: No such file or directory");
    EXPECT_FALSE(std::filesystem::exists(dir / "no"));
    EXPECT_TRUE(test::list_directory(dir).empty());
}

TEST(AtomicWrite, ReplacesAnExistingFile) {
    const auto dir = test::temp_dir("io-atomic-replace");
    const auto path = dir / "out.npy";
    test::write_bytes(path, "old contents that are longer than nothing");
    write_npy(path, 1, 1, std::vector<std::int32_t>{7});
    const std::string bytes = test::read_bytes(path);
    EXPECT_EQ(bytes.substr(0, 6), "\x93NUMPY");
    EXPECT_EQ(bytes.size(), 128u + 4u);  // the header, padded to 64 bytes, then one int32
    EXPECT_EQ(test::list_directory(dir), std::vector<std::string>{"out.npy"});
}

TEST(AtomicWrite, ADirectoryInTheWayIsAnErrorAndStaysUntouched) {
    const auto dir = test::temp_dir("io-atomic-dir");
    const auto path = dir / "taken.png";
    std::filesystem::create_directory(path);
    test::write_bytes(path / "keep.txt", "keep");
    test::expect_input_error([&] { write_png8(path, 2, 2, 3, kPixels); }, path, "cannot write: ");
    EXPECT_TRUE(std::filesystem::is_directory(path));
    EXPECT_EQ(test::read_bytes(path / "keep.txt"), "keep");
    EXPECT_EQ(test::list_directory(dir), std::vector<std::string>{"taken.png"});
}

TEST(AtomicWrite, RelativePathInTheCurrentDirectory) {
    const auto dir = test::temp_dir("io-atomic-relative");
    struct RestoreDirectory {
        std::filesystem::path previous = std::filesystem::current_path();
        ~RestoreDirectory() { std::filesystem::current_path(previous); }
    } restore;
    std::filesystem::current_path(dir);
    write_png8("plain.png", 2, 2, 3, kPixels);
    EXPECT_EQ(test::list_directory(dir), std::vector<std::string>{"plain.png"});
}

}  // namespace
}  // namespace zraster
