// NumPy .npy writer: the header as NumPy's format 1.0 specifies it, then the raw data.
#include <zraster/image_io.hpp>

#include "io/io_test_util.hpp"
#include "support/test_support.hpp"

#include <bit>
#include <cmath>
#include <limits>

namespace zraster {
namespace {

struct Npy {
    std::string dict;  // without the padding and newline
    std::string data;
};

Npy parse_npy(const std::string& file) {
    Npy out;
    EXPECT_GE(file.size(), 10u);
    EXPECT_EQ(file.substr(0, 6), "\x93NUMPY");
    EXPECT_EQ(file[6], 1);  // major version
    EXPECT_EQ(file[7], 0);  // minor version
    const std::size_t header_length =
        static_cast<std::uint8_t>(file[8]) | static_cast<std::uint8_t>(file[9]) << 8;
    EXPECT_EQ((10 + header_length) % 64, 0u) << "header not padded to 64 bytes";
    const std::string header = file.substr(10, header_length);
    EXPECT_EQ(header.back(), '\n');
    const std::size_t end = header.find_last_not_of(" \n");
    out.dict = header.substr(0, end + 1);
    EXPECT_EQ(header.find_first_not_of(' ', end + 1), header.size() - 1) << "padding is spaces";
    out.data = file.substr(10 + header_length);
    return out;
}

std::uint32_t le32(const std::string& s, std::size_t at) {
    return std::uint32_t{static_cast<std::uint8_t>(s[at])} |
           std::uint32_t{static_cast<std::uint8_t>(s[at + 1])} << 8 |
           std::uint32_t{static_cast<std::uint8_t>(s[at + 2])} << 16 |
           std::uint32_t{static_cast<std::uint8_t>(s[at + 3])} << 24;
}

TEST(WriteNpy, Float32HeaderShapeAndData) {
    const auto path = test::temp_dir("io-npy-f4") / "depth.npy";
    const int w = 3, h = 2;
    const std::vector<float> values = {
        0.0f, -1.5f, 3.25e-7f, std::numeric_limits<float>::infinity(), std::nanf(""), 1e30f};
    write_npy(path, w, h, values);
    const Npy npy = parse_npy(test::read_bytes(path));
    EXPECT_EQ(npy.dict, "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3), }");
    ASSERT_EQ(npy.data.size(), values.size() * 4);
    for (std::size_t i = 0; i < values.size(); ++i)
        EXPECT_EQ(le32(npy.data, 4 * i), std::bit_cast<std::uint32_t>(values[i])) << i;
}

TEST(WriteNpy, Int32HeaderShapeAndData) {
    const auto path = test::temp_dir("io-npy-i4") / "ids.npy";
    const int w = 1, h = 4;
    const std::vector<std::int32_t> values = {0, -1, 2147483647, -2147483647 - 1};
    write_npy(path, w, h, values);
    const Npy npy = parse_npy(test::read_bytes(path));
    EXPECT_EQ(npy.dict, "{'descr': '<i4', 'fortran_order': False, 'shape': (4, 1), }");
    ASSERT_EQ(npy.data.size(), 16u);
    for (std::size_t i = 0; i < values.size(); ++i)
        EXPECT_EQ(static_cast<std::int32_t>(le32(npy.data, 4 * i)), values[i]);
}

TEST(WriteNpy, PadsLongShapesToo) {
    const auto path = test::temp_dir("io-npy-big") / "wide.npy";
    const int w = 123456, h = 1;  // a longer dict still ends on a 64-byte boundary
    write_npy(path, w, h, std::vector<float>(w, 2.0f));
    const Npy npy = parse_npy(test::read_bytes(path));
    EXPECT_EQ(npy.dict, "{'descr': '<f4', 'fortran_order': False, 'shape': (1, 123456), }");
    EXPECT_EQ(npy.data.size(), static_cast<std::size_t>(w) * 4);
}

TEST(WriteNpy, RejectsBadSizes) {
    const auto path = test::temp_dir("io-npy-bad") / "x.npy";
    EXPECT_THROW(write_npy(path, 2, 2, std::vector<float>(3)), std::invalid_argument);
    EXPECT_THROW(write_npy(path, -1, 2, std::vector<float>(2)), std::invalid_argument);
    EXPECT_THROW(write_npy(path, 2, 0, std::vector<std::int32_t>{}), std::invalid_argument);
    EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace zraster
