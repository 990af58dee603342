#include "io/declared_counts_check.hpp"

#include <zraster/error.hpp>

#include <cctype>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace zraster::io {

namespace {

struct DeclaredElement {
    std::string name;
    std::uint64_t count = 0;
    std::uint64_t min_record_bytes = 1;
};

// The leading digits, as Assimp's strtoul10 reads a count: it stops at the first non-digit, so
// "1099511627-776" declares 1099511627 records (found by fuzz_load_off: Assimp then allocated
// 16 GiB of faces). No leading digit: nullopt, Assimp reads 0 and reports the file itself.
// Saturates instead of wrapping.
std::optional<std::uint64_t> parse_count(const std::string& token) {
    if (token.empty() || token[0] < '0' || token[0] > '9') return std::nullopt;
    std::uint64_t value = 0;
    for (char c : token) {
        if (c < '0' || c > '9') break;
        const std::uint64_t digit = static_cast<std::uint64_t>(c - '0');
        value = value > (UINT64_MAX - digit) / 10 ? UINT64_MAX : value * 10 + digit;
    }
    return value;
}

std::string read_prefix(const std::filesystem::path& path, std::size_t limit) {
    std::ifstream in(path, std::ios::binary);
    std::string text(limit, '\0');
    in.read(text.data(), static_cast<std::streamsize>(limit));
    text.resize(static_cast<std::size_t>(in.gcount()));
    return text;
}

// body_bytes: what follows the header (PLY) or the whole file (OFF, whose header is tiny).
void check_body(const std::filesystem::path& path, const char* format,
                const std::vector<DeclaredElement>& elements, std::uint64_t body_bytes) {
    std::uint64_t needed = 0;
    for (const DeclaredElement& e : elements) {
        // The last record may lack its trailing separator, hence the one byte of slack.
        const std::uint64_t available = body_bytes + 1 - needed;
        if (e.count > available / e.min_record_bytes) {
            throw InputError(path.string(),
                             std::string("truncated or malformed file: the ") + format +
                                 " header declares " + std::to_string(e.count) + " " + e.name +
                                 " records, more than its " + std::to_string(body_bytes) +
                                 " bytes of data can hold");
        }
        needed += e.count * e.min_record_bytes;
    }
}

std::uint64_t ply_scalar_size(const std::string& type) {
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" ||
        type == "float32")
        return 4;
    if (type == "double" || type == "float64") return 8;
    return 1;  // unknown: Assimp will complain; stay conservative here
}

// Binary records hold every scalar and each list's length; ASCII records at least one digit and
// one separator per value.
void check_ply(const std::filesystem::path& path, const std::string& head,
               std::uintmax_t file_size) {
    std::istringstream lines(head);
    std::string line;
    bool ascii = false;
    bool ended = false;
    std::vector<DeclaredElement> elements;
    std::vector<std::uint64_t> property_bytes;  // per element, binary size
    std::vector<std::uint64_t> property_count;  // per element
    std::size_t header_bytes = 0;
    while (std::getline(lines, line)) {
        header_bytes += line.size() + 1;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        if (keyword == "format") {
            std::string kind;
            words >> kind;
            ascii = kind == "ascii";
        } else if (keyword == "element") {
            std::string name, count;
            words >> name >> count;
            const auto n = parse_count(count);
            if (!n) return;
            elements.push_back({name, *n, 1});
            property_bytes.push_back(0);
            property_count.push_back(0);
        } else if (keyword == "property" && !elements.empty()) {
            std::string type;
            words >> type;
            if (type == "list") words >> type;  // the list's length type
            property_bytes.back() += ply_scalar_size(type);
            property_count.back() += 1;
        } else if (keyword == "end_header") {
            ended = true;
            break;
        }
    }
    if (!ended || header_bytes > file_size) return;  // Assimp reports a broken header itself
    for (std::size_t i = 0; i < elements.size(); ++i) {
        const std::uint64_t bytes = ascii ? 2 * property_count[i] : property_bytes[i];
        elements[i].min_record_bytes = bytes > 0 ? bytes : 1;
    }
    check_body(path, "PLY", elements, file_size - header_bytes);
}

// "[ST][C][N][4][n]OFF [dim] nv nf ne", comments starting with '#'; the keyword is optional.
void check_off(const std::filesystem::path& path, const std::string& head,
               std::uintmax_t file_size) {
    std::istringstream text(head);
    std::vector<std::string> tokens;
    std::string line;
    while (tokens.size() < 5 && std::getline(text, line)) {
        const auto hash = line.find('#');
        if (hash != std::string::npos) line.resize(hash);
        std::istringstream words(line);
        std::string word;
        while (tokens.size() < 5 && words >> word) tokens.push_back(word);
    }
    std::size_t next = 0;
    if (!tokens.empty() && tokens[0].ends_with("OFF")) {
        next = tokens[0].find('n') != std::string::npos ? 2 : 1;
    }
    if (tokens.size() < next + 2) return;
    const auto vertices = parse_count(tokens[next]);
    const auto faces = parse_count(tokens[next + 1]);
    if (!vertices || !faces) return;
    // At least "x y z" plus a separator per vertex and "n" plus a separator per face.
    check_body(path, "OFF", {{"vertex", *vertices, 6}, {"face", *faces, 2}}, file_size);
}

}  // namespace

void check_declared_counts(const std::filesystem::path& path, std::uintmax_t file_size) {
    // Headers are short; 64 KiB leaves room for long comment blocks.
    const std::string head = read_prefix(path, 64 * 1024);
    if (head.starts_with("ply\n") || head.starts_with("ply\r\n")) {
        check_ply(path, head, file_size);
        return;
    }
    std::istringstream first(head);
    std::string token;
    first >> token;
    std::string extension = path.extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if ((token.ends_with("OFF") && token.size() <= 8) || extension == ".off")
        check_off(path, head, file_size);
}

}  // namespace zraster::io
