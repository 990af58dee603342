// See batch_inputs.hpp.
#include "batch_inputs.hpp"

#include <zraster/error.hpp>
#include <zraster/load.hpp>
#include <zraster/scenes.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <system_error>

#include "input_stream.hpp"

namespace zraster::cli {
namespace {

std::string lower(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

// The name without its format's extension: the longest of the loader's that matches
// ("a.mesh.xml" -> "a"), else the last one (".stl" of a file given by name).
std::string without_extension(const std::string& name) {
    const std::string lowered = lower(name);
    std::size_t cut = 0;
    for (const std::string& extension : mesh_file_extensions())
        if (lowered.size() > extension.size() && lowered.ends_with(extension))
            cut = std::max(cut, extension.size());
    if (cut > 0) return name.substr(0, name.size() - cut);
    const std::string stem = std::filesystem::path(name).stem().string();
    return stem.empty() ? name : stem;
}

std::string stem_of(const std::filesystem::path& relative) {
    const std::filesystem::path parent = relative.parent_path();
    const std::string name = without_extension(relative.filename().string());
    return parent.empty() ? name : (parent / name).generic_string();
}

void add_folder(std::filesystem::path folder, const std::filesystem::path& skip,
                std::vector<BatchInput>& inputs) {
    // "meshes/" as "meshes": a trailing separator would count as a path element of its own.
    while (folder.has_relative_path() && folder.filename().empty()) folder = folder.parent_path();
    std::vector<BatchInput> found;
    std::error_code ec;
    std::filesystem::recursive_directory_iterator it(folder, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
        std::error_code status_error;
        if (!skip.empty() && it->is_directory(status_error) &&
            std::filesystem::equivalent(it->path(), skip, status_error)) {
            it.disable_recursion_pending();
            continue;
        }
        if (!it->is_regular_file(status_error) || !has_mesh_file_extension(it->path())) continue;
        const std::filesystem::path relative = it->path().lexically_relative(folder);
        found.push_back({it->path(), stem_of(relative)});
    }
    if (ec) throw InputError(folder.string(), "cannot read the folder: " + ec.message());
    std::sort(found.begin(), found.end(),
              [](const BatchInput& a, const BatchInput& b) { return a.stem < b.stem; });
    inputs.insert(inputs.end(), found.begin(), found.end());
}

std::filesystem::path identity(const std::filesystem::path& path) {
    std::error_code ec;
    std::filesystem::path p = std::filesystem::weakly_canonical(path, ec);
    return ec ? path.lexically_normal() : p;
}

}  // namespace

std::vector<BatchInput> find_inputs(const std::vector<std::string>& paths,
                                    const std::filesystem::path& skip) {
    std::vector<BatchInput> inputs;
    for (const std::string& text : paths) {
        const std::filesystem::path path(text);
        std::error_code ec;
        if (std::filesystem::is_directory(path, ec))
            add_folder(path, skip, inputs);
        else if (is_procedural_spec(text) && !std::filesystem::exists(path, ec))
            throw InputError(text,
                             "batch renders model files and folders of them; a procedural scene "
                             "(builtin:, sphere:, city:, soup:, building:) is for zraster render");
        else
            inputs.push_back({path, without_extension(path.filename().string())});
    }
    // The same file reached twice for the same outputs (a folder and a file in it, a list
    // repeating a line) is one input.
    std::set<std::pair<std::string, std::filesystem::path>> seen;
    std::vector<BatchInput> unique;
    for (BatchInput& input : inputs)
        if (seen.insert({input.stem, identity(input.source)}).second)
            unique.push_back(std::move(input));
    return unique;
}

std::vector<std::string> read_path_list(const std::string& list, std::istream& standard_input) {
    std::unique_ptr<std::istream> file;
    if (list != "-") {
        std::error_code ec;
        if (std::filesystem::is_directory(list, ec))
            throw InputError("--list " + list, "is a folder, not a list of paths");
        file = open_input_stream(list, "--list " + list);
    }
    std::istream& in = list == "-" ? standard_input : *file;
    // Lines read within bounds: a device (/dev/zero) or a binary file is one endless line.
    constexpr std::size_t kMaxLine = 4096, kMaxPaths = 10'000'000;
    std::vector<std::string> paths;
    std::string line;
    std::size_t number = 1;
    const auto end_line = [&] {
        if (line.ends_with('\r')) line.pop_back();
        if (line.find_first_not_of(" \t") != std::string::npos) {
            if (paths.size() == kMaxPaths)
                throw InputError("--list " + list, "more than " + std::to_string(kMaxPaths) +
                                                       " paths: split the list (--shard)");
            paths.push_back(line);
        }
        line.clear();
        ++number;
    };
    for (std::istreambuf_iterator<char> it(in), end; it != end; ++it) {
        const char c = *it;
        if (c == '\n') {
            end_line();
            continue;
        }
        if (c == '\0')
            throw InputError("--list " + list, "line " + std::to_string(number) +
                                                   " holds a NUL byte: not a text list of paths");
        if (line.size() == kMaxLine)
            throw InputError("--list " + list, "line " + std::to_string(number) +
                                                   " is longer than " + std::to_string(kMaxLine) +
                                                   " bytes: not a list of paths");
        line.push_back(c);
    }
    if (!line.empty()) end_line();
    if (in.bad()) throw InputError("--list " + list, "cannot read the list");
    return paths;
}

void check_output_clashes(
    const std::vector<BatchInput>& inputs,
    const std::function<std::vector<std::filesystem::path>(const BatchInput&)>& outputs_of) {
    std::map<std::string, const BatchInput*> writer;
    for (const BatchInput& input : inputs)
        for (const std::filesystem::path& output : outputs_of(input)) {
            const auto [it, inserted] =
                writer.emplace(output.lexically_normal().generic_string(), &input);
            if (!inserted)
                throw InputError(input.source.string(),
                                 "writes " + output.string() + " as " +
                                     it->second->source.string() +
                                     " does: each input needs outputs of its own (rename one, or "
                                     "give their folder so that their paths under it tell them "
                                     "apart)");
        }
}

Shard parse_shard(const std::string& text) {
    const std::size_t slash = text.find('/');
    Shard shard;
    bool ok = slash != std::string::npos;
    if (ok) {
        const char* begin = text.data();
        const auto k = std::from_chars(begin, begin + slash, shard.index);
        const auto n = std::from_chars(begin + slash + 1, begin + text.size(), shard.count);
        ok = slash > 0 && k.ec == std::errc() && k.ptr == begin + slash && n.ec == std::errc() &&
             n.ptr == begin + text.size() && text[0] != '-' && text[slash + 1] != '-';
    }
    if (!ok) throw InputError("--shard", "expected K/N (e.g. 0/4), got '" + text + "'");
    if (shard.count == 0 || shard.index >= shard.count)
        throw InputError("--shard", "K/N needs 0 <= K < N, got '" + text + "'");
    return shard;
}

std::uint64_t fnv1a64(std::string_view text, std::uint64_t hash) {
    for (const char c : text) {
        hash ^= static_cast<unsigned char>(c);
        hash *= 0x100000001b3ull;
    }
    return hash;
}

bool in_shard(const BatchInput& input, const Shard& shard) {
    return fnv1a64(input.stem) % shard.count == shard.index;
}

}  // namespace zraster::cli
