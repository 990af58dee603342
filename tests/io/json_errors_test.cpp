// nlohmann::json's exceptions as one line in a user's terms (io/json_errors.hpp): the position
// and cause of a syntax error, a number too large for a double, no "[json.exception...]" prefix,
// no raw bytes.
#include <gtest/gtest.h>

#include <string>

#include "io/json_errors.hpp"

namespace zraster {
namespace {

std::string error_of(const std::string& text) {
    try {
        const nlohmann::json parsed = nlohmann::json::parse(text);
        return "(parsed: " + parsed.dump() + ")";
    } catch (const nlohmann::json::exception& e) {
        return io::json_error_text(e);
    }
    return "";
}

TEST(JsonErrors, SyntaxErrorsSayWhereAndWhat) {
    EXPECT_EQ(error_of(R"({"a": [1, 2)"),
              "line 1, column 12: unexpected end of input; expected ']'");
    EXPECT_EQ(error_of("{\n  \"a\": tru\n}"),
              "line 3, column 0: invalid literal; last read: '\"a\": tru<U+000A>'");
}

TEST(JsonErrors, ANumberTooLargeForADoubleIsNamed) {
    EXPECT_EQ(error_of(R"({"count": 1e400})"), "a number too large for a double ('1e400')");
    EXPECT_EQ(error_of("[-1e999]"), "a number too large for a double ('-1e999')");
}

TEST(JsonErrors, QuotedBytesArePrintable) {
    const std::string text = error_of("{\"a\": \xff\xfe}");
    for (const char c : text) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << text;
    EXPECT_EQ(text.find("[json.exception"), std::string::npos) << text;
}

}  // namespace
}  // namespace zraster
