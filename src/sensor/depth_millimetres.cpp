// z as 16-bit millimetres, the depth encoding of RGB-D data sets (TUM RGB-D stores 5000 per
// metre, most others 1000; zraster uses 1000).
#include <zraster/depth_camera.hpp>
#include <zraster/error.hpp>

#include <algorithm>
#include <cmath>

namespace zraster {

void depth_millimetres(std::span<const float> z, std::span<std::uint16_t> out) {
    if (z.size() != out.size())
        throw InputError("out", "holds " + std::to_string(out.size()) + " values, z " +
                                    std::to_string(z.size()));
    for (std::size_t i = 0; i < z.size(); ++i) {
        if (!(z[i] > 0.0f)) {
            out[i] = 0;
            continue;
        }
        const double mm = std::min(std::round(double(z[i]) * 1000.0), 65535.0);
        // 0 means "no measurement": a measured point nearer than 0.5 mm keeps the smallest depth.
        out[i] = static_cast<std::uint16_t>(std::max(mm, 1.0));
    }
}

}  // namespace zraster
