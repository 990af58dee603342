// See batch_history.hpp.
#include "batch_history.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <fstream>
#include <string_view>
#include <system_error>

#include "batch_inputs.hpp"

namespace zraster::cli {
namespace {

constexpr std::size_t kMaxRecordBytes = std::size_t(1) << 20;

// The paths in order, each ended by a NUL (which no path holds).
template <typename Paths, typename AsString>
std::uint64_t paths_hash(const Paths& paths, AsString as_string) {
    std::uint64_t hash = fnv1a64("");
    for (const auto& p : paths)
        hash = fnv1a64(std::string_view("\0", 1), fnv1a64(as_string(p), hash));
    return hash;
}

std::vector<std::string> strings_of(const nlohmann::json& array) {
    std::vector<std::string> out;
    if (!array.is_array()) return out;
    for (const nlohmann::json& s : array)
        if (s.is_string()) out.push_back(s.get<std::string>());
    return out;
}

}  // namespace

BatchHistory BatchHistory::read(const std::filesystem::path& log) {
    BatchHistory history;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(log, ec)) return history;
    std::ifstream in(log, std::ios::binary);
    std::string line;
    bool too_long = false;  // the line being read is past kMaxRecordBytes: passed over
    const auto take = [&] {
        if (!too_long) history.add(line);
        line.clear();
        too_long = false;
    };
    std::array<char, 64 * 1024> chunk;
    // Read a chunk at a time, so that a line of gigabytes is passed over, never held.
    while (in.read(chunk.data(), std::streamsize(chunk.size())) || in.gcount() > 0) {
        const std::string_view text(chunk.data(), std::size_t(in.gcount()));
        for (std::size_t start = 0; start < text.size();) {
            const std::size_t end = std::min(text.find('\n', start), text.size());
            if (!too_long) {
                line.append(text.substr(start, end - start));
                too_long = line.size() > kMaxRecordBytes;
                if (too_long) line.clear();
            }
            if (end < text.size()) take();
            start = end + 1;
        }
    }
    if (!line.empty()) take();  // a last line without its newline
    return history;
}

void BatchHistory::add(const std::string& line) {
    const nlohmann::json record = nlohmann::json::parse(line, nullptr, false);
    if (!record.is_object() || !record.contains("input") || !record["input"].is_string()) return;
    Entry entry;
    const nlohmann::json status = record.value("status", nlohmann::json());
    entry.written = status == "ok" || status == "skipped";
    const std::vector<std::string> outputs = strings_of(record.value("outputs", nlohmann::json()));
    entry.outputs_hash = paths_hash(outputs, [](const std::string& s) { return s; });
    entry.reads = strings_of(record.value("reads", nlohmann::json()));
    entries_[fnv1a64(record["input"].get<std::string>())] = std::move(entry);
}

const std::vector<std::string>* BatchHistory::written(
    const std::string& input, const std::vector<std::filesystem::path>& outputs) const {
    const auto it = entries_.find(fnv1a64(input));
    if (it == entries_.end() || !it->second.written) return nullptr;
    const std::uint64_t hash =
        paths_hash(outputs, [](const std::filesystem::path& p) { return p.string(); });
    return hash == it->second.outputs_hash ? &it->second.reads : nullptr;
}

bool outputs_up_to_date(const std::filesystem::path& input,
                        const std::vector<std::filesystem::path>& outputs,
                        const std::vector<std::string>& reads) {
    std::error_code ec;
    auto newest = std::filesystem::last_write_time(input, ec);
    if (ec) return false;
    for (const std::string& file : reads) {
        const auto time = std::filesystem::last_write_time(file, ec);
        if (ec) return false;  // gone: the model cannot be the same
        newest = std::max(newest, time);
    }
    for (const std::filesystem::path& output : outputs) {
        // (A folder made where the image was is no output: render it again.)
        if (!std::filesystem::is_regular_file(output, ec)) return false;
        const auto output_time = std::filesystem::last_write_time(output, ec);
        if (ec || !(output_time > newest)) return false;
    }
    return true;
}

}  // namespace zraster::cli
