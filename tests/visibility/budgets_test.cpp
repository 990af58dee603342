// The budgets of the object-space algorithms (RenderLimits' max_painter_comparisons,
// max_bsp_polygons, max_projected_polygons, max_painted_fragments, max_warnock_classifications;
// ABufferOptions::max_fragments; and max_covered_samples, of the rasterizing paths that draw every
// fragment): what they are
// by default, that random interpenetrating triangles are refused by name long before they cost
// minutes or gigabytes, that real meshes stay far inside them, and the progress reports.
#include <zraster/abuffer.hpp>
#include <zraster/error.hpp>
#include <zraster/load.hpp>
#include <zraster/scenes.hpp>
#include <zraster/svg.hpp>
#include <zraster/visibility.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "support/test_support.hpp"
#include "visibility/visibility_test_util.hpp"

namespace zraster::test {
namespace {

// Random triangles as big as the scene: nearly every pair overlaps and many cross.
Scene wild_soup(int n) {
    return scene_from_meshes({make_interpenetrating_soup(n, 1.0, 7)});
}

RenderOptions soup_options() {
    RenderOptions options = id_options(320, 240);
    options.cull = CullMode::None;
    return options;
}

// Runs f, which must throw LimitExceeded for `limit`, quickly; returns its message.
template <class F>
std::string refusal(const F& f, const std::string& limit) {
    const auto start = std::chrono::steady_clock::now();
    try {
        f();
    } catch (const LimitExceeded& e) {
        EXPECT_EQ(e.limit(), limit);
        // (Generous: the point is seconds, not the minutes these inputs took before.)
        EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(60));
        return e.what();
    }
    ADD_FAILURE() << "expected LimitExceeded for " << limit;
    return "";
}

TEST(Budgets, AutomaticValuesScaleWithTheInput) {
    const RenderLimits automatic;
    EXPECT_EQ(painter_comparison_budget(automatic, 1000), 2048u * 1000u + 10'000'000u);
    // Capped for time: 10^8 comparisons are 10 to 20 s.
    EXPECT_EQ(painter_comparison_budget(automatic, 1'000'000), 100'000'000u);
    EXPECT_EQ(bsp_polygon_budget(automatic, 1000), 16u * 1000u + 65'536u);
    // Capped for memory (about 1 GB); a larger input is refused before its tree is built.
    EXPECT_EQ(bsp_polygon_budget(automatic, 200'000), 3'265'536u);
    EXPECT_EQ(bsp_polygon_budget(automatic, 1'000'000), std::uint64_t{1} << 22);
    EXPECT_EQ(bsp_polygon_budget(automatic, 20'000'000), std::uint64_t{1} << 22);
    EXPECT_EQ(bsp_classification_budget(automatic, 1000), 16u * 1000u * 1000u + 10'000'000u);
    EXPECT_EQ(bsp_classification_budget(automatic, 1'000'000), 500'000'000u);
    EXPECT_EQ(projected_polygon_budget(automatic), std::uint64_t{1} << 19);
    EXPECT_EQ(painted_fragment_budget(automatic, 1920, 1080),
              16u * 1920u * 1080u + (std::uint64_t{1} << 24));
    EXPECT_EQ(painted_fragment_budget(automatic, 8192, 8192), std::uint64_t{1} << 26);
    EXPECT_EQ(ABufferOptions{}.max_fragments, std::size_t{1} << 24);  // 384 MiB of fragments
    // 1920 is 11 bits: 12 levels of quadtree.
    EXPECT_EQ(warnock_classification_budget(automatic, 1000, 1920, 1080),
              64u * 1000u * 12u + 4u * 1920u * 1080u + 10'000'000u);
    RenderLimits set;
    set.max_painter_comparisons = 5;
    set.max_bsp_polygons = 6;
    set.max_warnock_classifications = 7;
    set.max_projected_polygons = 8;
    set.max_bsp_classifications = 10;
    set.max_painted_fragments = 9;
    EXPECT_EQ(painter_comparison_budget(set, 1000), 5u);
    EXPECT_EQ(bsp_polygon_budget(set, 1000), 6u);
    EXPECT_EQ(projected_polygon_budget(set), 8u);
    EXPECT_EQ(bsp_classification_budget(set, 1000), 10u);
    EXPECT_EQ(painted_fragment_budget(set, 1920, 1080), 9u);
    EXPECT_EQ(warnock_classification_budget(set, 1000, 1920, 1080), 7u);
}

// 2,000 such triangles took the painter's algorithm a minute and the BSP tree gigabytes.
TEST(Budgets, RandomSoupsAreRefusedByName) {
    const Scene soup = wild_soup(2000);
    const RenderOptions options = soup_options();
    std::string message =
        refusal([&] { render_with_visibility(soup, options, VisibilityAlgorithm::Painter); },
                "max_painter_comparisons");
    EXPECT_NE(message.find("painter's algorithm: more than"), std::string::npos) << message;
    message = refusal([&] { render_with_visibility(soup, options, VisibilityAlgorithm::Bsp); },
                      "max_bsp_polygons");
    EXPECT_NE(message.find("BSP tree: more than " +
                           std::to_string(bsp_polygon_budget(RenderLimits{}, 2000)) + " polygons"),
              std::string::npos)
        << message;
    // The SVG writer's orders have the same budgets (set low here: the refusal is the point).
    RenderOptions low = options;
    low.limits.max_painter_comparisons = 100'000;
    low.limits.max_bsp_polygons = 10'000;
    refusal([&] { svg_polygons(soup, low, SvgOptions::Order::Bsp); }, "max_bsp_polygons");
    refusal([&] { svg_polygons(soup, low, SvgOptions::Order::Painter); },
            "max_painter_comparisons");
}

TEST(Budgets, ExplicitLimitsAreHonouredExactly) {
    const Scene soup = wild_soup(200);
    RenderOptions options = soup_options();
    VisibilityStats stats;
    const RenderResult painted =
        render_with_visibility(soup, options, VisibilityAlgorithm::Painter, &stats);
    const std::uint64_t comparisons = stats.painter.comparisons;
    const std::uint64_t projected = stats.polygons;
    const std::uint64_t painter_fills = painted.stats.fragments_shaded;
    const RenderResult bsp_painted =
        render_with_visibility(soup, options, VisibilityAlgorithm::Bsp, &stats);
    const std::uint64_t splits = stats.bsp.splits;
    const std::uint64_t pool = stats.bsp.input_polygons + 2 * splits;
    const std::uint64_t bsp_fills = bsp_painted.stats.fragments_shaded;
    const std::uint64_t bsp_classifications = stats.bsp.classifications;
    render_with_visibility(soup, options, VisibilityAlgorithm::Warnock, &stats);
    std::uint64_t classifications = 0;
    for (const std::uint64_t c : stats.warnock.classifications) classifications += c;
    ASSERT_GT(comparisons, 1000u);
    ASSERT_GT(splits, 100u);
    ASSERT_GT(projected, 100u);
    ASSERT_GT(painter_fills, 10'000u);
    ASSERT_GT(bsp_fills, 10'000u);

    // Exactly what the run needs passes; one less is refused.
    options.limits.max_painter_comparisons = comparisons;
    options.limits.max_bsp_polygons = pool;
    options.limits.max_warnock_classifications = classifications;
    options.limits.max_projected_polygons = projected;
    options.limits.max_painted_fragments = std::max(painter_fills, bsp_fills);
    options.limits.max_bsp_classifications = bsp_classifications;
    EXPECT_NO_THROW(render_with_visibility(soup, options, VisibilityAlgorithm::Painter));
    EXPECT_NO_THROW(render_with_visibility(soup, options, VisibilityAlgorithm::Bsp));
    EXPECT_NO_THROW(render_with_visibility(soup, options, VisibilityAlgorithm::Warnock));
    RenderOptions exact = options;
    exact.limits.max_painted_fragments = painter_fills;
    EXPECT_NO_THROW(render_with_visibility(soup, exact, VisibilityAlgorithm::Painter));
    exact.limits.max_painted_fragments = bsp_fills;
    EXPECT_NO_THROW(render_with_visibility(soup, exact, VisibilityAlgorithm::Bsp));
    exact.limits.max_painted_fragments = painter_fills - 1;
    std::string message =
        refusal([&] { render_with_visibility(soup, exact, VisibilityAlgorithm::Painter); },
                "max_painted_fragments");
    EXPECT_NE(message.find("painter's algorithm: more than " + std::to_string(painter_fills - 1) +
                           " pixels filled"),
              std::string::npos)
        << message;
    exact.limits.max_painted_fragments = bsp_fills - 1;
    refusal([&] { render_with_visibility(soup, exact, VisibilityAlgorithm::Bsp); },
            "max_painted_fragments");
    exact.limits.max_painted_fragments = 0;
    exact.limits.max_bsp_classifications = bsp_classifications - 1;
    message = refusal([&] { render_with_visibility(soup, exact, VisibilityAlgorithm::Bsp); },
                      "max_bsp_classifications");
    EXPECT_NE(message.find("BSP tree: more than " + std::to_string(bsp_classifications - 1) +
                           " polygon-plane classifications"),
              std::string::npos)
        << message;
    exact.limits.max_bsp_classifications = 0;
    exact.limits.max_projected_polygons = projected - 1;
    message = refusal([&] { render_with_visibility(soup, exact, VisibilityAlgorithm::Warnock); },
                      "max_projected_polygons");
    EXPECT_NE(message.find("more than " + std::to_string(projected - 1) + " polygons in view"),
              std::string::npos)
        << message;
    refusal([&] { render_with_visibility(soup, exact, VisibilityAlgorithm::Painter); },
            "max_projected_polygons");

    options.limits.max_painter_comparisons = comparisons - 1;
    options.limits.max_bsp_polygons = pool - 1;
    options.limits.max_warnock_classifications = classifications - 1;
    refusal([&] { render_with_visibility(soup, options, VisibilityAlgorithm::Painter); },
            "max_painter_comparisons");
    refusal([&] { render_with_visibility(soup, options, VisibilityAlgorithm::Bsp); },
            "max_bsp_polygons");
    message = refusal([&] { render_with_visibility(soup, options, VisibilityAlgorithm::Warnock); },
                      "max_warnock_classifications");
    EXPECT_NE(message.find("Warnock's algorithm: more than " + std::to_string(classifications - 1)),
              std::string::npos)
        << message;
    // A scene of more triangles than the BSP pool may hold is refused before its tree is made.
    options.limits.max_bsp_polygons = 199;
    message = refusal([&] { render_with_visibility(soup, options, VisibilityAlgorithm::Bsp); },
                      "max_bsp_polygons");
    EXPECT_NE(message.find("BSP tree: 200 input triangles, more than the budget of 199"),
              std::string::npos)
        << message;
}

// A convex mesh makes the BSP tree a chain: n^2 classifications, refused by their budget (a
// 100,000-triangle sphere ran for minutes; now about 4 s).
TEST(Budgets, AConvexMeshsChainIsRefusedByItsClassifications) {
    const Scene sphere = scene_from_meshes({make_uv_sphere(1.0f, 100, 50)});
    RenderOptions options = soup_options();
    options.limits.max_bsp_classifications = 2'000'000;
    refusal([&] { render_with_visibility(sphere, options, VisibilityAlgorithm::Bsp); },
            "max_bsp_classifications");
}

// The A-buffer's budget is its fragments (24 bytes each): exactly what a frame stores passes.
TEST(Budgets, ABufferFragmentsExactly) {
    const Scene soup = wild_soup(50);
    const RenderOptions options = soup_options();
    ABufferOptions abuffer;
    ABufferStats stats;
    const RenderResult full = render_abuffer(soup, options, abuffer, &stats);
    ASSERT_GT(stats.fragments, 1000u);
    abuffer.max_fragments = stats.fragments;
    const RenderResult exact = render_abuffer(soup, options, abuffer);
    EXPECT_EQ(exact.targets.color, full.targets.color);
    abuffer.max_fragments = stats.fragments - 1;
    const std::string message =
        refusal([&] { render_abuffer(soup, options, abuffer); }, "max_abuffer_fragments");
    EXPECT_NE(message.find("A-buffer: more than " + std::to_string(stats.fragments - 1) +
                           " fragments (polygon-pixel pairs of 24 bytes"),
              std::string::npos)
        << message;
}

// The paths that rasterize every triangle whole, hidden or not (render() with the depth test
// off, as --view overdraw's count does; multisampling) are budgeted by the samples the
// triangles' bounding boxes cover in the frame: exactly a frame's count passes, with the image
// of the default budget, and one less is refused naming RenderLimits::max_covered_samples.
TEST(Budgets, CoveredSamplesExactly) {
    EXPECT_EQ(RenderLimits{}.max_covered_samples, std::uint64_t{1} << 31);
    const Scene soup = wild_soup(50);
    RenderOptions no_depth_test = soup_options();
    no_depth_test.depth_test = false;
    const std::vector<std::pair<std::string, std::function<RenderResult(const RenderOptions&)>>>
        paths = {{"depth test off", [&](const RenderOptions& o) { return render(soup, o); }},
                 {"multisampled",
                  [&](const RenderOptions& o) { return render_multisampled(soup, o, 4); }}};
    for (const auto& path : paths) {
        // (Named copies: clang does not let lambdas capture structured bindings.)
        const std::string& name = path.first;
        const auto& draw = path.second;
        SCOPED_TRACE(name);
        RenderOptions options = name == "multisampled" ? soup_options() : no_depth_test;
        const RenderResult full = draw(options);
        options.limits.max_covered_samples = 0;
        const std::string counted = refusal([&] { draw(options); }, "max_covered_samples");
        const std::string key = "bounding boxes cover ";
        const std::size_t at = counted.find(key);
        ASSERT_NE(at, std::string::npos) << counted;
        const std::uint64_t needed = std::stoull(counted.substr(at + key.size()));
        ASSERT_GT(needed, 1000u);
        options.limits.max_covered_samples = needed;
        EXPECT_EQ(draw(options).targets.color, full.targets.color);
        options.limits.max_covered_samples = needed - 1;
        const std::string message = refusal([&] { draw(options); }, "max_covered_samples");
        EXPECT_NE(message.find(key + std::to_string(needed) + " samples, more than the limit of " +
                               std::to_string(needed - 1)),
                  std::string::npos)
            << message;
    }
}

// A large triangle placed 50,000 times (a 2 KB glTF can do it): with the depth test off,
// multisampled or transparent it was minutes of rasterizing in bins of a few hundred MB; the
// default budget refuses it before any is rasterized.
TEST(Budgets, StackedLargeTrianglesAreRefusedBeforeRasterizing) {
    Scene stacked = scene_from_meshes({make_interpenetrating_soup(1, 1.0, 7)});
    stacked.instances.assign(50'000, stacked.instances.front());
    RenderOptions options = soup_options();
    options.width = 1920;
    options.height = 1080;
    options.depth_test = false;
    refusal([&] { render(stacked, options); }, "max_covered_samples");
    options.depth_test = true;
    options.width = 256;
    options.height = 256;
    refusal([&] { render_multisampled(stacked, options, 8); }, "max_covered_samples");
    // Transparent, with the depth test: blended triangles write no depth, none hides another (at
    // 640x360, 2.4 x 10^9 samples of a glTF's, this took over a minute and 3.8 GB). Exactly the
    // count passes.
    Material glass;
    glass.opacity = 0.5f;
    stacked.materials.push_back(glass);
    stacked.meshes.front().material = 1;
    options.width = 1280;
    options.height = 720;
    const std::string message = refusal([&] { render(stacked, options); }, "max_covered_samples");
    EXPECT_NE(message.find("blended (transparent) triangles"), std::string::npos) << message;
    stacked.instances.resize(10);
    options.limits.max_covered_samples = 0;
    const std::string counted = refusal([&] { render(stacked, options); }, "max_covered_samples");
    const std::string key = "bounding boxes cover ";
    const std::size_t at = counted.find(key);
    ASSERT_NE(at, std::string::npos) << counted;
    options.limits.max_covered_samples = std::stoull(counted.substr(at + key.size()));
    EXPECT_NO_THROW(render(stacked, options));
    --options.limits.max_covered_samples;
    refusal([&] { render(stacked, options); }, "max_covered_samples");
}

// Real meshes stay well inside the automatic budgets: a fifth of each is enough.
TEST(Budgets, MeshesFitWithAMargin) {
    ZRASTER_REQUIRE_SHARED_DATA();
    for (const char* name : {"obj/bunny-small.obj", "obj/teapot.obj", "3ds/cat.3ds"}) {
        SCOPED_TRACE(name);
        const Scene scene = load_scene(shared_data("meshes") / name);
        RenderOptions options = id_options(640, 480);
        const std::size_t triangles = scene.triangle_count();
        const std::size_t polygons = project_scene(scene, options).size();
        options.limits.max_painter_comparisons = painter_comparison_budget({}, polygons) / 5;
        options.limits.max_bsp_polygons = bsp_polygon_budget({}, triangles) / 5;
        options.limits.max_warnock_classifications =
            warnock_classification_budget({}, polygons, 640, 480) / 5;
        options.limits.max_projected_polygons = projected_polygon_budget({}) / 5;
        options.limits.max_painted_fragments = painted_fragment_budget({}, 640, 480) / 5;
        for (const VisibilityAlgorithm a :
             {VisibilityAlgorithm::Painter, VisibilityAlgorithm::Bsp, VisibilityAlgorithm::Warnock})
            EXPECT_NO_THROW(render_with_visibility(scene, options, a));
    }
}

// Progress: fractions in [0, 1], never decreasing within a stage, from each algorithm.
struct Recorder final : ProgressReporter {
    std::vector<std::pair<std::string, double>> reports;
    void report(const char* stage, double fraction) override {
        reports.emplace_back(stage, fraction);
    }
};

TEST(Budgets, LongWorkReportsProgress) {
    const Scene soup = wild_soup(300);
    RenderOptions options = soup_options();
    options.width = 640;
    options.height = 480;
    // Low budgets keep it short; reports come before any refusal.
    options.limits.max_painter_comparisons = 1'000'000;
    options.limits.max_bsp_polygons = 30'000;
    Recorder recorder;
    options.progress = &recorder;
    const std::pair<VisibilityAlgorithm, const char*> runs[] = {
        {VisibilityAlgorithm::Painter, "painter's algorithm"},
        {VisibilityAlgorithm::Bsp, "BSP tree"},
        {VisibilityAlgorithm::Warnock, "Warnock's algorithm"}};
    for (const auto& [algorithm, stage] : runs) {
        SCOPED_TRACE(stage);
        recorder.reports.clear();
        try {
            render_with_visibility(soup, options, algorithm);
        } catch (const LimitExceeded&) {
            // (Past the low budget: progress was reported on the way.)
        }
        // Each stage's fractions in [0, 1], never decreasing; the algorithm's own stage moves.
        std::map<std::string, double> last;
        for (const auto& [name, fraction] : recorder.reports) {
            EXPECT_TRUE(name == stage || name == "projecting triangles" ||
                        name == "drawing back to front")
                << name;
            EXPECT_GE(fraction, last[name]);
            EXPECT_LE(fraction, 1.0);
            last[name] = fraction;
        }
        EXPECT_GT(last[stage], 0.0);
        if (algorithm != VisibilityAlgorithm::Bsp) {
            EXPECT_TRUE(last.count("projecting triangles"));
        }
    }
}

// The stages outside the algorithms report too: projection (a scene of many triangles took
// Warnock's run 25 s before its first report) and the back-to-front drawing (a million
// coincident triangles took the BSP tree's frame 50 s without a word).
TEST(Budgets, ProjectionAndDrawingReportProgress) {
    // Small triangles: few cross, so the automatic budgets hold.
    const Scene soup = scene_from_meshes({make_interpenetrating_soup(5000, 0.02, 3)});
    RenderOptions options = soup_options();
    Recorder recorder;
    options.progress = &recorder;
    render_with_visibility(soup, options, VisibilityAlgorithm::Bsp);
    double projecting = -1.0, drawing = -1.0;
    for (const auto& [name, fraction] : recorder.reports) {
        if (name == "drawing back to front") drawing = fraction;
    }
    EXPECT_GT(drawing, 0.0);
    recorder.reports.clear();
    render_with_visibility(soup, options, VisibilityAlgorithm::Warnock);
    for (const auto& [name, fraction] : recorder.reports)
        if (name == "projecting triangles") projecting = std::max(projecting, fraction);
    EXPECT_GE(projecting, 0.0);
}

}  // namespace
}  // namespace zraster::test
