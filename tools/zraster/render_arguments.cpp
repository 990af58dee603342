// The scene, camera and pipeline flags of `zraster render` and `zraster svg`, and the
// RenderOptions they make.
#include "render_arguments.hpp"

#include <zraster/abuffer.hpp>
#include <zraster/clip.hpp>
#include <zraster/depth_buffer.hpp>
#include <zraster/scenes.hpp>

#include <fmt/format.h>
#include <glm/gtx/component_wise.hpp>

#include <algorithm>
#include <cmath>
#include <map>

#include "camera_ranges.hpp"
#include "command_caps.hpp"
#include "command_line.hpp"

namespace zraster::cli {

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

namespace {

// --eye, --target: finite, within the coordinates a camera may use.
glm::dvec3 parse_position(const std::string& option, const std::string& text) {
    const glm::dvec3 p = parse_vec3(option, text);
    if (glm::compMax(glm::abs(p)) > kMaxCameraCoordinate)
        throw InputError(option, text + " is beyond the +-1e32 a camera may use");
    return p;
}

}  // namespace

void add_frame_arguments(CLI::App& cmd, RenderArguments& a) {
    cmd.add_option("--visibility", a.visibility,
                   "Visible-surface algorithm: zbuffer (the pipeline), painter (Newell's "
                   "painter's algorithm), bsp (BSP tree), warnock (area subdivision), all shaded "
                   "as zbuffer (--shading, lights, textures) and painter, bsp, warnock drawing "
                   "every surface opaque; abuffer (Carpenter's A-buffer): shaded as zbuffer, "
                   "antialiased, transparent materials blended in any submission order")
        ->check(CLI::IsMember({"zbuffer", "painter", "bsp", "warnock", "abuffer"}))
        ->capture_default_str();
    cmd.add_option("--view", a.view,
                   "Debug view in place of the shaded color (docs/debug-views.md): none, depth, "
                   "normals, overdraw, hiz, tiles, ids, backfaces, clipped, zfight, mip (or lod); "
                   "with --visibility zbuffer, no --aa or --msaa")
        ->capture_default_str();
    cmd.add_option("--aa", a.aa,
                   "Antialiasing: N x N supersampling of the z-buffer path (every sample "
                   "shaded), or with --msaa N x N multisampling (N = 1, 2, 4, 8; one shading per "
                   "pixel and surface), or with --visibility abuffer the A-buffer's samples per "
                   "side (1, 2, 4, 8; default 4)")
        ->capture_default_str();
    cmd.add_flag("--msaa", a.msaa,
                 "With --aa N and --visibility zbuffer: multisample (coverage and depth per "
                 "sample, shading per pixel) instead of supersampling");
}

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
    cmd.add_option("--max-bin-bytes", a.max_bin_bytes,
                   "Refuse frames whose tile records (triangles times the tiles each covers) take "
                   "more bytes than this")
        ->check(whole_number(false))
        ->capture_default_str();
    cmd.add_option("--max-covered-samples", a.max_covered_samples,
                   "Refuse frames that rasterize every triangle whole (--view overdraw, "
                   "--no-depth-test, --msaa) when the triangles' bounding boxes cover more "
                   "samples than this")
        ->check(whole_number(false))
        ->capture_default_str();
    cmd.add_option("--max-frame-bytes", a.max_frame_bytes_text,
                   "Refuse frames whose working memory, estimated from the vertices and "
                   "triangles over all instances and the image, is more than this (e.g. 8G)")
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
    cmd.add_option("--ortho-height", a.ortho_height,
                   "With --ortho: the view's height in scene units (default: the bounding "
                   "sphere's diameter)");
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
    cmd.add_option("--cull", a.cull,
                   "Face culling auto|back|front|none (auto: back faces, except of double-sided "
                   "materials, glTF doubleSided; back: every back face)")
        ->check(CLI::IsMember({"auto", "back", "front", "none"}))
        ->capture_default_str();
    cmd.add_flag("--no-cull", a.no_cull, "Same as --cull none");
    cmd.add_flag("--occlusion-cull", a.occlusion_cull,
                 "Skip instances hidden behind the largest ones (occlusion buffer; same image)");
    cmd.add_flag("--portal-cull{frustum}", a.portal_cull,
                 "Portal culling through the scene's cells (building:RxC, .cells.json): frustum "
                 "(the flag alone: portals clipped exactly), rectangles (screen cull boxes) or "
                 "off; same image")
        ->check(CLI::IsMember({"off", "rectangles", "frustum"}))
        ->capture_default_str();
    cmd.add_flag("--front-to-back", a.front_to_back,
                 "Draw instances nearest first (hierarchical z then skips more; the image "
                 "changes only where instances meet at exactly equal depth)");
    cmd.add_option("--shading-strategy", a.strategy,
                   "auto (deferred) | forward | deferred (same image)")
        ->check(CLI::IsMember({"auto", "forward", "deferred"}))
        ->capture_default_str();
    cmd.add_option("--alpha-mode", a.alpha_mode,
                   "auto (as the file says: cut-outs alpha-tested, transparent surfaces "
                   "blended) | opaque (every surface opaque)")
        ->check(CLI::IsMember({"auto", "opaque"}))
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
    cmd.add_option("--max-painter-comparisons", a.max_painter_comparisons,
                   "Budget of --visibility painter (and svg --order painter): polygon-pair "
                   "comparisons (0: 2048 per polygon + 10^7, at most 10^8)")
        ->check(whole_number(true))
        ->capture_default_str();
    cmd.add_option("--max-bsp-polygons", a.max_bsp_polygons,
                   "Budget of --visibility bsp (and svg --order bsp): polygons after splitting "
                   "(0: 16 per triangle + 65536, at most 2^22)")
        ->check(whole_number(true))
        ->capture_default_str();
    cmd.add_option("--max-bsp-classifications", a.max_bsp_classifications,
                   "Budget of --visibility bsp (and svg --order bsp): polygon-plane tests while "
                   "building (0: 16 x triangles^2 + 10^7, at most 5 x 10^8)")
        ->check(whole_number(true))
        ->capture_default_str();
    cmd.add_option("--max-projected-polygons", a.max_projected_polygons,
                   "Budget of --visibility painter, warnock, abuffer, --msaa and svg: polygons in "
                   "view after projection (0: 2^19)")
        ->check(whole_number(true))
        ->capture_default_str();
    cmd.add_option("--max-painted-fragments", a.max_painted_fragments,
                   "Budget of --visibility painter and bsp: pixels filled back to front, overdraw "
                   "included (0: 16 per pixel + 2^24, at most 2^26)")
        ->check(whole_number(true))
        ->capture_default_str();
    cmd.add_option("--max-warnock-classifications", a.max_warnock_classifications,
                   "Budget of --visibility warnock: polygon-region tests (0: 64 per polygon per "
                   "subdivision level + 4 per pixel + 10^7)")
        ->check(whole_number(true))
        ->capture_default_str();
    cmd.add_option("--max-abuffer-fragments", a.max_abuffer_fragments,
                   "Budget of --visibility abuffer: polygon-pixel fragments (24 bytes each: "
                   "384 MiB at the default)")
        ->check(whole_number(false))
        ->capture_default_str();
}

