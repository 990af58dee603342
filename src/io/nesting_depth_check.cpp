#include "io/nesting_depth_check.hpp"

#include <zraster/error.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <unordered_map>
#include <vector>

namespace zraster::io {

namespace {

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

// The line at `at` (without its newline), blanks trimmed at both ends; `at` moves past it.
std::string_view take_line(std::string_view text, std::size_t& at) {
    std::size_t end = text.find('\n', at);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(at, end - at);
    at = end + 1;
    while (!line.empty() && is_space(line.front())) line.remove_prefix(1);
    while (!line.empty() && is_space(line.back())) line.remove_suffix(1);
    return line;
}

// Tokens as the X importer's text reader splits them: whitespace and comments ("//", "#" to the
// end of the line) separate, and ; , { } are tokens of their own.
class XTokens {
  public:
    explicit XTokens(std::string_view text) : text_(text) {}
    std::string_view next() {
        for (;;) {
            while (at_ < text_.size() && is_space(text_[at_])) ++at_;
            if (at_ >= text_.size()) return {};
            if (text_[at_] == '#' || text_.compare(at_, 2, "//") == 0) {
                const std::size_t end = text_.find('\n', at_);
                at_ = end == std::string_view::npos ? text_.size() : end + 1;
                continue;
            }
            break;
        }
        const std::size_t start = at_;
        if (is_delimiter(text_[at_])) return text_.substr(at_++, 1);
        while (at_ < text_.size() && !is_space(text_[at_]) && !is_delimiter(text_[at_])) ++at_;
        return text_.substr(start, at_ - start);
    }

  private:
    static bool is_delimiter(char c) { return c == ';' || c == ',' || c == '{' || c == '}'; }
    std::string_view text_;
    std::size_t at_ = 0;
};

// Skips to the next "{" and past its matching "}", as the importer skips an unknown object (and
// reads, with braces balanced, the objects it knows). False at the end of the text.
bool skip_object(XTokens& tokens) {
    std::string_view t;
    do {
        t = tokens.next();
        if (t.empty()) return false;
    } while (t != "{");
    for (std::size_t open = 1; open > 0;) {
        t = tokens.next();
        if (t.empty()) return false;
        if (t == "{") ++open;
        if (t == "}") --open;
    }
    return true;
}

}  // namespace

XFrameDepth x_frame_depth(std::string_view body) {
    XTokens tokens(body);
    std::size_t depth = 0;
    XFrameDepth result;
    std::size_t& deepest = result.depth;
    for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next()) {
        if (t == "Frame") {
            // The head: an optional name, then "{" (else the importer stops with an error).
            std::string_view brace = tokens.next();
            if (brace != "{") brace = tokens.next();
            if (brace != "{") break;
            deepest = std::max(deepest, ++depth);
            if (deepest > kMaxNestingDepth) break;
        } else if (t == "}") {
            if (depth > 0) --depth;
        } else if (t == "template" && depth == 0) {
            while (!t.empty() && t != "}") t = tokens.next();  // (templates hold no braces)
            if (t.empty()) break;
        } else {
            if (t == "{" && depth > 0) result.reference_in_frame = true;
            if (!skip_object(tokens)) break;
        }
    }
    return result;
}

std::size_t ac3d_object_depth(std::string_view text) {
    // Children not yet read, per open level: an OBJECT takes one from the innermost level, its
    // "kids N" opens a level of N (a leaf, N = 0, closes the levels it completes).
    std::vector<std::uint64_t> remaining;
    std::size_t deepest = 0;
    for (std::size_t at = 0; at < text.size();) {
        std::string_view line = take_line(text, at);
        if (line.starts_with("OBJECT")) {
            if (!remaining.empty() && remaining.back() > 0) --remaining.back();
            deepest = std::max(deepest, remaining.size() + 1);
            if (deepest > kMaxNestingDepth) break;
        } else if (line.starts_with("kids")) {
            line.remove_prefix(4);
            while (!line.empty() && is_space(line.front())) line.remove_prefix(1);
            std::uint64_t kids = 0;
            std::from_chars(line.data(), line.data() + line.size(), kids);
            if (kids > 0) {
                remaining.push_back(kids);
            } else {
                while (!remaining.empty() && remaining.back() == 0) remaining.pop_back();
            }
        }
    }
    return deepest;
}

