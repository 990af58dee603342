// One input file of `zraster batch`: loaded once, every view rendered exactly as `zraster render`
// renders it (render_outputs), every output of every view written together, all or nothing
// (OutputFiles), and the record of what happened. What the command runs for each input, from any
// thread, several at once; anything else that renders collections (the Python module) can run
// the same job for the same files.
#pragma once
#include <zraster/load.hpp>
#include <zraster/render.hpp>

#include <atomic>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "batch_history.hpp"
#include "batch_inputs.hpp"
#include "batch_limits.hpp"
#include "batch_record.hpp"
#include "batch_views.hpp"
#include "render_arguments.hpp"

namespace zraster::cli {

// The extra outputs of each view; empty or false: not written. Names (docs/batch.md):
// STEM[SUFFIX].png, then _depth, _z, _range, _normal, _id, _points and _camera before the
// extension.
struct BatchOutputKinds {
    std::string depth;         // "npy" | "png": --depth-out
    std::string z;             // "npy" | "png": --z-out
    std::string id;            // "npy" | "png": --id-out
    bool range = false;        // --range-out (.npy)
    bool normal = false;       // --normal-out (.png)
    bool points = false;       // --points-out (.ply)
    bool camera_json = false;  // --camera-json (.json)
};

struct BatchSettings {
    RenderArguments render;  // every `zraster render` flag; scene and output paths set per file
    BatchOutputKinds outputs;
    std::vector<BatchView> views = single_view();
    LoadOptions load;  // max_triangles: load_triangle_limit(limits)
    BatchLimits limits;
    std::filesystem::path out_dir;
    bool force = false;  // render even when the outputs are up to date
    // What the log says earlier runs wrote (empty with force): see batch_history.hpp.
    std::shared_ptr<const BatchHistory> history = std::make_shared<BatchHistory>();
    // Every output the batch plans (every input's, all shards'), weakly canonical, and the input
    // that writes it: an input whose model reads one of them fails, whichever job runs first.
    std::shared_ptr<const std::map<std::filesystem::path, std::string>> planned_writers =
        std::make_shared<std::map<std::filesystem::path, std::string>>();
};

// The render arguments of one view of one input: `settings.render` with the view's camera, the
// input as the scene and the view's output paths.
RenderArguments view_arguments(const BatchInput& input, const BatchSettings& settings,
                               const BatchView& view);

// Every file the input's views write, view by view in the order above.
std::vector<std::filesystem::path> planned_outputs(const BatchInput& input,
                                                   const BatchSettings& settings);

// Throws InputError naming the option for settings no file could render with (bad flag values,
// combinations `zraster render` refuses, an output folder that cannot be written), so that a
// batch refuses them before any work. Run it once before the jobs.
void check_batch_settings(const BatchSettings& settings);

// Renders one input: Skipped when its outputs are up to date (unless settings.force); Ok when
// every output was written; Error, with nothing written, when the file cannot be read, is over a
// limit, or any view fails. Catches every failure: one file never stops the others. When `stop`
// (may be null) becomes true, the job ends before writing anything and returns Dropped; once the
// outputs are being written they are finished. `renderer` (may be null) draws the frames,
// reusing its memory from file to file: one per thread that runs jobs.
BatchRecord run_batch_job(const BatchInput& input, const BatchSettings& settings,
                          const std::atomic<bool>* stop, Renderer* renderer);

}  // namespace zraster::cli