namespace {

// Places the camera as the flags say, starting from `camera` (the scene's default framing).
Camera place_camera(const RenderArguments& a, Camera camera, const BoundingSphere& sphere) {
    const double radius = sphere.radius > 0.0 ? sphere.radius : 1.0;
    if (!a.orbit.empty() && (!a.eye.empty() || !a.target.empty()))
        throw InputError("--orbit", std::string("and ") + (a.eye.empty() ? "--target" : "--eye") +
                                        " both place the camera: give one or the other");
    if (!a.orbit.empty()) {
        const glm::dvec3 o = parse_vec3("--orbit", a.orbit);
        if (const std::string problem = orbit_problem(o); !problem.empty())
            throw InputError("--orbit", problem);
        const double distance = o.z * radius;
        camera = orbit_camera(sphere.center, distance, o.x, o.y, camera.fovy_degrees);
        camera.near = std::max(distance - 1.01 * radius, distance * 1e-3);
        camera.far = distance + 1.01 * radius;
    }
    if (!a.eye.empty()) camera.eye = parse_position("--eye", a.eye);
    if (!a.target.empty()) camera.target = parse_position("--target", a.target);
    camera.up = parse_vec3("--up", a.up);
    if (const std::string problem = direction_problem(camera.up); !problem.empty())
        throw InputError("--up", problem);
    if (const std::string problem = pose_problem(camera.eye, camera.target, camera.up);
        !problem.empty())
        throw InputError(!a.target.empty() ? "--target"
                         : !a.eye.empty()  ? "--eye"
                         : !a.orbit.empty() && problem.find("same point") != std::string::npos
                             ? "--orbit"
                             : "--up",
                         problem);
    if (!a.eye.empty() || !a.target.empty()) {
        // Near/far from the bounding sphere as seen from the new eye, unless given.
        const double d = glm::length(sphere.center - camera.eye);
        // Farther, the scene is below a pixel at any field of view and its near and far sides
        // fall within one float of each other.
        if (!a.eye.empty() && !(a.near && a.far) && d > kMaxEyeDistance * radius)
            throw InputError("--eye", fmt::format("{} is {:.3g} scene radii from the scene's "
                                                  "center, more than the {:g} a view can resolve",
                                                  a.eye, d / radius, kMaxEyeDistance));
        camera.near = std::max(d - 1.01 * radius, std::max(d + 1.01 * radius, 1e-6) * 1e-4);
        camera.far = d + 1.01 * radius;
    }
    if (a.fovy) {
        if (const std::string problem = fovy_problem(*a.fovy); !problem.empty())
            throw InputError("--fovy", problem);
        camera.fovy_degrees = *a.fovy;
    }
    if (a.ortho_height && !a.ortho) throw InputError("--ortho-height", "goes with --ortho");
    if (a.ortho) {
        camera.projection = Camera::Projection::Orthographic;
        camera.ortho_height = 2.0 * radius;
        if (a.ortho_height) {
            if (!(std::isfinite(*a.ortho_height) && *a.ortho_height > 0.0))
                throw InputError("--ortho-height", "must be a positive number");
            if (const std::string problem = distance_problem(*a.ortho_height); !problem.empty())
                throw InputError("--ortho-height", problem);
            camera.ortho_height = *a.ortho_height;
        }
    }
    return camera;
}

}  // namespace

