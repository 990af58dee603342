#pragma once
#include <CLI/CLI.hpp>

#include <string>

namespace zraster::cli {

struct InfoArguments {
    std::string scene;
};

void add_info_command(CLI::App& app, InfoArguments& arguments);
int run_info(const InfoArguments& arguments);

}  // namespace zraster::cli
