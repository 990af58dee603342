// libFuzzer target: the parent's side of the loader worker protocol (src/io/worker_message.hpp).
// The bytes are what a crashed, corrupted or hostile importer process could send. They must be
// refused with a one-line InputError naming the file, or give a scene that keeps every promise of
// load.hpp; a decoded scene must encode and decode again to the same bytes, and render.
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>

#include "fuzz_support.hpp"
#include "io/worker_message.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace zraster;
    const std::string file = "input.ply";
    LoadOptions options;
    options.max_triangles = 200'000;
    io::LoadedScene loaded;
    try {
        loaded = io::decode_worker_message(std::span(data, size), file, options);
    } catch (const InputError& e) {
        fuzz::check_input_error(e, file);
        return 0;
    } catch (const std::runtime_error& e) {
        // An internal-error message of the child: rethrown as such (exit status 1 in the
        // command). Any other exception escapes and is a finding.
        if (std::string_view(e.what()).starts_with("in the importer process: ")) return 0;
        throw;
    }
    fuzz::check_loaded_scene(loaded.scene, loaded.warnings);
    const std::string encoded = io::encode_scene_message(loaded);
    const io::LoadedScene again = io::decode_worker_message(
        std::span(reinterpret_cast<const std::uint8_t*>(encoded.data()), encoded.size()), file,
        options);
    if (io::encode_scene_message(again) != encoded) fuzz::fail("encode/decode round trip differs");
    fuzz::check_renders(loaded.scene, "a decoded scene");
    return 0;
}
