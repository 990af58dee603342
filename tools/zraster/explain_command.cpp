// `zraster explain`: the algorithm table, the flags and the folder.
#include "explain_command.hpp"

#include <zraster/error.hpp>

#include <fmt/format.h>

#include <array>

#include "command_line.hpp"
#include "explain_algorithms.hpp"
#include "progress.hpp"

namespace zraster::cli {
namespace {

struct ExplainedAlgorithm {
    const char* name;
    const char* title;
    bool uses_scene;
    void (*make)(const ExplainInput&, ExplainOutput&);
    const char* introduction;
};

constexpr std::array<ExplainedAlgorithm, 15> kExplained = {{
    {"zbuffer", "The z-buffer", true, explain_zbuffer,
     "Triangles are drawn in submission order; each pixel keeps the nearest depth seen so far. "
     "Left: the color buffer, right: the depth buffer (near bright, far dark, empty black)."},
    {"painter", "Painter's algorithm (Newell, Newell & Sancha 1972)", true, explain_painter,
     "Polygons are sorted by their farthest depth and drawn back to front with no depth test; "
     "pairs whose depth ranges overlap are settled by the overlap tests, and where no order "
     "exists one polygon is split by the other's plane."},
    {"bsp", "BSP tree (Fuchs, Kedem & Naylor 1980)", true, explain_bsp,
     "A world-space binary space partition built once: each node's polygon plane splits the "
     "remaining polygons into front and back; a walk that visits the far side first gives a "
     "back-to-front order for any eye position."},
    {"warnock", "Warnock's area subdivision (1969)", true, explain_warnock,
     "The screen is split into quadrants until each region is simple: empty, covered by one "
     "polygon, or surrounded by a polygon in front of all others; otherwise it is too complex "
     "and subdivided, down to single pixels."},
    {"abuffer", "The A-buffer (Carpenter 1984)", true, explain_abuffer,
     "Each pixel keeps a list of fragments: depth, opacity and a mask of the subsamples the "
     "polygon covers. The list is sorted by depth and composited front to back per subsample."},
    {"sutherland-hodgman", "Sutherland-Hodgman polygon clipping (1974)", false,
     explain_sutherland_hodgman,
     "The polygon is clipped against one boundary at a time: each edge keeps its inside "
     "endpoint and adds the crossing point. In 2D against a window, and in homogeneous clip "
     "space (before the divide) for a triangle crossing the near plane."},
    {"cohen-sutherland", "Cohen-Sutherland line clipping", false, explain_cohen_sutherland,
     "Each endpoint gets a 4-bit outcode (left, right, bottom, top). Both 0000: trivially "
     "accepted; a common bit: trivially rejected; otherwise an outside endpoint is moved to a "
     "boundary and the test repeats."},
    {"liang-barsky", "Liang-Barsky line clipping", false, explain_liang_barsky,
     "The segment a + t (b - a) enters and leaves each slab of the window at a parameter t; "
     "the visible part is the interval [largest entering t, smallest leaving t]."},
    {"cyrus-beck", "Cyrus-Beck line clipping", false, explain_cyrus_beck,
     "Liang-Barsky's parameter intervals against any convex window: each edge's inward normal "
     "tells whether the segment enters or leaves there."},
    {"bresenham", "Bresenham's line algorithm (1965)", false, explain_bresenham,
     "One pixel per column (x-major lines) chosen with integer arithmetic: the error term "
     "2 (dy (x - x0) - dx (y - y0)) says how far the ideal line is from the chosen pixel."},
    {"dda", "The digital differential analyzer (DDA)", false, explain_dda,
     "One pixel per step along the major axis; the minor coordinate is accumulated in floating "
     "point (y += slope) and rounded."},
    {"frustum-culling", "View-frustum culling", true, explain_frustum_culling,
     "Triangles wholly outside one plane of the view volume are rejected from their vertices' "
     "outcodes; those crossing a plane are clipped; the rest pass untouched."},
    {"backface-culling", "Back-face culling", true, explain_backface_culling,
     "A triangle whose projected winding is clockwise faces away from the camera and is "
     "dropped before rasterization: about half of a closed mesh."},
    {"occlusion-culling", "Occlusion culling", true, explain_occlusion_culling,
     "Whole instances hidden behind others are skipped before their triangles are read. The "
     "pictures show which instances the final image does not show at all: what an exact "
     "occlusion culler could skip."},
    {"hiz", "Hierarchical z", true, explain_hiz,
     "The rasterizer keeps, per 8x8 block of a tile, the farthest depth stored there, and skips "
     "a triangle's part in a block when its nearest depth cannot pass against that bound. The "
     "pictures are the renderer's debug views (docs/debug-views.md)."},
}};

const ExplainedAlgorithm& find_algorithm(const std::string& name) {
    for (const ExplainedAlgorithm& a : kExplained)
        if (name == a.name) return a;
    std::string names;
    for (const ExplainedAlgorithm& a : kExplained)
        names += (names.empty() ? "" : ", ") + std::string(a.name);
    throw InputError("explain", "unknown algorithm '" + name + "' (" + names + ")");
}

}  // namespace

std::vector<std::string> explained_algorithms() {
    std::vector<std::string> names;
    for (const ExplainedAlgorithm& a : kExplained) names.emplace_back(a.name);
    return names;
}

void add_explain_command(CLI::App& app, ExplainArguments& a) {
    CLI::App* cmd = app.add_subcommand(
        "explain", "Pictures of an algorithm at work, with an index.html (docs/explain.md)");
    std::string names;
    for (const ExplainedAlgorithm& e : kExplained)
        names += (names.empty() ? "" : ", ") + std::string(e.name);
    cmd->add_option("algorithm", a.algorithm, "One of: " + names)->required();
    a.render.size = "480x360";
    a.render.scene = "builtin:default";
    add_render_arguments(*cmd, a.render);
    cmd->add_option("-o,--output", a.output, "Folder for the pictures and index.html")->required();
    cmd->add_option("--step", a.step,
                    "Frames after every STEP triangles or polygons (0: about 8 frames)")
        ->check(CLI::Range(0, 1 << 30))
        ->capture_default_str();
    cmd->add_option("--max-explain-pixels", a.max_pixels,
                    "Refuse runs whose pictures (every frame counted) take more pixels than this")
        ->check(whole_number(false))
        ->capture_default_str();
    cmd->parse_complete_callback([cmd, &a] {
        for (const CLI::Option* option : cmd->get_options())
            if (option->count() > 0) a.given.push_back(option->get_name());
    });
}

int run_explain(const ExplainArguments& a) {
    const ExplainedAlgorithm& algorithm = find_algorithm(a.algorithm);
    // The 2D algorithms draw their own segments and polygons: a scene, a camera or --step would
    // change nothing (budget flags are accepted everywhere, as docs/limits.md says).
    if (!algorithm.uses_scene)
        for (const std::string& name : a.given)
            if (name != "algorithm" && name != "--output" && !name.starts_with("--max-"))
                throw InputError(
                    name == "scene" ? a.render.scene : name,
                    std::string(a.algorithm) +
                        " draws its own figures: it takes no scene, and no size, camera, "
                        "shading or --step (only -o and the --max- budgets)");
    Scene scene;
    RenderOptions options;
    std::vector<std::filesystem::path> files_read;  // besides the model: textures, buffers
    if (algorithm.uses_scene) {
        scene = load_scene_or_procedural(a.render.scene, nullptr, nullptr, &files_read);
        options = make_render_options(a.render, scene);
        options.progress = stderr_progress();  // silent unless a stage runs past two seconds
    }
    ExplainOutput out(a.output, algorithm.title, algorithm.introduction);
    if (algorithm.uses_scene) out.check_input(a.render.scene, "");
    for (const std::filesystem::path& file : files_read)
        out.check_input(file, file_named_by(a.render.scene));
    try {
        algorithm.make(ExplainInput{a.render, scene, options, a.step, a.max_pixels}, out);
    } catch (const LimitExceeded& e) {
        // The algorithms see polygons, not files: name the model, as render does.
        if (!e.file().empty() || scene.name.empty()) throw;
        throw LimitExceeded(scene.name, e.limit(), e.cause());
    }
    out.commit();
    const std::vector<std::string> files = out.file_names();
    fmt::print("explain {}: {} files in {}\n", algorithm.name, files.size(), a.output);
    return kExitOk;
}

}  // namespace zraster::cli
