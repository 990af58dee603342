// A mesh file (or a procedural scene such as sphere:10000) to a PNG with zraster::zraster: the
// loader (Assimp and zraster's OBJ reader, untrusted files in a worker process), the engine and
// the PNG writer.
//
//   load_and_render SCENE OUT.png
#include <zraster/error.hpp>
#include <zraster/image_io.hpp>
#include <zraster/load.hpp>
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: load_and_render SCENE OUT.png\n");
        return 2;
    }
    try {
        const std::string spec = argv[1];
        zraster::LoadOptions load;
        load.isolation = zraster::LoadIsolation::WorkerProcess;  // a crashing importer is an error
        std::vector<std::string> warnings;  // a missing texture, ...: the scene is still drawn
        const zraster::Scene scene = zraster::is_procedural_spec(spec)
                                         ? zraster::make_procedural_scene(spec)
                                         : zraster::load_scene(spec, load, &warnings);
        for (const std::string& w : warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());

        zraster::RenderOptions options;  // no camera: the scene is framed as `zraster` does
        options.width = 640;
        options.height = 480;
        const zraster::RenderResult result = zraster::render(scene, options);
        zraster::write_png8(argv[2], options.width, options.height, 4, result.targets.color);
        std::printf("%s: %zu triangles, %llu rasterized\n", argv[1], scene.triangle_count(),
                    static_cast<unsigned long long>(result.stats.triangles_rasterized));
        return result.stats.triangles_rasterized > 0 ? 0 : 1;
    } catch (const zraster::InputError& e) {  // bad file or options: one line naming it
        std::fprintf(stderr, "load_and_render: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "load_and_render: internal error: %s\n", e.what());
        return 1;
    }
}
