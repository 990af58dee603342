// Every writer replaces its output atomically: a failure leaves nothing behind, success leaves
// exactly the new file (no temporaries).
#include <zraster/image_io.hpp>

#include <sys/stat.h>

#include "io/io_test_util.hpp"
#include "support/test_support.hpp"

namespace zraster {
namespace {

const std::vector<std::uint8_t> kPixels(2 * 2 * 3, 200);

TEST(AtomicWrite, MissingDirectoryThrowsAndLeavesNothing) {
    const auto dir = test::temp_dir("io-atomic-missing");
    const auto path = dir / "no" / "such" / "dir" / "out.png";
    const std::string cause =
        "cannot write: directory '" + path.parent_path().string() + "' does not exist";
    test::expect_input_error([&] { write_png8(path, 2, 2, 3, kPixels); }, path, cause);
    test::expect_input_error([&] { write_png16_gray(path, 1, 1, std::vector<std::uint16_t>{1}); },
                             path, cause);
    test::expect_input_error([&] { write_npy(path, 1, 1, std::vector<float>{1}); }, path, cause);
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

// The temporary is ".zraster-PID-N.tmp", not NAME plus a suffix: a name of the file system's
// longest length is written too.
TEST(AtomicWrite, ANameOfTheLongestLengthIsWritten) {
    const auto dir = test::temp_dir("io-atomic-long");
    const std::string name = std::string(251, 'n') + ".png";
    write_png8(dir / name, 2, 2, 3, kPixels);
    EXPECT_EQ(test::list_directory(dir), std::vector<std::string>{name});
}

// A FIFO or device node at the path is refused, not replaced by a regular file.
TEST(AtomicWrite, AFifoInTheWayIsRefusedAndStays) {
    const auto dir = test::temp_dir("io-atomic-fifo");
    const auto path = dir / "pipe.png";
    ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
    test::expect_input_error([&] { write_png8(path, 2, 2, 3, kPixels); }, path,
                             "cannot write: exists and is not a regular file");
    EXPECT_TRUE(std::filesystem::is_fifo(path));
    EXPECT_EQ(test::list_directory(dir), std::vector<std::string>{"pipe.png"});
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
