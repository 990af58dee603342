// Helpers for the io tests: fixture files and checks on InputError.
#pragma once
#include <zraster/error.hpp>
#include <zraster/load.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "support/test_support.hpp"

namespace zraster::test {

inline void write_bytes(const std::filesystem::path& path, std::string_view bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    ASSERT_TRUE(out.good()) << path;
}

// A file `name` holding `content` in a fresh temp_dir(folder).
inline std::filesystem::path write_fixture(const std::string& folder, const std::string& name,
                                           std::string_view content) {
    const auto path = temp_dir(folder) / name;
    write_bytes(path, content);
    return path;
}

// Standard base64 with padding: glTF buffers and images as data URIs.
inline std::string base64(std::string_view bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t v = std::uint32_t(std::uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) v |= std::uint32_t(std::uint8_t(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size()) v |= std::uint32_t(std::uint8_t(bytes[i + 2]));
        out += digits[(v >> 18) & 63];
        out += digits[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? digits[v & 63] : '=';
    }
    return out;
}

inline std::vector<std::string> list_directory(const std::filesystem::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        names.push_back(entry.path().filename().string());
    return names;
}

// Runs `action`, which must throw an InputError naming `file` whose cause contains `cause`; the
// message must be the single line "FILE: cause".
template <typename Action>
void expect_input_error(Action&& action, const std::filesystem::path& file,
                        std::string_view cause) {
    try {
        action();
        ADD_FAILURE() << "no InputError for " << file << " (expected '" << cause << "')";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), file.string());
        EXPECT_NE(e.cause().find(cause), std::string::npos)
            << "cause '" << e.cause() << "' lacks '" << cause << "'";
        EXPECT_EQ(std::string(e.what()), file.string() + ": " + e.cause());
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    }
}

// As expect_input_error, for a LimitExceeded whose limit() is `limit`.
template <typename Action>
void expect_limit_exceeded(Action&& action, const std::filesystem::path& file,
                           std::string_view limit, std::string_view cause) {
    try {
        action();
        ADD_FAILURE() << "no LimitExceeded for " << file << " (expected '" << cause << "')";
    } catch (const LimitExceeded& e) {
        EXPECT_EQ(e.limit(), limit);
        expect_input_error([&] { throw e; }, file, cause);
    } catch (const InputError& e) {
        ADD_FAILURE() << "an InputError, not a LimitExceeded: " << e.what();
    }
}

// Both ways a model file is loaded: in this process, and through the importer's worker process.
inline constexpr LoadIsolation kBothIsolations[] = {LoadIsolation::InProcess,
                                                    LoadIsolation::WorkerProcess};

// load_scene(path, options) refuses the file with an InputError whose cause contains `cause`, in
// process and through the worker alike (expect_input_error).
inline void expect_refused_both_ways(const std::filesystem::path& path, std::string_view cause,
                                     LoadOptions options = {}) {
    for (const LoadIsolation isolation : kBothIsolations) {
        SCOPED_TRACE(isolation == LoadIsolation::InProcess ? "in process" : "worker");
        options.isolation = isolation;
        expect_input_error([&] { load_scene(path, options); }, path, cause);
    }
}

}  // namespace zraster::test
