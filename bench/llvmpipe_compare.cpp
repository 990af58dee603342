// llvmpipe_compare: zraster against Mesa llvmpipe in ONE process, on the scenes, camera and
// shading of docs/bench-scenes.md. Both render the same float geometry; batches of
// frames alternate between the two (interleaved rounds, the side that goes first alternating),
// so machine noise hits both alike; each side's time is its best round (median of the batch).
//
//   llvmpipe_compare [options] CASE...      CASE = SCENE[@MODE[,MODE...]]
//   SCENE: bunny (../shared/data/meshes/obj/bunny.obj) | mesh path | sphere:N | city:N[:SEED] |
//          soup:N[:SEED]
//   --check renders one frame of each case with both and compares the depth (and color) buffers.
#include <zraster/bench_workload.hpp>
#include <zraster/camera.hpp>
#include <zraster/error.hpp>
#include <zraster/load.hpp>
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <fmt/format.h>
#include <hwy/targets.h>
#include <sys/resource.h>
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench/gl_reference.hpp"

namespace zraster::bench {
namespace {

struct Options {
    std::vector<std::string> cases;
    std::string size = "1920x1080";
    std::string modes = "phong";
    int threads = 0;
    int rounds = 3;
    int frames = 5;
    int warmup = 2;
    bool no_cull = false;
    bool no_avx512 = false;
    bool check = false;
    bool verbose = false;
};

// The reference values glbench prints (BENCH-SCENES.md "Camera" table).
struct Reference {
    const char* name;
    std::size_t triangles;
    std::uint64_t hash;
    float eye[3];
    float near, far;
};
constexpr Reference kReferences[] = {
    {"bunny.obj",
     69666,
     0xffbd53754430e6f7ull,
     {1.09894478f, 1.09894478f, 2.19788957f},
     1.33246779f,
     4.05124044f},
    {"sphere:1000000",
     998000,
     0xa006c80ed0f36341ull,
     {0.816496611f, 0.816496611f, 1.63299322f},
     0.990000069f,
     3.01000023f},
    {"city:20000",
     200002,
     0x2ecc612cd13d8f0eull,
     {122.648422f, 130.645508f, 245.296844f},
     148.710892f,
     452.141205f},
    {"soup:1000000",
     1000000,
     0xcdc28ecb2e3c4d81ull,
     {1.42199349f, 1.42213714f, 2.84399104f},
     1.72423446f,
     5.24236917f},
};

const Reference* find_reference(const std::string& spec) {
    std::string key = spec;
    if (key.ends_with(":1") && (key.starts_with("city:") || key.starts_with("soup:")) &&
        std::count(key.begin(), key.end(), ':') == 2)
        key.resize(key.size() - 2);  // seed 1 is the default
    if (!is_procedural_spec(key)) key = std::filesystem::path(key).filename().string();
    for (const Reference& r : kReferences)
        if (key == r.name) return &r;
    return nullptr;
}

struct BenchScene {
    std::string spec;  // as given (the table's name)
    Scene scene;
    Camera camera;
    std::unique_ptr<GlMesh> gl_mesh;
};

struct SideTimes {
    std::vector<double> round_median;  // one per round
    double min_frame = HUGE_VAL;
    double best() const { return *std::min_element(round_median.begin(), round_median.end()); }
};

struct Case {
    BenchScene* scene;
    BenchMode mode;
    RenderOptions options;
    std::unique_ptr<GlRenderer> gl;
    std::unique_ptr<Renderer> renderer = std::make_unique<Renderer>();
    SideTimes gl_times, zraster_times;
};

using Clock = std::chrono::steady_clock;

double elapsed_ms(Clock::time_point since) {
    return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// CPU seconds of the whole machine and of this process: their difference over the timed phase
// is the load of other processes (the noise indicator glbench prints too).
double machine_cpu_s() {
    std::ifstream f("/proc/stat");
    std::string cpu;
    double user = 0, nice = 0, sys = 0, idle = 0, iowait = 0, irq = 0, softirq = 0;
    f >> cpu >> user >> nice >> sys >> idle >> iowait >> irq >> softirq;
    return (user + nice + sys + irq + softirq) / double(sysconf(_SC_CLK_TCK));
}

double process_cpu_s() {
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    return double(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
           1e-6 * double(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
}

// "WxH" with 1 <= W, H <= kMaxViewport.
glm::ivec2 parse_size(const std::string& text) {
    const std::size_t x = text.find('x');
    int w = 0, h = 0;
    if (x != std::string::npos) {
        const auto r1 = std::from_chars(text.data(), text.data() + x, w);
        const auto r2 = std::from_chars(text.data() + x + 1, text.data() + text.size(), h);
        if (r1.ec == std::errc() && r1.ptr == text.data() + x && r2.ec == std::errc() &&
            r2.ptr == text.data() + text.size() && w >= 1 && h >= 1 && w <= kMaxViewport &&
            h <= kMaxViewport)
            return {w, h};
    }
    throw InputError("--size", "expected WIDTHxHEIGHT with sides 1.." +
                                   std::to_string(kMaxViewport) + ", got '" + text + "'");
}

std::string resolve_scene_path(const std::string& spec) {
    if (spec == "bunny") return std::string(ZRASTER_SHARED_DATA) + "/meshes/obj/bunny.obj";
    return spec;
}

std::vector<BenchMode> parse_modes(const std::string& list) {
    std::vector<BenchMode> modes;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = list.find(',', start);
        modes.push_back(parse_bench_mode("mode", list.substr(start, comma - start)));
        if (comma == std::string::npos) return modes;
        start = comma + 1;
    }
}

std::unique_ptr<BenchScene> load_bench_scene(const std::string& spec) {
    auto s = std::make_unique<BenchScene>();
    s->spec = spec;
    const std::string path = resolve_scene_path(spec);
    std::vector<std::string> warnings;
    s->scene =
        is_procedural_spec(path) ? make_procedural_scene(path) : load_scene(path, {}, &warnings);
    for (const std::string& w : warnings) fmt::print("warning: {}\n", w);
    // The same framing render() does for an unset camera, computed once outside the timing.
    s->camera = fit_camera(s->scene.world_positions());
    const FlatMesh flat = flatten_scene(s->scene);
    const std::uint64_t hash = geometry_hash(flat);
    const Camera& c = s->camera;
    fmt::print("scene {}: {} vertices, {} triangles, geometry_hash {:016x}\n", spec,
               flat.vertex_count(), flat.triangle_count(), hash);
    fmt::print(
        "  camera eye ({:.9g} {:.9g} {:.9g}) target ({:.9g} {:.9g} {:.9g}) near {:.9g} far "
        "{:.9g}\n",
        float(c.eye.x), float(c.eye.y), float(c.eye.z), float(c.target.x), float(c.target.y),
        float(c.target.z), float(c.near), float(c.far));
    if (const Reference* r = find_reference(resolve_scene_path(spec))) {
        const bool hash_ok = hash == r->hash && flat.triangle_count() == r->triangles;
        const bool camera_ok = float(c.eye.x) == r->eye[0] && float(c.eye.y) == r->eye[1] &&
                               float(c.eye.z) == r->eye[2] && float(c.near) == r->near &&
                               float(c.far) == r->far;
        fmt::print("  reference {}: geometry {}, camera {}\n", r->name,
                   hash_ok ? "matches" : fmt::format("MISMATCH (expected {:016x})", r->hash),
                   camera_ok ? "matches" : "MISMATCH");
    }
    s->gl_mesh = std::make_unique<GlMesh>(flat);
    return s;
}

RenderResult render_zraster(Case& c) {
    // Materials are per scene and the modes of a scene share it: set them before each frame
    // (a few assignments, outside the timing).
    apply_bench_shading(c.scene->scene, c.mode);
    return render(c.scene->scene, c.options);
}

double time_zraster_frame(Case& c) {
    apply_bench_shading(c.scene->scene, c.mode);
    // One Renderer per case, as an application keeps one: llvmpipe keeps its context too.
    const auto t0 = Clock::now();
    c.renderer->render(c.scene->scene, c.options);
    return elapsed_ms(t0);
}

double time_gl_frame(Case& c) {
    const auto t0 = Clock::now();
    c.gl->draw();
    return elapsed_ms(t0);
}

void run_batch(Case& c, bool gl, int frames, SideTimes& times) {
    std::vector<double> ms;
    for (int f = 0; f < frames; ++f) ms.push_back(gl ? time_gl_frame(c) : time_zraster_frame(c));
    times.round_median.push_back(median(ms));
    times.min_frame = std::min(times.min_frame, *std::min_element(ms.begin(), ms.end()));
}

int run_check(std::vector<Case>& cases) {
    bool all_ok = true;
    fmt::print(
        "\n| scene | mode | coverage agreement | only llvmpipe | only zraster | max depth "
        "diff | px diff >= 1e-5 | color: max diff, px > 1, px > 8 |\n");
    fmt::print("|---|---|---:|---:|---:|---:|---:|---|\n");
    for (Case& c : cases) {
        c.gl->draw();
        const std::vector<float> gl_depth = c.gl->read_depth();
        const RenderResult zr = render_zraster(c);
        const DepthComparison d = compare_depth(gl_depth, zr.targets.depth);
        std::string color = "-";
        if (c.mode != BenchMode::Depth) {
            const ColorComparison k =
                compare_color(c.gl->read_color(), zr.targets.color, gl_depth, zr.targets.depth);
            color = fmt::format(
                "{}, {} ({:.3f}%), {}", k.max_difference, k.over_1,
                100.0 * double(k.over_1) / double(std::max<std::size_t>(1, k.compared)), k.over_8);
        }
        const bool ok = d.coverage_agreement() > 0.999;
        all_ok &= ok;
        fmt::print("| {} | {} | {:.4f}%{} | {} | {} | {:.3g} | {} | {} |\n", c.scene->spec,
                   bench_mode_name(c.mode), 100.0 * d.coverage_agreement(), ok ? "" : " (LOW)",
                   d.only_gl, d.only_zraster, d.max_abs_difference, d.differing_over_1e5, color);
    }
    return all_ok ? 0 : 1;
}

int run_timing(std::vector<Case>& cases, const Options& o) {
    // Warm-up: llvmpipe JIT-compiles its shader variants on the first draws.
    for (Case& c : cases)
        for (int f = 0; f < o.warmup; ++f) {
            time_gl_frame(c);
            time_zraster_frame(c);
        }
    fmt::print("llvmpipe worker threads observed: {}\n", count_llvmpipe_threads());

    const double machine0 = machine_cpu_s(), self0 = process_cpu_s();
    const auto start = Clock::now();
    for (int r = 0; r < o.rounds; ++r) {
        for (std::size_t i = 0; i < cases.size(); ++i) {
            Case& c = cases[i];
            const bool gl_first = (std::size_t(r) + i) % 2 == 0;
            run_batch(c, gl_first, o.frames, gl_first ? c.gl_times : c.zraster_times);
            run_batch(c, !gl_first, o.frames, gl_first ? c.zraster_times : c.gl_times);
            if (o.verbose)
                fmt::print("round {} {} {}: llvmpipe {:.3f} ms, zraster {:.3f} ms\n", r + 1,
                           c.scene->spec, bench_mode_name(c.mode), c.gl_times.round_median.back(),
                           c.zraster_times.round_median.back());
        }
    }
    const double wall_s = elapsed_ms(start) * 1e-3;
    const double other_load =
        std::max(0.0, (machine_cpu_s() - machine0) - (process_cpu_s() - self0)) / wall_s;
    fmt::print("other processes' CPU load during the timed rounds: {:.2f} CPUs{}\n", other_load,
               other_load >= 0.3 ? " (disturbed: rerun for clean numbers)" : "");

    const RenderOptions& first = cases.front().options;
    fmt::print("\n{}x{}, {} rounds x {} frames, best round's median ms/frame\n\n", first.width,
               first.height, o.rounds, o.frames);
    fmt::print(
        "| scene | mode | threads | llvmpipe ms | zraster ms | ratio (llvmpipe/zraster) |\n");
    fmt::print("|---|---|---:|---:|---:|---:|\n");
    for (const Case& c : cases) {
        const double gl = c.gl_times.best(), zr = c.zraster_times.best();
        fmt::print("| {} | {} | {} | {:.2f} | {:.2f} | {:.2f} |\n", c.scene->spec,
                   bench_mode_name(c.mode), effective_thread_count(c.options.threads), gl, zr,
                   gl / zr);
    }
    return 0;
}

int run(const Options& o) {
    const glm::ivec2 size = parse_size(o.size);
    if (o.rounds < 1 || o.frames < 1 || o.warmup < 0 || o.threads < 0)
        throw InputError("", "--rounds and --frames must be >= 1, --warmup and --threads >= 0");
    if (o.no_avx512) hwy::DisableTargets(HWY_AVX2 - 1);  // the targets better than AVX2

    // The context first: LP_NUM_THREADS must be in the environment before EGL initializes.
    const GlContext context(o.threads);
    fmt::print("GL_RENDERER: {}\nGL_VERSION: {}\nLP_NUM_THREADS={}, zraster threads {}\n",
               context.renderer(), context.version(),
               o.threads > 0 ? std::to_string(o.threads) : "(llvmpipe default)",
               effective_thread_count(o.threads));

    std::vector<std::unique_ptr<BenchScene>> scenes;
    std::vector<Case> cases;
    for (const std::string& item : o.cases) {
        const std::size_t at = item.rfind('@');
        const std::string spec = item.substr(0, at);
        const std::vector<BenchMode> modes =
            parse_modes(at == std::string::npos ? o.modes : item.substr(at + 1));
        BenchScene* scene = nullptr;
        for (const auto& s : scenes)
            if (s->spec == spec) scene = s.get();
        if (!scene) {
            scenes.push_back(load_bench_scene(spec));
            scene = scenes.back().get();
        }
        for (const BenchMode mode : modes) {
            Case c;
            c.scene = scene;
            c.mode = mode;
            c.options = bench_render_options(mode, size.x, size.y, o.threads, !o.no_cull);
            c.options.camera = scene->camera;
            c.gl = std::make_unique<GlRenderer>(*scene->gl_mesh, mode, size.x, size.y, !o.no_cull,
                                                scene->camera);
            cases.push_back(std::move(c));
        }
    }
    return o.check ? run_check(cases) : run_timing(cases, o);
}

}  // namespace
}  // namespace zraster::bench

int main(int argc, char** argv) {
    zraster::bench::Options o;
    CLI::App app{"zraster against Mesa llvmpipe, interleaved in one process", "llvmpipe_compare"};
    app.add_option("cases", o.cases,
                   "SCENE[@MODE[,MODE...]]; SCENE = bunny | mesh path | sphere:N | "
                   "city:N[:SEED] | soup:N[:SEED]")
        ->required();
    app.add_option("--modes", o.modes, "Modes for cases without @: depth,flat,phong")
        ->capture_default_str();
    app.add_option("--size", o.size, "Image size WIDTHxHEIGHT")->capture_default_str();
    app.add_option("--threads", o.threads,
                   "Threads for both (LP_NUM_THREADS and zraster); 0: each one's default")
        ->capture_default_str();
    app.add_option("--rounds", o.rounds, "Interleaved rounds")->capture_default_str();
    app.add_option("--frames", o.frames, "Frames per batch")->capture_default_str();
    app.add_option("--warmup", o.warmup, "Untimed frames per side first")->capture_default_str();
    app.add_flag("--no-cull", o.no_cull, "Disable back-face culling");
    app.add_flag("--no-avx512", o.no_avx512,
                 "zraster runs its AVX2 kernels where AVX-512 is available (llvmpipe unchanged)");
    app.add_flag("--check", o.check, "Compare one frame's depth and color instead of timing");
    app.add_flag("--verbose", o.verbose, "Print every round");
    CLI11_PARSE(app, argc, argv);
    try {
        return zraster::bench::run(o);
    } catch (const zraster::InputError& e) {
        fmt::print(stderr, "llvmpipe_compare: {}\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        fmt::print(stderr, "llvmpipe_compare: {}\n", e.what());
        return 1;
    }
}
