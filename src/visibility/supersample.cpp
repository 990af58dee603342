// Supersampling (SSAA) of the z-buffer path: the brute-force antialiasing the A-buffer is compared
// with (L. Carpenter 1984, "The A-buffer, an antialiased hidden surface method", measures itself
// against it).
//
// What: render() at factor x the resolution in each direction (the options' own shading and
// textures, the unsupersampled frame's camera), then a box filter: each output channel is the exact
// integer mean of its factor x factor block of 8-bit samples, rounded half up. Sample (i, j) of
// output pixel (px, py) is the big image's pixel center, i.e. (px + (i + 0.5) / factor, py + (j +
// 0.5) / factor): for factor 4 the same 4 x 4 grid as the A-buffer's masks.
//
// Cost: factor^2 times the frame's rasterization, shading and memory (every subsample is shaded);
// the filter is O(big pixels). Transparency and cut-outs are render()'s (RenderOptions::
// alpha_mode), per sample.
//
// When to use: as the reference for antialiasing quality, or when per-sample shading matters
// (texture and specular aliasing inside polygons, which the A-buffer does not address).
#include <zraster/abuffer.hpp>
#include <zraster/error.hpp>

#include <string>

namespace zraster {

RenderResult render_supersampled(const Scene& scene, RenderOptions options, int factor) {
    if (factor < 1 || factor > kMaxViewport)
        throw InputError("", "supersampling factor must be between 1 and " +
                                 std::to_string(kMaxViewport) + ", not " + std::to_string(factor));
    const std::int64_t big_width = std::int64_t(options.width) * factor;
    const std::int64_t big_height = std::int64_t(options.height) * factor;
    if (options.width < 1 || options.height < 1 || big_width > kMaxViewport ||
        big_height > kMaxViewport)
        throw InputError("", "supersampled image " + std::to_string(big_width) + " x " +
                                 std::to_string(big_height) + " is out of range (1.." +
                                 std::to_string(kMaxViewport) + " per side)");
    const int width = options.width, height = options.height;
    options.camera = effective_camera(scene, options);
    options.width = int(big_width);
    options.height = int(big_height);
    options.coverage_counts = false;
    RenderResult big = render(scene, options);

    RenderResult result;
    result.stats = big.stats;
    RenderTargets& t = result.targets;
    const RenderTargets& b = big.targets;
    t.width = width;
    t.height = height;
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    const std::size_t bw = std::size_t(big_width);
    const std::size_t f = std::size_t(factor);
    const std::uint64_t count = std::uint64_t(f) * f;
    if (!b.color.empty()) t.color.resize(pixels * 4);
    t.depth.resize(pixels);
    if (!b.normal.empty()) t.normal.resize(pixels);
    if (!b.instance_id.empty()) t.instance_id.resize(pixels);
    if (!b.primitive_id.empty()) t.primitive_id.resize(pixels);
    for (std::size_t py = 0; py < std::size_t(height); ++py) {
        for (std::size_t px = 0; px < std::size_t(width); ++px) {
            const std::size_t p = py * std::size_t(width) + px;
            if (!b.color.empty()) {
                std::uint64_t sum[4] = {0, 0, 0, 0};
                for (std::size_t j = 0; j < f; ++j) {
                    const std::uint8_t* row = &b.color[((py * f + j) * bw + px * f) * 4];
                    for (std::size_t i = 0; i < f * 4; ++i) sum[i & 3] += row[i];
                }
                for (std::size_t c = 0; c < 4; ++c)
                    t.color[p * 4 + c] = std::uint8_t((sum[c] + count / 2) / count);
            }
            const std::size_t q = (py * f + f / 2) * bw + px * f + f / 2;
            t.depth[p] = b.depth[q];
            if (!b.normal.empty()) t.normal[p] = b.normal[q];
            if (!b.instance_id.empty()) t.instance_id[p] = b.instance_id[q];
            if (!b.primitive_id.empty()) t.primitive_id[p] = b.primitive_id[q];
        }
    }
    return result;
}

}  // namespace zraster
