// The files of one `zraster render` frame (-o, --depth-out, --normal-out, --id-out and the depth
// camera's): their paths checked before any work, then the frame rendered and every file encoded.
// `zraster batch` renders each of its views through these same functions, so that its files are
// byte for byte `zraster render`'s.
#pragma once
#include <zraster/abuffer.hpp>
#include <zraster/output_files.hpp>
#include <zraster/render.hpp>
#include <zraster/scene.hpp>
#include <zraster/visibility.hpp>

#include <cstdio>
#include <string>

#include "render_arguments.hpp"

namespace zraster::cli {

// Checks and reserves every output path the arguments give (extension, then
// OutputFiles::check) and the depth-camera flags' consistency. Throws InputError naming the
// option.
void check_render_outputs(const RenderArguments& arguments, OutputFiles& outputs);

struct RenderedFrame {
    RenderStats stats;
    VisibilityStats visibility;
    ABufferStats abuffer;
    double render_ms = 0.0;  // the camera and the frame
    double encode_ms = 0.0;  // the files' bytes
};

// Renders `scene` as the arguments ask and adds every requested file's bytes to `outputs`
// (checked before with check_render_outputs); writes nothing. `progress` receives the reports of
// long object-space work (null: none); `notes` the notes of debug views (null: none).
// With `renderer`, a pipeline frame (renders_with_pipeline) is drawn by it, reusing its memory
// and threads from the frames before (same bytes); null: a frame of its own.
RenderedFrame render_outputs(const RenderArguments& arguments, const Scene& scene,
                             OutputFiles& outputs, ProgressReporter* progress, std::FILE* notes,
                             Renderer* renderer = nullptr);

}  // namespace zraster::cli
