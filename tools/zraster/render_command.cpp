// `zraster render`: a scene to a PNG, with optional depth, normal and id outputs.
#include "render_command.hpp"

#include <zraster/abuffer.hpp>
#include <zraster/depth_buffer.hpp>
#include <zraster/image_io.hpp>
#include <zraster/output_files.hpp>
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>
#include <zraster/visibility.hpp>

#include <fmt/format.h>

#include <glm/gtx/component_wise.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <numeric>

#include "command_line.hpp"
#include "output_maps.hpp"
#include "progress.hpp"

namespace zraster::cli {

void add_render_command(CLI::App& app, RenderArguments& a) {
    CLI::App* cmd =
        app.add_subcommand("render", "Render a mesh file or a procedural scene to a PNG");
    add_render_arguments(*cmd, a);
    cmd->add_option("-o,--output", a.output, "Output PNG (color)")->capture_default_str();
    cmd->add_option("--depth-out", a.depth_out,
                    "Depth map: .npy (float32, HxW, window depth in [0,1], 1 = empty) or .png "
                    "(16-bit gray)");
    cmd->add_option("--normal-out", a.normal_out, "World-space normals as PNG (n * 0.5 + 0.5)");
    cmd->add_option("--id-out", a.id_out,
                    "Instance/primitive ids: .npy (int32 primitive id, -1 empty) or .png "
                    "(false color by instance and primitive)");
    cmd->add_flag("--stats", a.print_stats, "Print pipeline statistics");
    cmd->add_option("--visibility", a.visibility,
                    "Visible-surface algorithm: zbuffer (the pipeline), painter (Newell's "
                    "painter's algorithm), bsp (BSP tree), warnock (area subdivision): these four "
                    "draw every surface opaque (material opacity is ignored) and painter, bsp, "
                    "warnock flat-shade; abuffer (Carpenter's A-buffer): shaded as zbuffer, "
                    "antialiased, transparent materials blended in any submission order")
        ->check(CLI::IsMember({"zbuffer", "painter", "bsp", "warnock", "abuffer"}))
        ->capture_default_str();
    cmd->add_option("--aa", a.aa,
                    "Antialiasing: N x N supersampling of the z-buffer path (every sample "
                    "shaded), or with --msaa N x N multisampling (N = 1, 2, 4, 8; one shading per "
                    "pixel and surface), or with --visibility abuffer the A-buffer's samples per "
                    "side (1, 2, 4, 8; default 4)")
        ->capture_default_str();
    cmd->add_flag("--msaa", a.msaa,
                  "With --aa N and --visibility zbuffer: multisample (coverage and depth per "
                  "sample, shading per pixel) instead of supersampling");
    add_depth_camera_options(*cmd, a.depth_camera);
}

namespace {

// Digits only (at most 19): CLI11 reads "-5" into an unsigned as 2^64 - 5, no limit at all.
CLI::Validator whole_number(bool zero_allowed) {
    return CLI::Validator(
        [zero_allowed](const std::string& text) {
            const bool digits = !text.empty() && text.size() <= 19 &&
                                text.find_first_not_of("0123456789") == std::string::npos;
            const bool ok = digits && (zero_allowed || text.find_first_not_of('0') != text.npos);
            return ok ? std::string()
                      : std::string(zero_allowed ? "expected a whole number"
                                                 : "expected a positive whole number") +
                            ", got '" + text + "'";
        },
        zero_allowed ? "UINT" : "POSITIVE");
}

}  // namespace

void add_render_arguments(CLI::App& cmd, RenderArguments& a) {
    cmd.add_option("scene", a.scene,
                   "Mesh file (OBJ, PLY, STL, glTF/GLB, 3DS, OFF, ...) or builtin:default, "
                   "builtin:sphere, builtin:cube, sphere:N, city:N[:SEED], soup:N[:SEED]")
        ->capture_default_str();
    cmd.add_option("--size", a.size, "Image size WIDTHxHEIGHT")->capture_default_str();
    cmd.add_option("--max-pixels", a.max_pixels,
                   "Refuse images of more pixels than this (width * height)")
        ->check(whole_number(false))
        ->capture_default_str();
    cmd.add_option("--max-painter-comparisons", a.max_painter_comparisons,
                   "Budget of --visibility painter (and svg --order painter): polygon-pair "
                   "comparisons (0: 2048 per polygon + 10^7)")
        ->check(whole_number(true))
        ->capture_default_str();
    cmd.add_option("--max-bsp-polygons", a.max_bsp_polygons,
                   "Budget of --visibility bsp (and svg --order bsp): polygons after splitting "
                   "(0: 16 per triangle + 65536, at most 2^24)")
        ->check(whole_number(true))
        ->capture_default_str();
    cmd.add_option("--max-warnock-classifications", a.max_warnock_classifications,
                   "Budget of --visibility warnock: polygon-region tests (0: 64 per polygon per "
                   "subdivision level + 4 per pixel + 10^7)")
        ->check(whole_number(true))
        ->capture_default_str();
    cmd.add_option("--max-abuffer-fragments", a.max_abuffer_fragments,
                   "Budget of --visibility abuffer: polygon-pixel fragments (24 bytes each)")
        ->check(whole_number(false))
        ->capture_default_str();
    cmd.add_option("--threads", a.threads, "Worker threads (0: all cores)")->capture_default_str();
    cmd.add_option("--eye", a.eye, "Camera position X,Y,Z (default: frame the bounding sphere)");
    cmd.add_option("--target", a.target, "Point looked at X,Y,Z");
    cmd.add_option("--up", a.up, "Up vector X,Y,Z")->capture_default_str();
    cmd.add_option("--orbit", a.orbit,
                   "Orbit camera AZIMUTH,ELEVATION,DISTANCE (degrees, degrees, scene radii) around "
                   "the scene center");
    cmd.add_option("--fovy", a.fovy, "Vertical field of view in degrees");
    cmd.add_option("--near", a.near, "Near plane distance");
    cmd.add_option("--far", a.far, "Far plane distance");
    cmd.add_flag("--ortho", a.ortho, "Orthographic projection (frames the bounding sphere)");
    cmd.add_flag("--reversed-z", a.reversed_z, "Reversed-Z projection (near->1, far->0, GREATER)");
    cmd.add_flag("--infinite-far", a.infinite_far, "Far plane at infinity");
    cmd.add_option("--shading", a.shading, "flat|gouraud|phong|unlit")
        ->check(CLI::IsMember({"flat", "gouraud", "phong", "unlit"}))
        ->capture_default_str();
    cmd.add_option("--reflection", a.reflection, "Specular model: blinn-phong|phong")
        ->check(CLI::IsMember({"blinn-phong", "phong"}))
        ->capture_default_str();
    cmd.add_flag("--infinite-viewer", a.infinite_viewer,
                 "Constant view direction for specular (default: local viewer)");
    cmd.add_option("--light-dir", a.light_dirs,
                   "Directional light towards the light X,Y,Z (repeatable; default "
                   "-1/3,2/3,2/3)");
    cmd.add_option("--point-light", a.point_lights, "Point light position X,Y,Z (repeatable)");
    cmd.add_option("--cull", a.cull, "Face culling back|front|none")
        ->check(CLI::IsMember({"back", "front", "none"}))
        ->capture_default_str();
    cmd.add_flag("--no-cull", a.no_cull, "Same as --cull none");
    cmd.add_flag("--occlusion-cull", a.occlusion_cull,
                 "Skip instances hidden behind the largest ones (occlusion buffer; same image)");
    cmd.add_flag("--front-to-back", a.front_to_back,
                 "Draw instances nearest first (hierarchical z then skips more; the image "
                 "changes only where instances meet at exactly equal depth)");
    cmd.add_option("--shading-strategy", a.strategy,
                   "auto (deferred) | forward | deferred (same image)")
        ->check(CLI::IsMember({"auto", "forward", "deferred"}))
        ->capture_default_str();
    cmd.add_option("--front-face", a.front_face, "Front-face winding ccw|cw")
        ->check(CLI::IsMember({"ccw", "cw"}))
        ->capture_default_str();
    cmd.add_option("--depth-format", a.depth_format, "d32f|d24|d16")
        ->check(CLI::IsMember({"d32f", "d24", "d16"}))
        ->capture_default_str();
    cmd.add_option("--depth-compare", a.depth_compare,
                   "never|less|lequal|equal|notequal|gequal|greater|always (default less, "
                   "greater with --reversed-z)")
        ->check(CLI::IsMember(
            {"never", "less", "lequal", "equal", "notequal", "gequal", "greater", "always"}));
    cmd.add_flag("--no-depth-test", a.no_depth_test, "Disable the depth test");
    cmd.add_flag("--no-depth-write", a.no_depth_write, "Do not write depth");
    cmd.add_option("--interpolation", a.interpolation,
                   "perspective|linear (linear = screen-space, shows affine texture warping)")
        ->check(CLI::IsMember({"perspective", "linear"}))
        ->capture_default_str();
    cmd.add_option("--texture-filter", a.texture_filter, "nearest|bilinear|trilinear")
        ->check(CLI::IsMember({"nearest", "bilinear", "trilinear"}))
        ->capture_default_str();
    cmd.add_flag("--no-textures", a.no_textures, "Ignore textures");
    cmd.add_option("--clip-plane", a.clip_planes,
                   "User clip plane A,B,C,D in world space, keeps Ax+By+Cz+D >= 0 (repeatable)");
    cmd.add_option("--background", a.background, "Background color R,G,B (0-255)")
        ->capture_default_str();
    cmd.add_flag("--wireframe", a.wireframe,
                 "Draw every triangle edge (Bresenham lines) instead of the surfaces");
    cmd.add_flag("--hidden-line", a.hidden_line,
                 "Draw the visible triangle edges over the shaded surfaces");
    cmd.add_option("--edge-color", a.edge_color, "Edge color R,G,B (0-255)")->capture_default_str();
}

namespace {

// --eye, --target: finite, within the coordinates a camera may use.
glm::dvec3 parse_position(const std::string& option, const std::string& text) {
    const glm::dvec3 p = parse_vec3(option, text);
    if (glm::compMax(glm::abs(p)) > kMaxCameraCoordinate)
        throw InputError(option, text + " is beyond the +-1e32 a camera may use");
    return p;
}

Camera make_camera(const RenderArguments& a, const Scene& scene, double aspect) {
    Camera camera;
    if (auto builtin = builtin_camera(a.scene)) {
        camera = *builtin;
    } else {
        try {
            camera = fit_camera(scene.world_positions());
        } catch (const InputError& e) {
            throw InputError(scene.source, e.cause());
        }
    }
    const BoundingSphere sphere = bounding_sphere(scene.world_positions());
    const double radius = sphere.radius > 0.0 ? sphere.radius : 1.0;
    if (!a.orbit.empty() && (!a.eye.empty() || !a.target.empty()))
        throw InputError("--orbit", std::string("and ") + (a.eye.empty() ? "--target" : "--eye") +
                                        " both place the camera: give one or the other");
    if (!a.orbit.empty()) {
        const glm::dvec3 o = parse_vec3("--orbit", a.orbit);
        if (!(o.z > 0.0)) throw InputError("--orbit", "distance must be positive");
        const double distance = o.z * radius;
        camera = orbit_camera(sphere.center, distance, o.x, o.y, camera.fovy_degrees);
        camera.near = std::max(distance - 1.01 * radius, distance * 1e-3);
        camera.far = distance + 1.01 * radius;
    }
    if (!a.eye.empty()) camera.eye = parse_position("--eye", a.eye);
    if (!a.target.empty()) camera.target = parse_position("--target", a.target);
    camera.up = parse_vec3("--up", a.up);
    if (!a.eye.empty() || !a.target.empty()) {
        // Near/far from the bounding sphere as seen from the new eye, unless given.
        const double d = glm::length(sphere.center - camera.eye);
        camera.near = std::max(d - 1.01 * radius, std::max(d + 1.01 * radius, 1e-6) * 1e-4);
        camera.far = d + 1.01 * radius;
    }
    if (a.fovy) camera.fovy_degrees = *a.fovy;
    if (a.near) camera.near = *a.near;
    if (a.far) camera.far = *a.far;
    camera.reversed_z = a.reversed_z;
    camera.infinite_far = a.infinite_far;
    if (a.ortho) {
        camera.projection = Camera::Projection::Orthographic;
        camera.ortho_height = 2.0 * radius;
        (void)aspect;
    }
    return camera;
}

}  // namespace

RenderOptions make_render_options(const RenderArguments& a, const Scene& scene) {
    RenderOptions o;
    const glm::ivec2 size = parse_size("--size", a.size, kMaxViewport);
    const std::uint64_t pixels = std::uint64_t(size.x) * std::uint64_t(size.y);
    if (pixels > a.max_pixels)
        throw InputError("--size", a.size + " is " + std::to_string(pixels) +
                                       " pixels, more than --max-pixels " +
                                       std::to_string(a.max_pixels));
    o.width = size.x;
    o.height = size.y;
    o.limits.max_pixels = a.max_pixels;
    o.limits.max_painter_comparisons = a.max_painter_comparisons;
    o.limits.max_bsp_polygons = a.max_bsp_polygons;
    o.limits.max_warnock_classifications = a.max_warnock_classifications;
    o.progress = stderr_progress();
    o.threads = checked_thread_count("--threads", a.threads);
    o.camera = make_camera(a, scene, double(o.width) / double(o.height));
    o.camera = apply_intrinsics(a.depth_camera, *o.camera, o.width, o.height);
    const std::map<std::string, ShadingMode> shading{{"flat", ShadingMode::Flat},
                                                     {"gouraud", ShadingMode::Gouraud},
                                                     {"phong", ShadingMode::Phong},
                                                     {"unlit", ShadingMode::Unlit}};
    o.shading = shading.at(a.shading);
    o.lighting.reflection =
        a.reflection == "phong" ? ReflectionModel::Phong : ReflectionModel::BlinnPhong;
    o.lighting.local_viewer = !a.infinite_viewer;
    if (!a.light_dirs.empty() || !a.point_lights.empty()) o.lighting.lights.clear();
    for (const std::string& text : a.light_dirs) {
        Light light;
        const glm::dvec3 d = parse_vec3("--light-dir", text);
        if (glm::length(d) == 0.0) throw InputError("--light-dir", "direction must be non-zero");
        light.direction = glm::vec3(glm::normalize(d));
        o.lighting.lights.push_back(light);
    }
    for (const std::string& text : a.point_lights) {
        Light light;
        light.type = Light::Type::Point;
        light.position = glm::vec3(parse_vec3("--point-light", text));
        o.lighting.lights.push_back(light);
    }
    o.cull = a.no_cull || a.cull == "none" ? CullMode::None
             : a.cull == "front"           ? CullMode::Front
                                           : CullMode::Back;
    o.front_face = a.front_face == "cw" ? FrontFace::Clockwise : FrontFace::CounterClockwise;
    o.occlusion_cull = a.occlusion_cull;
    if (a.front_to_back) o.instance_order = InstanceOrder::FrontToBack;
    o.strategy = shading_strategy(a.strategy);
    parse_depth_format(a.depth_format, o.depth_format);
    if (!a.depth_compare.empty()) {
        CompareFunc f{};
        parse_compare_func(a.depth_compare, f);
        o.depth_compare = f;
    }
    o.depth_test = !a.no_depth_test;
    o.depth_write = !a.no_depth_write;
    o.interpolation = a.interpolation == "linear" ? Interpolation::ScreenLinear
                                                  : Interpolation::PerspectiveCorrect;
    o.texture_filter = a.texture_filter == "nearest"    ? TextureFilter::Nearest
                       : a.texture_filter == "bilinear" ? TextureFilter::Bilinear
                                                        : TextureFilter::Trilinear;
    o.textures = !a.no_textures;
    for (const std::string& text : a.clip_planes) {
        const glm::dvec4 plane = parse_vec4("--clip-plane", text);
        if (glm::dvec3(plane) == glm::dvec3(0.0))
            throw InputError("--clip-plane", "the normal A,B,C of '" + text +
                                                 "' is zero: the plane keeps everything or "
                                                 "nothing");
        o.clip_planes.push_back(glm::vec4(plane));
    }
    const glm::dvec3 bg = parse_vec3("--background", a.background);
    if (glm::any(glm::lessThan(bg, glm::dvec3(0.0))) ||
        glm::any(glm::greaterThan(bg, glm::dvec3(255.0))))
        throw InputError("--background", "components must be in 0..255");
    o.background = glm::vec3(bg / 255.0);
    if (a.wireframe && a.hidden_line)
        throw InputError("--wireframe", "choose --wireframe or --hidden-line, not both");
    o.edges = a.wireframe     ? RenderOptions::Edges::Wireframe
              : a.hidden_line ? RenderOptions::Edges::HiddenLine
                              : RenderOptions::Edges::None;
    const glm::dvec3 ec = parse_vec3("--edge-color", a.edge_color);
    if (glm::any(glm::lessThan(ec, glm::dvec3(0.0))) ||
        glm::any(glm::greaterThan(ec, glm::dvec3(255.0))))
        throw InputError("--edge-color", "components must be in 0..255");
    o.edge_color = glm::vec3(ec / 255.0);
    return o;
}

namespace {

std::string lower_extension(const std::string& path) {
    std::string e = std::filesystem::path(path).extension().string();
    for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return e;
}

// Checks an output path before any work (its extension, then OutputFiles::check: writable,
// within the name limits, distinct from the run's other outputs), so that a bad one fails the
// run before anything is rendered or written.
void check_output(OutputFiles& outputs, const std::string& path,
                  std::initializer_list<const char*> extensions, const char* option,
                  const char* what) {
    if (path.empty()) return;
    const std::string ext = lower_extension(path);
    bool ok = false;
    std::string names;
    for (const char* e : extensions) {
        ok |= ext == e;
        names += names.empty() ? e : std::string(" or ") + e;
    }
    if (!ok) throw InputError(path, std::string(what) + " must end in " + names);
    outputs.check(path, option);
}

}  // namespace

// Material opacity only counts in the A-buffer: say so when the scene has any to ignore.
void warn_if_transparent(const Scene& scene, const std::string& what) {
    std::size_t transparent = 0;
    std::string first;
    for (const Instance& instance : scene.instances) {
        const Mesh& mesh = scene.meshes.at(instance.mesh);
        const Material& m =
            scene.materials.at(mesh.material < scene.materials.size() ? mesh.material : 0);
        if (m.opacity < 1.0f && transparent++ == 0) first = m.name;
    }
    if (transparent > 0)
        fmt::print(stderr,
                   "note: {} instance(s) have a transparent material (opacity < 1, e.g. '{}'): "
                   "{} draws them opaque; `zraster render --visibility abuffer` blends them\n",
                   transparent, first, what);
}

int run_render(const RenderArguments& a) {
    OutputFiles outputs;  // written together at the end, or not at all
    if (a.output.empty()) throw InputError("-o", "the output path is empty");
    check_output(outputs, a.output, {".png"}, "-o", "the color output");
    check_output(outputs, a.depth_out, {".npy", ".png"}, "--depth-out", "the depth output");
    check_output(outputs, a.normal_out, {".png"}, "--normal-out", "the normal output");
    check_output(outputs, a.id_out, {".npy", ".png"}, "--id-out", "the id output");
    check_depth_camera_arguments(a.depth_camera, a.visibility, a.aa, a.msaa, a.ortho,
                                 a.fovy.has_value(), outputs);
    // Wall-clock times of the stages, for --stats.
    using Clock = std::chrono::steady_clock;
    const auto since = [](Clock::time_point start) {
        return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    };
    const Clock::time_point load_start = Clock::now();
    const Scene scene = load_scene_or_procedural(a.scene);
    const double load_ms = since(load_start);
    for (const std::string& w : scene.warnings) fmt::print(stderr, "warning: {}\n", w);
    const Clock::time_point render_start = Clock::now();
    RenderOptions options = make_render_options(a, scene);
    options.normal_target = !a.normal_out.empty();
    options.id_targets = !a.id_out.empty();
    options.normal_target |= depth_camera_needs_normals(a.depth_camera);
    VisibilityStats visibility_stats;
    ABufferStats abuffer_stats;
    RenderResult result;
    if (a.aa < 1 || a.aa > 16) throw InputError("--aa", "must be in 1..16");
    if (a.msaa && a.visibility != "zbuffer")
        throw InputError("--msaa", "works with --visibility zbuffer");
    if ((a.wireframe || a.hidden_line) && (a.visibility != "zbuffer" || a.msaa))
        throw InputError(a.wireframe ? "--wireframe" : "--hidden-line",
                         "works with --visibility zbuffer, without --msaa");
    if (a.msaa && a.aa != 1 && a.aa != 2 && a.aa != 4 && a.aa != 8)
        throw InputError("--aa", "with --msaa must be 1, 2, 4 or 8");
    if (a.visibility != "abuffer") warn_if_transparent(scene, "--visibility " + a.visibility);
    if (a.visibility == "abuffer") {
        ABufferOptions abuffer;
        abuffer.samples_per_side = a.aa == 1 ? 4 : a.aa;
        abuffer.max_fragments = a.max_abuffer_fragments;
        result = render_abuffer(scene, options, abuffer, &abuffer_stats);
    } else if (a.visibility == "zbuffer") {
        result = a.msaa     ? render_multisampled(scene, options, a.aa)
                 : a.aa > 1 ? render_supersampled(scene, options, a.aa)
                            : render(scene, options);
    } else {
        if (a.aa > 1) throw InputError("--aa", "works with --visibility zbuffer or abuffer");
        result = render_with_visibility(scene, options,
                                        a.visibility == "painter" ? VisibilityAlgorithm::Painter
                                        : a.visibility == "bsp"   ? VisibilityAlgorithm::Bsp
                                                                  : VisibilityAlgorithm::Warnock,
                                        &visibility_stats);
    }
    const RenderTargets& t = result.targets;
    const double render_ms = since(render_start);

    const Clock::time_point write_start = Clock::now();
    // RGBA -> RGB: the alpha channel is always opaque.
    std::vector<std::uint8_t> rgb(std::size_t(t.width) * std::size_t(t.height) * 3);
    for (std::size_t i = 0, n = rgb.size() / 3; i < n; ++i)
        std::copy_n(&t.color[i * 4], 3, &rgb[i * 3]);
    outputs.add(a.output, encode_png8(t.width, t.height, 3, rgb));
    if (!a.depth_out.empty()) outputs.add(a.depth_out, encode_depth_map(a.depth_out, t));
    if (!a.normal_out.empty()) outputs.add(a.normal_out, encode_normal_map(a.normal_out, t));
    if (!a.id_out.empty()) {
        std::vector<std::int64_t> first_triangle;
        std::int64_t total = 0;
        for (const Instance& instance : scene.instances) {
            first_triangle.push_back(total);
            total += static_cast<std::int64_t>(scene.meshes[instance.mesh].triangle_count());
        }
        outputs.add(a.id_out, encode_id_map(a.id_out, t, first_triangle));
    }
    add_depth_camera_outputs(a.depth_camera, scene, options, t, outputs);
    outputs.commit();
    const double write_ms = since(write_start);

    if (a.print_stats && a.visibility == "abuffer")
        fmt::print("abuffer: {} fragments over {} pixels, longest list {}\n",
                   abuffer_stats.fragments, abuffer_stats.pixels_with_fragments,
                   abuffer_stats.max_list_length);
    if (a.print_stats && a.visibility != "zbuffer" && a.visibility != "abuffer") {
        const VisibilityStats& v = visibility_stats;
        std::uint64_t regions = 0;
        for (const std::uint64_t n : v.warnock.regions_per_level) regions += n;
        if (a.visibility == "painter")
            fmt::print(
                "painter: {} polygons, {} comparisons, {} swaps, {} splits ({} forced by "
                "cycles)\n",
                v.polygons, v.painter.comparisons, v.painter.swaps, v.painter.splits,
                v.painter.cycle_splits);
        else if (a.visibility == "bsp")
            fmt::print(
                "bsp: {} input polygons, {} nodes, depth {}, {} splits, {} classifications\n",
                v.bsp.input_polygons, v.bsp.nodes, v.bsp.depth, v.bsp.splits,
                v.bsp.classifications);
        else
            fmt::print("warnock: {} polygons, {} regions in {} levels, {} classifications\n",
                       v.polygons, regions, v.warnock.regions_per_level.size(),
                       std::accumulate(v.warnock.classifications.begin(),
                                       v.warnock.classifications.end(), std::uint64_t{0}));
    }
    if (a.print_stats) {
        const RenderStats& s = result.stats;
        fmt::print(
            "scene {}: {} instances ({} frustum-culled, {} occlusion-culled), {} triangles "
            "in\n",
            a.scene, s.instances, s.instances_frustum_culled, s.instances_occlusion_culled,
            s.triangles_in);
        fmt::print(
            "  trivially rejected {}, clipped {}, back-face culled {}, degenerate {}, "
            "no pixel covered {}, non-finite {}, rasterized {}\n",
            s.triangles_trivially_rejected, s.triangles_clipped, s.triangles_backface_culled,
            s.triangles_degenerate, s.triangles_no_coverage, s.triangles_non_finite,
            s.triangles_rasterized);
        fmt::print(
            "  fragments shaded {} ({}); setup {:.1f} ms, raster {:.1f} ms, total {:.1f} ms\n",
            s.fragments_shaded, s.deferred ? "deferred" : "forward", s.setup_ms, s.raster_ms,
            s.total_ms);
        fmt::print(
            "  camera eye ({:.6g}, {:.6g}, {:.6g}) target ({:.6g}, {:.6g}, {:.6g}) near "
            "{:.6g} far {:.6g}\n",
            s.camera.eye.x, s.camera.eye.y, s.camera.eye.z, s.camera.target.x, s.camera.target.y,
            s.camera.target.z, s.camera.near, s.camera.far);
        fmt::print("  wall time: load {:.1f} ms, camera and render {:.1f} ms, write {:.1f} ms\n",
                   load_ms, render_ms, write_ms);
    }
    return kExitOk;
}

}  // namespace zraster::cli