Camera default_camera(const std::string& spec, std::span<const glm::vec3> world_positions) {
    if (auto builtin = builtin_camera(spec)) return *builtin;
    return fit_camera(world_positions);
}

RenderOptions make_render_options(const RenderArguments& a, const Scene& scene) {
    if (a.portal_cull != "off" && !scene.cells)
        throw InputError("--portal-cull",
                         "the scene has no cells (building:RxC or a .cells.json file)");
    check_instanced_vertices(scene, parse_byte_size("--max-frame-bytes", a.max_frame_bytes_text));
    const std::vector<glm::vec3> world = scene.world_positions();
    try {
        return make_render_options(a, world, std::nullopt);
    } catch (const InputError& e) {
        if (!e.file().empty()) throw;
        throw InputError(scene.name, e.cause());  // (the camera fit: about the scene)
    }
}

RenderOptions make_render_options(const RenderArguments& a,
                                  std::span<const glm::vec3> world_positions,
                                  const std::optional<Camera>& camera) {
    RenderOptions o;
    const glm::ivec2 size = parse_size("--size", a.size, kMaxViewport);
    const std::uint64_t pixels = std::uint64_t(size.x) * std::uint64_t(size.y);
    if (pixels > a.max_pixels)
        throw InputError("--size", a.size + " is " + std::to_string(pixels) +
                                       " pixels, more than --max-pixels " +
                                       std::to_string(a.max_pixels));
    check_samples_cap("--size", size.x, size.y, a.aa);
    // Supersampling renders the image `aa` times larger a side: that image has the limits of any.
    if (a.aa > 1 && !a.msaa && a.visibility == "zbuffer" &&
        std::int64_t{std::max(size.x, size.y)} * a.aa > kMaxViewport)
        throw InputError("--aa", std::to_string(a.aa) + " times --size " + a.size +
                                     " is more than " + std::to_string(kMaxViewport) +
                                     " pixels a side (lower --aa, or add --msaa)");
    if (a.aa > 1 && !a.msaa && a.visibility == "zbuffer" &&
        pixels * std::uint64_t(a.aa) * std::uint64_t(a.aa) > a.max_pixels)
        throw InputError("--aa", std::to_string(a.aa) + " times --size " + a.size + " is " +
                                     std::to_string(pixels * std::uint64_t(a.aa * a.aa)) +
                                     " pixels, more than --max-pixels " +
                                     std::to_string(a.max_pixels));
    o.width = size.x;
    o.height = size.y;
    o.limits.max_pixels = a.max_pixels;
    o.limits.max_bin_bytes = a.max_bin_bytes;
    o.limits.max_covered_samples = a.max_covered_samples;
    o.limits.max_frame_bytes = parse_byte_size("--max-frame-bytes", a.max_frame_bytes_text);
    o.limits.max_painter_comparisons = a.max_painter_comparisons;
    o.limits.max_bsp_polygons = a.max_bsp_polygons;
    o.limits.max_warnock_classifications = a.max_warnock_classifications;
    o.limits.max_bsp_classifications = a.max_bsp_classifications;
    o.limits.max_projected_polygons = a.max_projected_polygons;
    o.limits.max_painted_fragments = a.max_painted_fragments;
    o.threads = capped_threads("--threads", checked_thread_count("--threads", a.threads));
    if (camera) {
        o.camera = *camera;
    } else {
        o.camera = place_camera(a, default_camera(a.scene, world_positions),
                                bounding_sphere(world_positions));
    }
    for (const auto& [option, value] : {std::pair{"--near", a.near}, std::pair{"--far", a.far}})
        if (value)
            if (const std::string problem = distance_problem(*value); !problem.empty())
                throw InputError(option, problem);
    if (a.near) o.camera->near = *a.near;
    if (a.far) o.camera->far = *a.far;
    if (a.near && a.far && !(*a.near < *a.far))
        throw InputError(
            "--near",
            fmt::format("{} is not below --far {}: the view needs near < far", *a.near, *a.far));
    // One of them given, the other from the camera fit (or the caller's camera).
    if ((a.near || a.far) && !o.camera->infinite_far && !a.infinite_far &&
        !(o.camera->near < o.camera->far))
        throw a.near
            ? InputError("--near", fmt::format("{:g} is not below the far plane {:g} of the "
                                               "camera: the view needs near < far (give "
                                               "--far too)",
                                               o.camera->near, o.camera->far))
            : InputError("--far", fmt::format("{:g} is not beyond the near plane {:g} of "
                                              "the camera: the view needs near < far "
                                              "(give --near too)",
                                              o.camera->far, o.camera->near));
    // A given camera keeps its own depth conventions unless the flags add to them.
    if (!camera || a.reversed_z) o.camera->reversed_z = a.reversed_z;
    if (!camera || a.infinite_far) o.camera->infinite_far = a.infinite_far;
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
        if (const std::string problem = direction_problem(d); !problem.empty())
            throw InputError("--light-dir", problem);
        light.direction = glm::vec3(glm::normalize(d));
        o.lighting.lights.push_back(light);
    }
    for (const std::string& text : a.point_lights) {
        Light light;
        light.type = Light::Type::Point;
        const glm::dvec3 position = parse_vec3("--point-light", text);
        if (const std::string problem = position_problem(position); !problem.empty())
            throw InputError("--point-light", problem);
        light.position = glm::vec3(position);
        o.lighting.lights.push_back(light);
    }
    o.cull = a.no_cull || a.cull == "none" ? CullMode::None
             : a.cull == "front"           ? CullMode::Front
                                           : CullMode::Back;
    // auto: materials' sides count (double-sided ones are not culled and are lit two-sided);
    // an explicit mode applies to every triangle.
    o.material_sides = !a.no_cull && a.cull == "auto";
    o.front_face = a.front_face == "cw" ? FrontFace::Clockwise : FrontFace::CounterClockwise;
    o.occlusion_cull = a.occlusion_cull;
    o.portal_cull = a.portal_cull == "frustum"      ? PortalCull::Frustum
                    : a.portal_cull == "rectangles" ? PortalCull::Rectangles
                                                    : PortalCull::Off;
    if (a.front_to_back) o.instance_order = InstanceOrder::FrontToBack;
    o.strategy = shading_strategy(a.strategy);
    o.alpha_mode = a.alpha_mode == "opaque" ? MaterialAlpha::Opaque : MaterialAlpha::Auto;
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
        if (glm::dvec3(plane) == glm::dvec3(0.0) ||
            glm::length(glm::dvec3(plane)) < kMinDirectionLength)
            throw InputError("--clip-plane", "the normal A,B,C of '" + text +
                                                 "' is zero: the plane keeps everything or "
                                                 "nothing");
        if (const std::string problem = direction_problem(glm::dvec3(plane)); !problem.empty())
            throw InputError("--clip-plane", problem);
        if (!(std::abs(plane.w) <= kMaxDirectionComponent))
            throw InputError("--clip-plane",
                             fmt::format("D = {} is beyond the +-1e30 a plane may use", plane.w));
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
    const std::optional<DebugView> view = parse_debug_view(a.view);
    if (!view)
        throw InputError("--view", "unknown view '" + a.view + "': one of " + debug_view_names());
    o.view = *view;
    return o;
}

