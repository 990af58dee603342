// The inputs of `zraster batch` (docs/batch.md): found from the command's arguments (files,
// folders searched for every format the loader reads, lists of paths), each with the path its
// outputs take under the output folder; name clashes between them; and the shard each belongs to.
#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace zraster::cli {

struct BatchInput {
    // The file as given, or found: the folder argument joined with the path under it.
    std::filesystem::path source;
    // Where its outputs go under the output folder, without extension, '/'-separated: the path
    // under the folder argument ("obj/bunny"), or the file argument's name ("bunny").
    std::string stem;
};

// The inputs of `paths`, in order. A folder gives every file under it (recursively, symbolic
// links to files followed, to folders not) whose name has_mesh_file_extension(), sorted by
// path; anything else is taken as a file, whether it exists or not (loading it reports what is
// wrong). The same file given twice with the same stem is kept once. The folder `skip` (the
// output folder: its point clouds are .ply files) is not searched. Throws InputError naming a
// folder that cannot be read.
std::vector<BatchInput> find_inputs(const std::vector<std::string>& paths,
                                    const std::filesystem::path& skip = {});

// The paths of a --list file (`-`: `standard_input`): one per line, a trailing '\r' dropped,
// blank lines skipped. Throws InputError naming the list when it cannot be read.
std::vector<std::string> read_path_list(const std::string& list, std::istream& standard_input);

// Throws InputError before any work when two inputs would write the same output file
// (`outputs_of`: an input's output paths), naming both inputs and the file.
void check_output_clashes(
    const std::vector<BatchInput>& inputs,
    const std::function<std::vector<std::filesystem::path>(const BatchInput&)>& outputs_of);

// --shard K/N: the inputs whose stem hashes to K modulo N.
struct Shard {
    std::uint64_t index = 0, count = 1;
};
// "K/N" with 0 <= K < N; throws InputError naming --shard.
Shard parse_shard(const std::string& text);
// FNV-1a, 64 bits, of the bytes of `text`: stable across runs, machines and versions. `hash`:
// the hash of the bytes before `text`, to hash a sequence piece by piece.
std::uint64_t fnv1a64(std::string_view text, std::uint64_t hash = 0xcbf29ce484222325ull);
// fnv1a64(input.stem) % shard.count == shard.index: an input's shard depends on its own output
// path only, not on the other inputs.
bool in_shard(const BatchInput& input, const Shard& shard);

}  // namespace zraster::cli
