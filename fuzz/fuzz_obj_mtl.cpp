// libFuzzer target, structure-aware: the input drives a generator that writes an OBJ file and up
// to three material libraries into the model folder of reference_fixtures.hpp and loads the OBJ.
// The generator makes what random bytes rarely spell: chains of `mtllib` statements (several per
// line, repeated, naming generated libraries, missing ones, "../" escapes, absolute paths, links
// out of the folder, a FIFO, a loop of links, a directory, devices), libraries whose `map_Kd` and
// `map_d` name the same kinds of files, numbers from a palette of non-numbers, huge, negative,
// NaN and infinite values, and face indices from a palette of 0, negative, huge and out of range.
//
// Oracles (besides the sanitizers): refused with one line naming the OBJ (no Assimp internals
// as the cause), or a scene that keeps every promise of load.hpp and holds nothing of the secret
// files outside the folder (unless the input allowed outside references); then drawn at 24x16.
#include <fuzzer/FuzzedDataProvider.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_support.hpp"
#include "reference_fixtures.hpp"

namespace {

using namespace zraster;

const char* const kNumbers[] = {"0",    "1",    "-1",   "0.5", "1e30", "-1e30", "1e39",
                                "nan",  "inf",  "-inf", "abc", "",     "1e-45", "-0",
                                "1.5e", "0x10", ".5",   "1,5", "3e38", "2"};
const char* const kIndices[] = {"1",    "2",          "3",           "4",          "-1",   "-3",
                                "0",    "2147483647", "-2147483648", "4294967296", "99",   "1/1",
                                "2//1", "3/1/1",      "1/99/1",      "x",          "1/-1", "-4"};

std::string pick(FuzzedDataProvider& in, const char* const* items, std::size_t count) {
    return items[in.ConsumeIntegralInRange<std::size_t>(0, count - 1)];
}

std::string reference(FuzzedDataProvider& in, const std::vector<std::string>& names,
                      int generated) {
    const int choice = in.ConsumeIntegralInRange(0, int(names.size()) + generated);
    if (choice < int(names.size())) return names[std::size_t(choice)];
    if (choice < int(names.size()) + generated)
        return "gen" + std::to_string(choice - int(names.size())) + ".mtl";
    return in.ConsumeRandomLengthString(24);
}

std::string generate_mtl(FuzzedDataProvider& in) {
    static const std::vector<std::string> images = fuzz::reference_names(".png");
    std::string mtl;
    const int materials = in.ConsumeIntegralInRange(0, 4);
    for (int m = 0; m < materials; ++m) {
        mtl += "newmtl " + std::string(m % 2 ? "m" : "n") + std::to_string(m / 2) + "\n";
        const int statements = in.ConsumeIntegralInRange(0, 6);
        for (int s = 0; s < statements; ++s) {
            switch (in.ConsumeIntegralInRange(0, 6)) {
                case 0:
                    mtl += "Kd " + pick(in, kNumbers, std::size(kNumbers)) + " " +
                           pick(in, kNumbers, std::size(kNumbers)) + " " +
                           pick(in, kNumbers, std::size(kNumbers)) + "\n";
                    break;
                case 1:
                    mtl += "d " + pick(in, kNumbers, std::size(kNumbers)) + "\n";
                    break;
                case 2:
                    mtl += "Tr " + pick(in, kNumbers, std::size(kNumbers)) + "\n";
                    break;
                case 3:
                    mtl += "Ns " + pick(in, kNumbers, std::size(kNumbers)) + "\n";
                    break;
                case 4:
                    mtl += "map_d " + reference(in, images, 0) + "\n";
                    break;
                default:
                    mtl += "map_Kd " + reference(in, images, 0) + "\n";
                    break;
            }
        }
    }
    return mtl;
}

std::string generate_obj(FuzzedDataProvider& in, int libraries) {
    static const std::vector<std::string> mtls = fuzz::reference_names(".mtl");
    std::string obj;
    const int mtllib_lines = in.ConsumeIntegralInRange(0, 3);
    for (int l = 0; l < mtllib_lines; ++l) {
        obj += "mtllib";
        const int names = in.ConsumeIntegralInRange(1, 3);
        for (int n = 0; n < names; ++n) obj += " " + reference(in, mtls, libraries);
        obj += "\n";
    }
    const int vertices = in.ConsumeIntegralInRange(3, 8);
    for (int v = 0; v < vertices; ++v) {
        const bool plain = in.ConsumeIntegralInRange(0, 3) != 0;
        const auto number = [&] {
            return plain ? std::to_string(in.ConsumeIntegralInRange(-3, 3))
                         : pick(in, kNumbers, std::size(kNumbers));
        };
        obj += "v " + number() + " " + number() + " " + number() + "\n";
        if (in.ConsumeBool()) obj += "vt " + number() + " " + number() + "\n";
        if (in.ConsumeIntegralInRange(0, 3) == 0)
            obj += "vn " + number() + " " + number() + " " + number() + "\n";
    }
    const int statements = in.ConsumeIntegralInRange(1, 12);
    for (int s = 0; s < statements; ++s) {
        switch (in.ConsumeIntegralInRange(0, 9)) {
            case 0:
                obj += "usemtl " + std::string(in.ConsumeBool() ? "m" : "n") +
                       std::to_string(in.ConsumeIntegralInRange(0, 2)) + "\n";
                break;
            case 1:
                obj += (in.ConsumeBool() ? "o g" : "g g") + std::to_string(s) + "\n";
                break;
            case 2:
                obj += "p " + pick(in, kIndices, std::size(kIndices)) + "\n";
                break;
            case 3:
                obj += "l " + pick(in, kIndices, std::size(kIndices)) + " " +
                       pick(in, kIndices, std::size(kIndices)) + "\n";
                break;
            default: {
                const bool plain = in.ConsumeIntegralInRange(0, 3) != 0;
                const int corners = in.ConsumeIntegralInRange(plain ? 3 : 1, plain ? 4 : 6);
                obj += "f";
                for (int c = 0; c < corners; ++c)
                    obj += " " + (plain ? std::to_string(in.ConsumeIntegralInRange(1, vertices))
                                        : pick(in, kIndices, std::size(kIndices)));
                obj += "\n";
            }
        }
    }
    return obj;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider in(data, size);
    const std::filesystem::path& dir = fuzz::reference_model_dir();
    const std::filesystem::path path = dir / "model.obj";
    LoadOptions options = fuzz::fuzz_load_options();
    options.allow_outside_references = in.ConsumeIntegralInRange(0, 7) == 0;
    const int libraries = in.ConsumeIntegralInRange(0, 3);
    for (int l = 0; l < 3; ++l) {
        const std::filesystem::path mtl = dir / ("gen" + std::to_string(l) + ".mtl");
        if (l < libraries)
            fuzz::write_file(mtl, generate_mtl(in));
        else
            std::filesystem::remove(mtl);
    }
    fuzz::write_file(path, generate_obj(in, libraries));

    fuzz::load_reference_model(path, options);
    return 0;
}
