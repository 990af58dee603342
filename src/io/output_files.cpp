// OutputFiles: see include/zraster/output_files.hpp.
#include <zraster/error.hpp>
#include <zraster/output_files.hpp>

#include <atomic>
#include <cerrno>
#include <climits>
#include <span>
#include <stdexcept>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace zraster {
namespace {

std::string errno_message(int error) {
    return std::generic_category().message(error);
}

// A name beside `target`, unique per process and call, short enough for any file name limit.
std::filesystem::path sibling(const std::filesystem::path& target, const char* kind) {
    static std::atomic<unsigned> counter{0};
    std::filesystem::path dir = target.parent_path();
    return dir / (".zraster-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + "." +
                  kind);
}

// Writes everything to a new file; returns 0 or the errno of the failure.
int write_new_file(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) return errno;
    int error = 0;
    while (!bytes.empty() && error == 0) {
        const ssize_t n = ::write(fd, bytes.data(), bytes.size());
        if (n < 0 && errno != EINTR) error = errno;
        if (n > 0) bytes = bytes.subspan(static_cast<std::size_t>(n));
    }
    if (::close(fd) != 0 && error == 0) error = errno;
    return error;
}

std::filesystem::path directory_of(const std::filesystem::path& path) {
    const std::filesystem::path parent = path.parent_path();
    return parent.empty() ? std::filesystem::path(".") : parent;
}

// The path made absolute and free of links where it exists, for comparing spellings.
std::filesystem::path identity_of(const std::filesystem::path& path) {
    std::error_code error;
    // Absolute first: weakly_canonical leaves a relative path whose first part does not exist
    // as it is ("out.png"), but resolves "./out.png".
    std::filesystem::path identity =
        std::filesystem::weakly_canonical(std::filesystem::absolute(path, error), error);
    if (error) identity = std::filesystem::absolute(path, error).lexically_normal();
    return identity;
}

// Same spelling once resolved, or the same inode (a hard link, a bind mount).
bool same_file(const std::filesystem::path& identity, const std::filesystem::path& path,
               const std::filesystem::path& other_identity, const std::filesystem::path& other) {
    std::error_code error;
    return identity == other_identity || std::filesystem::equivalent(path, other, error);
}

template <class File>
std::string described(const File& file) {
    return file.what.empty() ? file.path.string() : file.what + " " + file.path.string();
}

}  // namespace

void OutputFiles::check_input(const std::filesystem::path& path, const std::string& what) {
    std::error_code error;
    if (path.empty() || !std::filesystem::exists(path, error)) return;
    Input input{path, what, identity_of(path)};
    for (const Output& output : outputs_)
        if (same_file(output.identity, output.path, input.identity, input.path))
            throw InputError(described(output),
                             "is the same file as the input " + described(input) +
                                 ": an output may not overwrite a file the run reads");
    inputs_.push_back(std::move(input));
}

void OutputFiles::check(const std::filesystem::path& path, const std::string& what) {
    const std::string label = what.empty() ? path.string() : what + " " + path.string();
    if (path.empty()) throw InputError(what, "the output path is empty");
    const std::filesystem::path name = path.filename();
    if (name.empty() || name == "." || name == "..")
        throw InputError(label, "cannot write: the path names a directory, not a file");
    const std::filesystem::path dir = directory_of(path);
    long name_max = ::pathconf(dir.c_str(), _PC_NAME_MAX);
    if (name_max <= 0) name_max = NAME_MAX;
    if (name.string().size() > std::size_t(name_max))
        throw InputError(label, "cannot write: the file name is " +
                                    std::to_string(name.string().size()) +
                                    " bytes long, more than the file system's limit of " +
                                    std::to_string(name_max));
    if (path.string().size() >= std::size_t(PATH_MAX))
        throw InputError(label,
                         "cannot write: the path is " + std::to_string(path.string().size()) +
                             " bytes long, more than the limit of " + std::to_string(PATH_MAX - 1));
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec))
        throw InputError(label, "cannot write: directory '" + dir.string() + "' does not exist");
    if (::access(dir.c_str(), W_OK | X_OK) != 0)
        throw InputError(label, "cannot write: directory '" + dir.string() + "' is not writable (" +
                                    errno_message(errno) + ")");
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (std::filesystem::is_directory(status))
        throw InputError(label, "cannot write: is a directory");
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
        throw InputError(label, "cannot write: exists and is not a regular file");
    const std::filesystem::path identity = identity_of(path);
    for (const Input& input : inputs_)
        if (same_file(identity, path, input.identity, input.path))
            throw InputError(label, "is the same file as the input " + described(input) +
                                        ": an output may not overwrite a file the run reads");
    for (const Output& earlier : outputs_)
        if (same_file(identity, path, earlier.identity, earlier.path))
            throw InputError(label, "is the same file as " +
                                        (earlier.what.empty() ? std::string("an earlier output")
                                                              : described(earlier)) +
                                        ": each output needs a path of its own");
    outputs_.push_back({path, what, identity, {}, false});
}

void OutputFiles::add(const std::filesystem::path& path, std::vector<std::uint8_t> bytes) {
    for (Output& output : outputs_)
        if (output.path == path) {
            output.bytes = std::move(bytes);
            output.added = true;
            return;
        }
    throw std::logic_error("OutputFiles::add: " + path.string() + " was not checked");
}

void OutputFiles::commit() {
    struct Staged {
        const Output* output;
        std::filesystem::path temp, backup;
        bool renamed = false;
    };
    std::vector<Staged> staged;
    std::error_code ec;
    const auto undo = [&] {
        for (Staged& s : staged) {
            if (s.renamed) {
                // Put back what the target held (or remove the new file where there was none).
                if (!s.backup.empty())
                    std::filesystem::rename(s.backup, s.output->path, ec);
                else
                    std::filesystem::remove(s.output->path, ec);
            } else {
                std::filesystem::remove(s.temp, ec);
                if (!s.backup.empty()) std::filesystem::remove(s.backup, ec);
            }
        }
    };
    // 1. Every file's bytes to a temporary beside its target.
    for (const Output& output : outputs_) {
        if (!output.added) continue;
        staged.push_back({&output, sibling(output.path, "tmp"), {}});
        const int error = write_new_file(staged.back().temp, output.bytes);
        if (error != 0) {
            undo();
            throw InputError(output.path.string(), "cannot write: " + errno_message(error) +
                                                       " (no output of this run was written)");
        }
    }
    // 2. A hard link to each file about to be replaced, to put it back if a later rename fails.
    for (Staged& s : staged) {
        if (!std::filesystem::exists(s.output->path, ec)) continue;
        std::filesystem::path backup = sibling(s.output->path, "old");
        if (::link(s.output->path.c_str(), backup.c_str()) == 0) s.backup = std::move(backup);
    }
    // 3. The renames: each atomic; a failure undoes the ones before it.
    for (Staged& s : staged) {
        std::filesystem::rename(s.temp, s.output->path, ec);
        if (ec) {
            const std::string cause = ec.message();
            undo();
            throw InputError(s.output->path.string(),
                             "cannot write: " + cause + " (no output of this run was written)");
        }
        s.renamed = true;
    }
    for (Staged& s : staged)
        if (!s.backup.empty()) std::filesystem::remove(s.backup, ec);
    for (Output& output : outputs_) {
        output.bytes.clear();
        output.bytes.shrink_to_fit();
        output.added = false;
    }
}

}  // namespace zraster