std::size_t smd_bone_depth(std::string_view text, const std::string& file) {
    // The "nodes" section: `id "name" parent` lines up to "end".
    std::unordered_map<std::int64_t, std::int64_t> parent_of;
    std::vector<std::int64_t> order;
    bool in_nodes = false;
    for (std::size_t at = 0; at < text.size();) {
        const std::string_view line = take_line(text, at);
        if (!in_nodes) {
            in_nodes = line == "nodes";
            continue;
        }
        if (line == "end") break;
        std::int64_t id = 0, parent = 0;
        const auto [id_end, id_ec] = std::from_chars(line.data(), line.data() + line.size(), id);
        const std::size_t last_blank = line.find_last_of(" \t");
        if (id_ec != std::errc() || last_blank == std::string_view::npos) continue;
        const std::string_view parent_text = line.substr(last_blank + 1);
        const auto [p_end, p_ec] =
            std::from_chars(parent_text.data(), parent_text.data() + parent_text.size(), parent);
        if (p_ec != std::errc()) continue;  // (the importer says what is wrong with the line)
        if (parent_of.emplace(id, parent).second) order.push_back(id);
    }
    // Ids are 0 to n-1; the importer sizes its bone array by the largest (2,000,000,000: out of
    // memory).
    for (const std::int64_t id : order)
        if (id < 0 || static_cast<std::uint64_t>(id) >= order.size())
            throw InputError(file, "malformed SMD file: node id " + std::to_string(id) +
                                       " is outside 0.." + std::to_string(order.size() - 1) +
                                       " (the nodes section has " + std::to_string(order.size()) +
                                       " nodes)");
    std::unordered_map<std::int64_t, std::size_t> depth;  // levels from the root, 1 for a root
    std::size_t deepest = 0;
    std::vector<std::int64_t> chain;  // from a node up to the first whose depth is known
    for (const std::int64_t start : order) {
        chain.clear();
        std::size_t above = 0;  // the depth above the chain's last node
        for (std::int64_t node = start;;) {
            if (const auto known = depth.find(node); known != depth.end()) {
                above = known->second;
                break;
            }
            if (std::find(chain.begin(), chain.end(), node) != chain.end())
                throw InputError(file, "malformed SMD file: node " + std::to_string(node) +
                                           " is its own ancestor (a loop of parents)");
            chain.push_back(node);
            const std::int64_t parent = parent_of[node];
            if (parent < 0 || chain.size() > kMaxNestingDepth) break;
            if (!parent_of.contains(parent))
                throw InputError(file, "malformed SMD file: node " + std::to_string(node) +
                                           "'s parent " + std::to_string(parent) +
                                           " is not a node");
            node = parent;
        }
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) depth[*it] = ++above;
        deepest = std::max(deepest, above);
        if (deepest > kMaxNestingDepth) break;
    }
    return deepest;
}

void check_nesting_depth(const std::filesystem::path& path, std::string_view head) {
    const bool x_text =
        head.size() >= 16 && head.starts_with("xof ") && head.substr(8, 4) == "txt ";
    const bool ac3d = head.starts_with("AC3D");
    std::string extension = path.extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const bool smd = extension == ".smd" || extension == ".vta";
    if (!x_text && !ac3d && !smd) return;
    std::ifstream in(path, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string limit = std::to_string(kMaxNestingDepth);
    if (x_text) {
        const XFrameDepth x = x_frame_depth(std::string_view(text).substr(16));
        if (x.depth > kMaxNestingDepth)
            throw InputError(
                path.string(),
                "malformed X file: its Frames nest more than " + limit +
                    " levels deep as the importer reads them (recursively" +
                    (x.reference_in_frame ? "; a data reference such as '{ m }' directly inside a "
                                            "Frame, which it cannot read, makes the Frames after "
                                            "it nest)"
                                          : ")"));
    }
    if (smd && smd_bone_depth(text, path.string()) > kMaxNestingDepth)
        throw InputError(path.string(), "malformed SMD file: its bones nest more than " + limit +
                                            " levels deep (each node's parent; the importer "
                                            "reads them recursively)");
    if (ac3d && ac3d_object_depth(text) > kMaxNestingDepth)
        throw InputError(path.string(), "malformed AC3D file: its OBJECTs nest more than " + limit +
                                            " levels deep ('kids' lines; the importer reads "
                                            "them recursively)");
}

}  // namespace zraster::io
