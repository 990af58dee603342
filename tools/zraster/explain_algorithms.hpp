// The picture makers of `zraster explain`, one file per family: explain_zbuffer.cpp,
// explain_painter.cpp, explain_bsp.cpp, explain_warnock.cpp, explain_abuffer.cpp,
// explain_polygon_clip.cpp, explain_line_clip.cpp, explain_lines.cpp, explain_culling.cpp,
// explain_hiz.cpp.
#pragma once
#include <zraster/render.hpp>
#include <zraster/scene.hpp>

#include "explain_budget.hpp"
#include "explain_output.hpp"
#include "render_arguments.hpp"

namespace zraster::cli {

struct ExplainInput {
    const RenderArguments& arguments;
    const Scene& scene;  // empty for the 2D algorithms
    const RenderOptions& options;
    int step = 0;                                         // 0: about 8 frames
    std::uint64_t max_pixels = kDefaultMaxExplainPixels;  // of all its pictures

    // Progress of a stage of the pictures (options.progress: silent for two seconds).
    void report(const char* stage, double fraction) const {
        if (options.progress != nullptr) options.progress->report(stage, fraction);
    }
};

void explain_zbuffer(const ExplainInput& in, ExplainOutput& out);
void explain_painter(const ExplainInput& in, ExplainOutput& out);
void explain_bsp(const ExplainInput& in, ExplainOutput& out);
void explain_warnock(const ExplainInput& in, ExplainOutput& out);
void explain_abuffer(const ExplainInput& in, ExplainOutput& out);
void explain_sutherland_hodgman(const ExplainInput& in, ExplainOutput& out);
void explain_cohen_sutherland(const ExplainInput& in, ExplainOutput& out);
void explain_liang_barsky(const ExplainInput& in, ExplainOutput& out);
void explain_cyrus_beck(const ExplainInput& in, ExplainOutput& out);
void explain_bresenham(const ExplainInput& in, ExplainOutput& out);
void explain_dda(const ExplainInput& in, ExplainOutput& out);
void explain_frustum_culling(const ExplainInput& in, ExplainOutput& out);
void explain_backface_culling(const ExplainInput& in, ExplainOutput& out);
void explain_occlusion_culling(const ExplainInput& in, ExplainOutput& out);
void explain_hiz(const ExplainInput& in, ExplainOutput& out);

}  // namespace zraster::cli
