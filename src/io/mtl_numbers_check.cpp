// See mtl_numbers_check.hpp.
#include "io/mtl_numbers_check.hpp"

#include <zraster/error.hpp>

#include "io/mtl_for_assimp.hpp"
#include "io/obj_number_token.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace zraster::io {

namespace {

constexpr std::array<std::string_view, 18> kNumeric = {
    "Ka",    "Kd", "Ks", "Ke", "Tf", "Ns",  "Ni",    "d",      "Tr",
    "illum", "Pr", "Pm", "Ps", "Pc", "Pcr", "aniso", "anisor", "sharpness"};

// The ranges of the statements zraster reads but does not use (Kd, Ks, Ns, d and Tr are
// checked where the material is converted): a value outside is warned about, once a library
// and statement.
struct UnusedRange {
    std::string_view keyword;
    double lo, hi;
    const char* range;
};
constexpr UnusedRange kUnusedRanges[] = {
    {"Ka", 0.0, 1.0, "0..1"},     {"Ke", 0.0, 1.0, "0..1"},
    {"Tf", 0.0, 1.0, "0..1"},     {"Ni", 0.001, 10.0, "0.001..10"},
    {"Pr", 0.0, 1.0, "0..1"},     {"Pm", 0.0, 1.0, "0..1"},
    {"Ps", 0.0, 1.0, "0..1"},     {"Pc", 0.0, 1.0, "0..1"},
    {"Pcr", 0.0, 1.0, "0..1"},    {"aniso", 0.0, 1.0, "0..1"},
    {"anisor", 0.0, 1.0, "0..1"}, {"sharpness", 0.0, 1000.0, "0..1000"},
};

bool blank(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}

}  // namespace

void check_mtl_numbers(const std::filesystem::path& obj, const std::filesystem::path& library,
                       std::vector<std::string>* warnings) {
    std::ifstream in(library, std::ios::binary);
    std::string line;
    bool decal_seen = false;
    std::vector<std::string_view> warned;  // kUnusedRanges keywords warned about
    std::vector<std::string_view> words;
    for (std::size_t number = 1; std::getline(in, line); ++number) {
        words.clear();
        const std::string_view text(line);
        for (std::size_t at = 0; at < text.size();) {
            while (at < text.size() && blank(text[at])) ++at;
            std::size_t end = at;
            while (end < text.size() && !blank(text[end])) ++end;
            if (end > at) words.push_back(text.substr(at, end - at));
            at = end;
        }
        const auto where = [&] {
            return "material library " + library.lexically_relative(obj.parent_path()).string() +
                   ": line " + std::to_string(number) + ": ";
        };
        if (!words.empty() && words[0] == "decal" && !decal_seen) {
            decal_seen = true;
            if (warnings != nullptr) warnings->push_back(where() + std::string(kDecalIgnored));
        }
        if (words.empty() ||
            std::find(kNumeric.begin(), kNumeric.end(), words[0]) == kNumeric.end())
            continue;
        const auto refuse = [&](const std::string& cause) {
            throw InputError(obj.string(), where() + cause);
        };
        std::size_t numbers = 0;
        for (std::size_t k = 1; k < words.size(); ++k) {
            const std::string_view w = words[k];
            if (w.starts_with('#')) break;
            if (!is_number_word(w)) refuse(not_a_number(w));
            ++numbers;
        }
        // Assimp's reader fails on these in its own words ("Cannot parse string \"\"").
        const bool color = words[0].size() == 2 && (words[0][0] == 'K' || words[0] == "Tf");
        if (color && numbers == 2)
            refuse("'" + std::string(words[0]) + "' of 2 numbers; a color is 1 or 3");
        if (color && numbers == 0)
            refuse("'" + std::string(words[0]) + "' without a number; a color is 1 or 3");
        if (color && numbers > 3)
            refuse("'" + std::string(words[0]) + "' of " + std::to_string(numbers) +
                   " numbers; a color is 1 or 3");
        for (const UnusedRange& r : kUnusedRanges) {
            if (words[0] != r.keyword || numbers == 0 || warnings == nullptr ||
                std::find(warned.begin(), warned.end(), r.keyword) != warned.end())
                continue;
            for (std::size_t k = 1; k <= numbers; ++k) {
                const double value = std::strtod(std::string(words[k]).c_str(), nullptr);
                if (value >= r.lo && value <= r.hi) continue;  // (NaN fails both)
                std::string statement(words[0]);
                for (std::size_t j = 1; j <= numbers; ++j)
                    statement.append(" ").append(words[j].substr(0, 24));
                warnings->push_back(where() + "'" + statement + "' is outside " + r.range +
                                    "; zraster does not use it (ignored)");
                warned.push_back(r.keyword);
                break;
            }
        }
        // An illumination model is one of the specification's 0 to 10 (Assimp read the word
        // into an int: 4294967296 wrapped).
        const auto model = [](std::string_view w) {
            const std::size_t first = std::min(w.find_first_not_of('0'), w.size() - 1);
            return w.substr(first);  // leading zeros dropped, "0" kept
        };
        if (words[0] == "illum" && numbers > 0 &&
            (numbers != 1 || words[1].find_first_not_of("0123456789") != std::string_view::npos ||
             model(words[1]).size() > 2 || std::stoi(std::string(model(words[1]))) > 10))
            refuse("'illum " + std::string(words[1].substr(0, 40)) + (numbers > 1 ? " ..." : "") +
                   "': the illumination model is one whole number from 0 to 10");
    }
}

}  // namespace zraster::io