void check_frame_arguments(const RenderArguments& a) {
    if (a.aa < 1 || a.aa > 16) throw InputError("--aa", "must be in 1..16");
    if (a.msaa && a.visibility != "zbuffer")
        throw InputError("--msaa", "works with --visibility zbuffer");
    // Flags that would silently overrule one another.
    if (a.msaa && a.aa == 1)
        throw InputError("--msaa", "needs --aa N: the samples a pixel side (2, 4 or 8)");
    if (a.ortho && a.fovy)
        throw InputError("--fovy",
                         "has no effect with --ortho (the view's height is "
                         "--ortho-height)");
    if (a.infinite_far && a.far)
        throw InputError("--far", "with --infinite-far the far plane is at infinity: give one");
    if (a.no_cull && a.cull != "auto" && a.cull != "none")
        throw InputError("--no-cull", "and --cull " + a.cull + " both set the culling: give one");
    if ((a.wireframe || a.hidden_line) && (a.visibility != "zbuffer" || a.msaa))
        throw InputError(a.wireframe ? "--wireframe" : "--hidden-line",
                         "works with --visibility zbuffer, without --msaa");
    if (a.msaa && a.aa != 1 && a.aa != 2 && a.aa != 4 && a.aa != 8)
        throw InputError("--aa", "with --msaa must be 1, 2, 4 or 8");
    if (a.aa > 1 && a.visibility != "zbuffer" && a.visibility != "abuffer")
        throw InputError("--aa", "works with --visibility zbuffer or abuffer");
    if (a.visibility == "abuffer" && a.aa != 1 && a.aa != 2 && a.aa != 4 && a.aa != 8)
        throw InputError("--aa",
                         "with --visibility abuffer must be 1, 2, 4 or 8 (its mask's "
                         "samples a pixel side)");
    if (a.clip_planes.size() > std::size_t(kMaxUserClipPlanes))
        throw InputError("--clip-plane", fmt::format("given {} times: at most {} planes",
                                                     a.clip_planes.size(), kMaxUserClipPlanes));
    if (a.view != "none" && !renders_with_pipeline(a))
        throw InputError("--view", "works with --visibility zbuffer, without --aa or --msaa");
}

bool renders_with_pipeline(const RenderArguments& a) {
    return a.visibility == "zbuffer" && a.aa == 1 && !a.msaa;
}

RenderResult render_frame(const RenderArguments& a, const Scene& scene,
                          const RenderOptions& options, VisibilityStats* visibility_stats,
                          ABufferStats* abuffer_stats) {
    check_frame_arguments(a);
    if (a.visibility == "abuffer") {
        ABufferOptions abuffer;
        abuffer.samples_per_side = a.aa == 1 ? 4 : a.aa;
        abuffer.max_fragments = a.max_abuffer_fragments;
        return render_abuffer(scene, options, abuffer, abuffer_stats);
    }
    if (a.visibility == "zbuffer") {
        return a.msaa     ? render_multisampled(scene, options, a.aa)
               : a.aa > 1 ? render_supersampled(scene, options, a.aa)
                          : render(scene, options);
    }
    return render_with_visibility(scene, options,
                                  a.visibility == "painter" ? VisibilityAlgorithm::Painter
                                  : a.visibility == "bsp"   ? VisibilityAlgorithm::Bsp
                                                            : VisibilityAlgorithm::Warnock,
                                  visibility_stats);
}

}  // namespace zraster::cli
