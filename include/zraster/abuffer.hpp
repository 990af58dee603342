// The A-buffer and supersampling: antialiased visible-surface determination with
// order-independent transparency (L. Carpenter 1984, "The A-buffer, an antialiased hidden surface
// method", SIGGRAPH '84), and the brute-force comparison, supersampling of the z-buffer path.
//
// A-buffer (src/visibility/abuffer.cpp): every polygon leaves, in every pixel it touches, a
// fragment holding its depth, a subpixel coverage mask and its opacity; a fragment is shaded once,
// as render() shades a pixel (shading mode, lighting, textures, perspective-correct attributes),
// when it first matters. Each pixel's fragment list is sorted by depth and composited front to
// back per subsample, then the samples are averaged: antialiased edges and correct transparency
// for any submission order. On opaque surfaces every pixel a surface covers whole is render()'s
// pixel bit for bit; only pixels along edges differ.
//   Cost: O(touched pixels x samples x polygon edges) to build masks, O(f log f) per pixel to sort
//   its f fragments, one shading per fragment that is visible in at least one sample,
//   O(f x samples) to resolve; memory 24 bytes per fragment (+ 8 per pixel, + about 300 per
//   polygon for shading), bounded by ABufferOptions::max_fragments. When to use: transparent
//   geometry in arbitrary order, and antialiasing without shading every subsample (one color per
//   fragment, as Carpenter's).
//
// Multisampling (src/visibility/multisample.cpp): coverage and depth per subsample (the A-buffer's
// masks), shading once per pixel and visible surface, samples averaged; cut-outs tested once per
// pixel and surface, blended fragments composited per sample. Cost: 8 bytes per sample, shading
// as an aliased frame. When to use: antialiased edges and intersection lines at about the
// shading cost of an aliased frame.
//
// Supersampling (src/visibility/supersample.cpp): render() at factor x the resolution with the
// same options, box-filtered down. Cost: factor^2 times a frame's memory and work (every
// subsample is shaded). Transparency and cut-outs as render() draws them, per sample.
#pragma once
#include <zraster/export.hpp>
#include <zraster/render.hpp>
#include <zraster/visibility.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace zraster {

struct ABufferOptions {
    // Subsamples per pixel side: 1, 2, 4 or 8 (1, 4, 16 or 64 samples; the mask is 64 bits).
    // Sample (i, j) of pixel (px, py) sits at (px + (i + 0.5) / n, py + (j + 0.5) / n), exactly on
    // the rasterizer's 1/256-pixel grid. Other values throw InputError.
    int samples_per_side = 4;
    // Fragments over the whole frame: the memory bound. Each takes 24 bytes, allocated 64 Ki
    // (1.5 MiB) at a time, so the pool never holds more than 24 x max_fragments bytes rounded up
    // to a block: 384 MiB at the default of 2^24 (besides 4 bytes per pixel for the lists' heads
    // and about 2 KB per projected polygon). Exceeding it throws LimitExceeded
    // ("max_abuffer_fragments") before the fragment past it is stored; memory the system refuses
    // below it is an InputError naming the budget.
    std::size_t max_fragments = std::size_t{1} << 24;
};

struct ABufferStats {
    std::uint64_t fragments = 0;              // (polygon, pixel) pairs with a nonzero mask
    std::uint64_t max_list_length = 0;        // longest per-pixel fragment list
    std::uint64_t pixels_with_fragments = 0;  // pixels whose list is not empty
};

// Pixel (x, y) and the samples of it a polygon covers: bit j * n + i is sample (i, j).
struct PixelCoverage {
    int x = 0, y = 0;
    std::uint64_t mask = 0;
};

// The subsample coverage of one polygon inside the viewport, pixels with a nonzero mask only, row
// by row. Exact: integer edge functions on polygon.vertices[].snapped with the rasterizer's
// top-left rule, so polygons sharing an edge partition the samples on it (none covered twice,
// none missed). With samples_per_side = 1 the covered pixels are exactly those render() fills.
// Throws InputError for an unsupported samples_per_side.
ZRASTER_API std::vector<PixelCoverage> polygon_coverage(const ScreenPolygon& polygon,
                                                        const Viewport& viewport,
                                                        int samples_per_side);

