// The outputs of one run (an image, its depth map, its normals, ...), written all or nothing:
// either every file appears (or replaces the old one) or none does, whatever fails on the way.
//
//   OutputFiles out;
//   out.check("a.png", "-o");               // before any work: a bad path fails the run early
//   out.check("a-depth.npy", "--depth-out");
//   out.check_input("model.ply", "");     // the files the run reads: no output may replace one
//   ... render ...
//   out.add("a.png", encode_png8(...));     // zraster/image_io.hpp's encoders
//   out.add("a-depth.npy", encode_npy(...));
//   out.commit();
//
// commit() writes every file to a temporary beside its target first; only when all of them are
// written does it rename them over their targets, keeping a hard link to each file it replaces
// so that a failed rename puts every earlier target back. A crash in the middle leaves at most
// temporaries (".zraster-*.tmp") beside the targets, never a truncated output.
#pragma once
#include <zraster/export.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace zraster {

class ZRASTER_API OutputFiles {
  public:
    // Checks an output path before any work and reserves it. Throws InputError naming the path
    // (and `what`, the option or role that gave it) when the name is empty or longer than the
    // file system allows, its directory does not exist or cannot be written, it names a
    // directory or something other than a regular file, or it is the same file as a path
    // checked before (also through another spelling or a symbolic link) or a file the run reads
    // (check_input).
    void check(const std::filesystem::path& path, const std::string& what);

    // Records a file the run reads (the model, a camera or list file): an output that is the
    // same file, checked before or after, is refused, since replacing it would lose the input
    // (`render m.png -o m.png`). Throws InputError naming the output when one already is. A
    // path that does not exist (a procedural scene's spec) is no file and is ignored.
    void check_input(const std::filesystem::path& path, const std::string& what);

    // The bytes of one output, kept until commit(). The path must have been checked.
    void add(const std::filesystem::path& path, std::vector<std::uint8_t> bytes);

    // Writes every added output, all or nothing (see above). Throws InputError naming the path
    // that failed and the cause; then no target has changed.
    void commit();

  private:
    struct Output {
        std::filesystem::path path;
        std::string what;
        std::filesystem::path identity;  // weakly canonical, for the sameness check
        std::vector<std::uint8_t> bytes;
        bool added = false;
    };
    struct Input {
        std::filesystem::path path;
        std::string what;
        std::filesystem::path identity;
    };
    std::vector<Output> outputs_;
    std::vector<Input> inputs_;
};

}  // namespace zraster
