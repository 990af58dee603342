// Scanning an OBJ file: its bytes, cut into line-aligned chunks that are parsed in parallel, and
// the character classes every part of the reader uses (blanks, words, control characters).
//
// The number parsers read up to 8 bytes at a time without checking for the end of the file
// (obj_numbers.hpp), so the bytes are followed by zeros. Chunks end at a line break, so that each
// can be parsed on its own: the only thing a chunk needs from the ones before it is how many
// values they read, which only matters once every chunk is parsed (negative indices, line
// numbers).
#pragma once
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace zraster::io::obj {

// The least number of zero bytes after the file.
constexpr std::size_t kPadding = 64;

// The file's bytes, mapped (no copy) or, where mapping fails, read, and followed by at least
// kPadding zero bytes. Throws InputError ("cannot read: ...").
class FileBytes {
  public:
    explicit FileBytes(const std::filesystem::path& path);
    FileBytes(const FileBytes&) = delete;
    FileBytes& operator=(const FileBytes&) = delete;
    ~FileBytes();

    const char* data() const {
        return map_ != nullptr ? static_cast<const char*>(map_) : copy_.data();
    }
    std::size_t size() const { return size_; }

  private:
    bool map(int fd);
    void read_all(int fd, const std::filesystem::path& path);

    void* map_ = nullptr;
    std::size_t map_size_ = 0;
    std::size_t size_ = 0;
    std::vector<char> copy_;
};

struct ByteRange {
    const char* begin = nullptr;
    const char* end = nullptr;
};

// The bytes cut after line breaks into chunks of about size / 256 bytes, at least 256 KiB and at
// most 16 MiB (a chunk is longer when a line is).
std::vector<ByteRange> line_aligned_chunks(const char* data, std::size_t size);

inline bool is_blank(char c) {
    return c == ' ' || c == '\t';
}

inline const char* skip_blanks(const char* q, const char* e) {
    while (q != e && is_blank(*q)) ++q;
    return q;
}

inline const char* skip_word(const char* q, const char* e) {
    while (q != e && !is_blank(*q)) ++q;
    return q;
}

// Control characters other than tab: a lone CR (a line break to Assimp), NUL, form feed, ...
inline bool has_control(const char* q, const char* e) {
    for (; q != e; ++q) {
        const auto c = static_cast<unsigned char>(*q);
        if (c < 0x20 && c != '\t') return true;
    }
    return false;
}

}  // namespace zraster::io::obj