// One frame through the A-buffer. Geometry is project_scene's with keep_subpixel (the renderer's
// camera, clipping, back-face culling per options.cull; slivers between pixel centers are kept,
// they may cover subsamples). Fragment alpha = the material's alpha (opacity x base-color texture
// alpha x opacity texture red) sampled where the fragment is shaded (below), clamped to [0, 1];
// with options.alpha_mode Auto, 1 for an Opaque material, and 1 or 0 for a Mask one as it
// reaches the cutoff or not (a fragment of alpha 0 is dropped); every fragment 1 with Opaque),
// fragment depth = the polygon's window-space depth plane at the pixel center. Fragment color =
// the surface shaded as render() shades it (options.shading or the instance's, lighting,
// textures, options.interpolation): a fragment covering every sample is shaded at the pixel
// center (render()'s color there, bit for bit, for a polygon that render() draws there), a partial
// one at the centroid of the samples it covers. A pixel's fragments are ordered by depth, then
// by content (opacity, mask, shaded color) and ids last: nothing that depends on submission
// order decides, and fragments that tie on everything but ids composite identically in either
// order. Then each sample composites the fragments covering it front to back (an opaque one ends
// it), over options.background; samples are averaged and quantized as render() quantizes. The
// result is bit-identical for any submission order and thread count.
// Targets: color (alpha 255); depth, ids and normal (render()'s shading normal) of the nearest
// fragment of each pixel that is not of a Blend material (blended ones write none, as in render())
// (depth stored as render() stores it; cleared where no fragment); no coverage counts. Stats
// (optional): fragment counts; RenderStats::fragments_shaded counts the fragments actually shaded.
// Throws InputError as project_scene does, for a bad samples_per_side, or when the fragment limit
// is exceeded.
RenderResult render_abuffer(const Scene& scene, const RenderOptions& options,
                            const ABufferOptions& abuffer = {}, ABufferStats* stats = nullptr);

// render() at (factor * width) x (factor * height) with the same options (shading, textures,
// lighting) and the same camera as the unsupersampled frame (effective_camera), box-filtered down:
// each color channel is the exact integer mean of the factor^2 samples, rounded half up. Depth, id
// and normal targets take the sample (factor / 2, factor / 2) of each block; no coverage counts.
// Stats are the big frame's. factor = 1 is render(). Throws InputError for factor < 1 or a
// supersampled size render() refuses.
ZRASTER_API RenderResult render_supersampled(const Scene& scene, RenderOptions options, int factor);

// Multisampling (MSAA): project_scene's polygons (slivers kept) rasterized into
// samples_per_side^2 samples per pixel (the A-buffer's grid and exact masks), each sample keeping
// the nearest polygon by its window-depth plane at the sample (equal depths: the first drawn).
// Each pixel then shades every polygon that holds one of its samples once, as the A-buffer shades
// a fragment (render()'s color at the pixel center when it holds every sample, else at the
// centroid of its samples), and averages the samples (background where none), quantized as
// render() quantizes. Materials' alpha (options.alpha_mode Auto): one alpha per polygon and
// pixel, sampled where the polygon is shaded there (the pixel center when it covers every sample:
// render()'s alpha; else the centroid of its samples); a Mask polygon failing the test there
// covers none of the pixel's samples; Blend polygons write no sample depth and are composited per
// sample, farthest first by their depth at the pixel center, over the sample's opaque color where
// they lie in front of it. Depth, ids and normal: the opaque polygon of sample (n / 2, n / 2).
// Throws InputError as project_scene does, for samples_per_side other than 1, 2, 4, 8, or when
// width x height x samples exceeds options.limits.max_pixels (the sample buffers take 8 bytes per
// sample), and LimitExceeded ("max_covered_samples") when the polygons' bounding boxes cover more
// than options.limits.max_covered_samples samples (checked before any is rasterized: every
// polygon's samples are, hidden or not). Bit-identical for any thread count.
ZRASTER_API RenderResult render_multisampled(const Scene& scene, const RenderOptions& options,
                                             int samples_per_side);

}  // namespace zraster
