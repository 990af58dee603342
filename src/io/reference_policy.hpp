// Where a model's external references (glTF buffers and images, OBJ material libraries and
// textures, any file an importer opens besides the model) may be read from. A service rendering
// uploaded files must not read /etc/passwd because a glTF buffer names it, nor block forever on
// a FIFO: by default a reference must be a regular file inside the model's folder, once
// symbolic links are followed (LoadOptions::allow_outside_references lifts the folder rule).
#pragma once
#include <filesystem>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace zraster::io {

class ReferencePolicy {
  public:
    enum class Verdict { Readable, Missing, Refused };
    struct Check {
        Verdict verdict = Verdict::Missing;
        std::string reason;  // for Refused: why, in the user's words
        // Refused only because it lies outside the model's folder: the one refusal
        // allow_outside_references lifts, so the one whose message names it (advice()).
        bool outside = false;

        // " (--allow-outside-references ...)" for a refusal for being outside the folder, else
        // "": a loop of links, a FIFO or a file without read permission stays refused with it.
        std::string advice() const;
    };

    // Allows every regular file (for callers with no model).
    ReferencePolicy() = default;
    ReferencePolicy(const std::filesystem::path& model_path, bool allow_outside);

    // Whether `file` (as an importer would open it: relative to the working directory) may be
    // read. Missing: it does not exist (or is a dangling link); Refused: it exists but is a
    // loop of symbolic links, a directory, not a regular file, not readable (permission), or
    // lies outside the model's folder.
    Check check(const std::filesystem::path& file) const;

    // The advice appended to a refusal's message.
    static const char* how_to_allow();

    // The files besides the model that check() found readable, or refused only for lying outside
    // the model's folder, canonical and sorted: the files the model names and the loader read or
    // could have read, which a command's outputs must not replace (and whose changes a batch
    // rerun notices). Copies of a policy share the list (the texture loader holds one).
    std::vector<std::filesystem::path> files_read() const;

  private:
    void note_named(const std::filesystem::path& resolved) const;
    struct ReadLog {
        std::mutex mutex;
        std::set<std::filesystem::path> files;
    };
    std::shared_ptr<ReadLog> read_ = std::make_shared<ReadLog>();
    std::filesystem::path root_;   // the model's folder, canonical; empty: anywhere
    std::filesystem::path model_;  // the model itself, canonical (readable wherever it is)
};

}  // namespace zraster::io
