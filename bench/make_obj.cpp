// Writes the benchmark sphere (the geometry of `sphere:N`, BENCH-SCENES.md) as an OBJ file with
// `v`, `vn` and `f v//vn` lines, six decimals as Blender writes them, for timing the OBJ loader
// end to end. Standalone (no zraster dependency):
//   g++ -std=c++20 -O2 bench/make_obj.cpp -o make_obj && ./make_obj 1000000 sphere-1m.obj
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s TRIANGLES OUT.obj\n", argv[0]);
        return 2;
    }
    const long n = std::atol(argv[1]);
    if (n < 1) {
        std::fprintf(stderr, "TRIANGLES must be positive\n");
        return 2;
    }
    std::FILE* out = std::fopen(argv[2], "wb");
    if (out == nullptr) {
        std::perror(argv[2]);
        return 1;
    }
    const long stacks = std::max(2L, std::lround(std::sqrt(double(n) / 4.0)));
    const long slices = 2 * stacks;
    std::fprintf(out, "# sphere:%ld, %ld stacks x %ld slices\no sphere\n", n, stacks, slices);
    std::string normals;
    char line[128];
    for (long i = 0; i <= stacks; ++i) {
        const double theta = std::numbers::pi * double(i) / double(stacks);
        for (long j = 0; j <= slices; ++j) {
            const double phi = 2.0 * std::numbers::pi * double(j) / double(slices);
            const float x = float(std::sin(theta) * std::cos(phi)), y = float(std::cos(theta)),
                        z = float(-std::sin(theta) * std::sin(phi));
            std::fprintf(out, "v %.6f %.6f %.6f\n", x, y, z);
            std::snprintf(line, sizeof line, "vn %.6f %.6f %.6f\n", x, y, z);
            normals += line;
        }
    }
    std::fputs(normals.c_str(), out);
    auto index = [&](long i, long j) { return i * (slices + 1) + j + 1; };
    long triangles = 0;
    for (long i = 0; i < stacks; ++i) {
        for (long j = 0; j < slices; ++j) {
            const long a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1),
                       d = index(i, j + 1);
            if (i != stacks - 1) {
                std::fprintf(out, "f %ld//%ld %ld//%ld %ld//%ld\n", a, a, b, b, c, c);
                ++triangles;
            }
            if (i != 0) {
                std::fprintf(out, "f %ld//%ld %ld//%ld %ld//%ld\n", a, a, c, c, d, d);
                ++triangles;
            }
        }
    }
    if (std::fclose(out) != 0) {
        std::perror(argv[2]);
        return 1;
    }
    std::fprintf(stderr, "%s: %ld triangles, %ld vertices\n", argv[2], triangles,
                 (stacks + 1) * (slices + 1));
    return 0;
}
