// A file the command reads as a stream (--list, --views-json), opened so that a FIFO or device
// with no writer cannot block the open for ever: `--list <(find ...)` (a pipe) works, a FIFO
// nothing writes reads as empty.
#pragma once
#include <filesystem>
#include <istream>
#include <memory>
#include <string>

namespace zraster::cli {

// The file opened for reading. Throws InputError naming `what` ("--list FILE") when it is a
// folder or cannot be opened.
std::unique_ptr<std::istream> open_input_stream(const std::filesystem::path& path,
                                                const std::string& what);

}  // namespace zraster::cli
