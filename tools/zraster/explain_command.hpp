// `zraster explain ALGORITHM [SCENE] -o DIR`: pictures of an algorithm at work, with an
// index.html naming what each shows (docs/explain.md).
#pragma once
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "explain_budget.hpp"
#include "render_arguments.hpp"

namespace zraster::cli {

struct ExplainArguments {
    std::string algorithm;
    RenderArguments render;  // the scene and camera of the 3D algorithms
    std::string output;
    int step = 0;  // frames: every step-th triangle or polygon (0: about 8 frames)
    std::uint64_t max_pixels = kDefaultMaxExplainPixels;  // of all pictures (explain_budget.hpp)
    std::vector<std::string> given;  // the options and positionals given, by name ("--size")
};

void add_explain_command(CLI::App& app, ExplainArguments& arguments);
int run_explain(const ExplainArguments& arguments);
// The algorithms it explains, in help order.
std::vector<std::string> explained_algorithms();

}  // namespace zraster::cli
