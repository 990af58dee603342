#include "io/reference_policy.hpp"

#include <algorithm>
#include <cerrno>
#include <system_error>

#include <unistd.h>

namespace zraster::io {

ReferencePolicy::ReferencePolicy(const std::filesystem::path& model_path, bool allow_outside) {
    std::error_code ec;
    model_ = std::filesystem::canonical(model_path, ec);
    if (allow_outside) return;
    const std::filesystem::path folder =
        model_path.parent_path().empty() ? std::filesystem::path(".") : model_path.parent_path();
    root_ = std::filesystem::canonical(folder, ec);
    // A model whose folder cannot be resolved reads nothing besides itself.
    if (ec) root_ = "/nonexistent-zraster-model-folder";
}

ReferencePolicy::Check ReferencePolicy::check(const std::filesystem::path& file) const {
    std::error_code ec;
    const std::filesystem::file_status link = std::filesystem::symlink_status(file, ec);
    if (ec || !std::filesystem::exists(link)) return {Verdict::Missing, {}};
    const std::filesystem::path resolved = std::filesystem::canonical(file, ec);
    if (ec) {
        // A dangling link, or a loop of links.
        if (ec == std::errc::too_many_symbolic_link_levels)
            return {Verdict::Refused, "is a loop of symbolic links"};
        return {Verdict::Missing, {}};
    }
    // What no option allows first: the hint to allow outside references would not help.
    const std::filesystem::file_status status = std::filesystem::status(resolved, ec);
    if (ec) return {Verdict::Missing, {}};
    if (std::filesystem::is_directory(status)) return {Verdict::Refused, "is a directory"};
    if (!std::filesystem::is_regular_file(status))
        return {Verdict::Refused, "is not a regular file (a FIFO, socket or device)"};
    if (!root_.empty() && resolved != model_) {
        const auto [end, _] =
            std::mismatch(root_.begin(), root_.end(), resolved.begin(), resolved.end());
        if (end != root_.end()) {
            // Not read, but named: an output over it would destroy a file the model names.
            note_named(resolved);
            return {Verdict::Refused,
                    "is outside the model's folder (" + resolved.string() + " is not under " +
                        root_.string() + ")",
                    true};
        }
    }
    if (::access(resolved.c_str(), R_OK) != 0)
        return {Verdict::Refused,
                "cannot be read (" + std::generic_category().message(errno) + ")"};
    note_named(resolved);
    return {Verdict::Readable, {}};
}

void ReferencePolicy::note_named(const std::filesystem::path& resolved) const {
    if (resolved == model_) return;
    const std::lock_guard lock(read_->mutex);
    read_->files.insert(resolved);
}

std::vector<std::filesystem::path> ReferencePolicy::files_read() const {
    const std::lock_guard lock(read_->mutex);
    return {read_->files.begin(), read_->files.end()};
}

std::string ReferencePolicy::Check::advice() const {
    return outside ? std::string(" (") + how_to_allow() + ")" : std::string();
}

const char* ReferencePolicy::how_to_allow() {
    return "--allow-outside-references or LoadOptions::allow_outside_references reads files "
           "outside the model's folder";
}

}  // namespace zraster::io
