// See flag_effects.hpp.
#include "flag_effects.hpp"

#include <zraster/error.hpp>

#include "render/material_alpha.hpp"

namespace zraster::cli {
namespace {

// The first depth-test flag given (null: none). They set the z-buffer's depth buffer: the other
// algorithms order surfaces by their own means (painter's sort, BSP, Warnock's subdivision, the
// A-buffer's lists), MSAA keeps its own per-sample depths (nearest wins), svg draws none.
const char* depth_test_flag(const RenderArguments& a) {
    return a.no_depth_test                                    ? "--no-depth-test"
           : a.no_depth_write                                 ? "--no-depth-write"
           : !a.depth_compare.empty()                         ? "--depth-compare"
           : a.depth_format != RenderArguments{}.depth_format ? "--depth-format"
                                                              : nullptr;
}

void check_depth_test_flags(const RenderArguments& a) {
    if (a.no_depth_test) {
        // (depth_test_flag names --no-depth-test first: the others, without it.)
        RenderArguments others = a;
        others.no_depth_test = false;
        if (const char* flag = depth_test_flag(others))
            throw InputError(flag,
                             "sets the depth test, which --no-depth-test turns off "
                             "(nothing is tested, nothing written)");
    }
    if (a.wireframe)
        if (const char* flag = depth_test_flag(a))
            throw InputError(flag,
                             "sets the depth test: --wireframe draws every edge, with no "
                             "depth test");
    if (a.visibility == "zbuffer" && !a.msaa) return;
    // The object-space algorithms draw by their own ordering: reversed depth changes only the
    // depth image they write.
    if (a.reversed_z && a.depth_out.empty())
        throw InputError("--reversed-z",
                         "stores depth reversed, which changes only the --depth-out image with " +
                             (a.msaa ? std::string("--msaa") : "--visibility " + a.visibility) +
                             ": give --depth-out, or leave it out");
    if (const char* flag = depth_test_flag(a))
        throw InputError(flag, a.msaa ? "sets the z-buffer's depth test, which --msaa does not "
                                        "use (its samples keep the nearest surface)"
                                      : "sets the z-buffer's depth test, which --visibility " +
                                            a.visibility + " does not use");
}

// The cleared depth buffer holds the far end (1, or 0 with reversed-Z): compares that nothing
// nearer passes draw nothing.
std::vector<std::string> depth_compare_warnings(const RenderArguments& a) {
    const std::string& c = a.depth_compare;
    const bool nothing = c == "never" || c == "equal" ||
                         (!a.reversed_z && (c == "greater" || c == "gequal")) ||
                         (a.reversed_z && (c == "less" || c == "lequal"));
    if (!nothing || a.no_depth_test) return {};
    return {"--depth-compare " + c + " passes nothing nearer than the cleared depth buffer (" +
            (a.reversed_z ? "0, the far plane with --reversed-z" : "1, the far plane") +
            "): the image shows only the background" +
            (c == "less" || c == "lequal"      ? "; reversed-Z needs greater or gequal"
             : c == "greater" || c == "gequal" ? "; greater and gequal need --reversed-z"
                                               : "")};
}

// The culling passes and the shading strategy are stages of the z-buffer's tiled pipeline.
void check_pipeline_flags(const RenderArguments& a) {
    if (a.visibility == "zbuffer" && !a.msaa) return;
    const char* flag = a.occlusion_cull                                 ? "--occlusion-cull"
                       : a.portal_cull != RenderArguments{}.portal_cull ? "--portal-cull"
                       : a.strategy != RenderArguments{}.strategy       ? "--shading-strategy"
                       : a.front_to_back                                ? "--front-to-back"
                                                                        : nullptr;
    if (flag == nullptr) return;
    throw InputError(flag, std::string("is a stage of the z-buffer's pipeline, which ") +
                               (a.msaa ? "--msaa does not use"
                                       : "--visibility " + a.visibility + " does not use"));
}

// The first flag that sets how surfaces are shaded or lit (null: none given).
const char* shading_flag(const RenderArguments& a) {
    return a.shading != RenderArguments{}.shading         ? "--shading"
           : !a.light_dirs.empty()                        ? "--light-dir"
           : !a.point_lights.empty()                      ? "--point-light"
           : a.reflection != RenderArguments{}.reflection ? "--reflection"
           : a.infinite_viewer                            ? "--infinite-viewer"
                                                          : nullptr;
}

// The debug views that show no shaded color (docs/debug-views.md); the others draw over it.
bool view_without_shading(const std::string& view) {
    for (const char* v : {"depth", "normals", "overdraw", "ids", "tiles", "mip", "lod"})
        if (view == v) return true;
    return false;
}

void check_shading_flags(const RenderArguments& a) {
    if (const char* flag = a.wireframe ? shading_flag(a) : nullptr)
        throw InputError(flag,
                         "shades surfaces, which --wireframe does not fill (it draws the "
                         "edges alone)");
    if (a.wireframe && (a.no_textures || a.texture_filter != RenderArguments{}.texture_filter))
        throw InputError(a.no_textures ? "--no-textures" : "--texture-filter",
                         "sets the surfaces' textures, which --wireframe does not fill");
    if (const char* flag = view_without_shading(a.view) ? shading_flag(a) : nullptr)
        throw InputError(flag, "shades the image, which --view " + a.view + " replaces");
    if (a.ortho && a.infinite_far)
        throw InputError("--infinite-far",
                         "moves a perspective projection's far plane to infinity: --ortho keeps "
                         "its far plane");
    if (a.shading == "unlit" && (!a.light_dirs.empty() || !a.point_lights.empty()))
        throw InputError(a.light_dirs.empty() ? "--point-light" : "--light-dir",
                         "lights nothing with --shading unlit (colors are drawn as they are)");
    if (a.shading == "unlit" && (a.infinite_viewer || a.reflection != RenderArguments{}.reflection))
        throw InputError(a.infinite_viewer ? "--infinite-viewer" : "--reflection",
                         "shapes highlights, which --shading unlit does not draw");
    if (a.no_textures && a.texture_filter != RenderArguments{}.texture_filter)
        throw InputError("--texture-filter", "filters textures, which --no-textures turns off");
    if (a.ortho && a.interpolation == "linear")
        throw InputError("--interpolation",
                         "linear: with --ortho every interpolation is linear on screen already "
                         "(no perspective to correct for): it changes nothing");
}

}  // namespace

std::vector<std::string> check_flags_take_effect(const RenderArguments& a) {
    check_depth_test_flags(a);
    check_pipeline_flags(a);
    if (a.edge_color != RenderArguments{}.edge_color && !a.wireframe && !a.hidden_line)
        throw InputError("--edge-color",
                         "colors the edges of --wireframe or --hidden-line: "
                         "give one of them");
    check_shading_flags(a);
    return depth_compare_warnings(a);
}

std::vector<std::string> scene_flag_warnings(const RenderArguments& a, const Scene& scene,
                                             bool normal_output) {
    const bool filter = a.texture_filter != RenderArguments{}.texture_filter && !a.no_textures;
    const bool opaque = a.alpha_mode == "opaque";
    const bool linear = a.interpolation == "linear" && a.shading == "flat" && !normal_output;
    if (!filter && !opaque && !linear) return {};
    RenderOptions as_the_file_says;  // alpha as the file says, textures as the flags say
    as_the_file_says.textures = !a.no_textures;
    bool textured = false, all_opaque = true, colored = false;
    for (const Instance& instance : scene.instances) {
        const Mesh& mesh = scene.meshes.at(instance.mesh);
        const Material& m =
            scene.materials.at(mesh.material < scene.materials.size() ? mesh.material : 0);
        const bool uvs = !a.no_textures && !mesh.uvs.empty();
        textured |= uvs && (m.base_color_texture || m.opacity_texture);
        colored |= !mesh.colors.empty();
        all_opaque &= detail::effective_alpha_mode(m, uvs, detail::least_vertex_alpha(mesh.colors),
                                                   as_the_file_says) == AlphaMode::Opaque;
    }
    const std::string name = scene.name.empty() ? "the scene" : scene.name;
    std::vector<std::string> warnings;
    if (filter && !textured)
        warnings.push_back("--texture-filter: " + name +
                           " has no textured surface: the filter changes nothing");
    if (linear && !textured && !colored)
        warnings.push_back("--interpolation linear: with --shading flat, " + name +
                           " interpolates nothing (no texture, no vertex colors, no normal output)"
                           ": it changes nothing");
    if (opaque && all_opaque)
        warnings.push_back("--alpha-mode opaque: every surface of " + name +
                           " is opaque already: it changes nothing");
    return warnings;
}

void check_svg_flags_take_effect(const RenderArguments& a, bool edges, bool edge_width_given) {
    if (const char* flag = depth_test_flag(a))
        throw InputError(flag,
                         "sets the z-buffer's depth test: svg orders polygons (--order), "
                         "it keeps no depth buffer");
    if (a.reversed_z)
        throw InputError("--reversed-z",
                         "stores depth reversed: svg orders polygons (--order), it keeps no "
                         "depth buffer");
    if (!edges && (a.edge_color != RenderArguments{}.edge_color || edge_width_given))
        throw InputError(edge_width_given ? "--edge-width" : "--edge-color",
                         "styles the outlines --edges draws: give --edges");
    check_shading_flags(a);
}

}  // namespace zraster::cli
