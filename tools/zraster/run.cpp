// Dispatches to the subcommands (one file each) and maps failures to exit codes.
#include "run.hpp"

#include <zraster/error.hpp>
#include <zraster/load.hpp>
#include <zraster/version.hpp>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <exception>
#include <new>
#include <string>

#include "batch_command.hpp"
#include "batch_limits.hpp"
#include "bench_command.hpp"
#include "command_line.hpp"
#include "decimal_numbers.hpp"
#include "explain_command.hpp"
#include "info_command.hpp"
#include "io/text_util.hpp"
#include "pvs_command.hpp"
#include "render_command.hpp"
#include "svg_command.hpp"
#include "view_command.hpp"

namespace zraster::cli {
namespace {

// CLI11's words for an option given twice ("--output: At Most 1 required but received 2").
std::string parse_error_cause(const std::string& text) {
    // A whole number of digits only (read_numbers_in_decimal checked them) past its type.
    const std::string_view conversion = "Could not convert: ";
    if (text.starts_with(conversion)) {
        const std::size_t equals = text.find(" = ", conversion.size());
        if (equals != std::string::npos)
            return text.substr(conversion.size(), equals - conversion.size()) + ": '" +
                   text.substr(equals + 3) +
                   "' is past the largest number it takes (--help gives its range)";
    }
    // CLI::Range's "--jobs: Value 0 not in range 1 to 1000" (doubles as 1.000000).
    const std::size_t value = text.find(": Value ");
    const std::size_t range = text.find(" not in range ");
    const std::size_t to = text.rfind(" to ");
    if (value != std::string::npos && range != std::string::npos && to != std::string::npos &&
        value < range && range < to) {
        const auto trimmed = [](std::string number) {
            if (number.find('.') != std::string::npos) {
                while (number.ends_with('0')) number.pop_back();
                if (number.ends_with('.')) number.pop_back();
            }
            return number;
        };
        return text.substr(0, value) + ": '" + text.substr(value + 8, range - value - 8) +
               "' is outside its range, " + trimmed(text.substr(range + 14, to - range - 14)) +
               " to " + trimmed(text.substr(to + 4));
    }
    const std::string_view marker = ": At Most 1 required but received ";
    const std::size_t at = text.find(marker);
    if (at == std::string::npos) return text;
    return text.substr(0, at) + ": given " + text.substr(at + marker.size()) +
           " times: give it once";
}

// The first argument, in the order given, that the command did not take: an option of another
// command ("svg --aa 4"), or a word no option reads.
std::string unexpected_arguments_cause(const CLI::App& app, const std::vector<std::string>& given) {
    std::string command = "zraster";
    for (const CLI::App* sub : app.get_subcommands()) command += " " + sub->get_name();
    const std::vector<std::string> remaining = app.remaining(true);
    for (auto it = given.begin(); it != given.end(); ++it) {
        if (std::find(remaining.begin(), remaining.end(), *it) == remaining.end()) continue;
        const std::string word = it->substr(0, it->find('='));
        if (word.starts_with("-"))
            return word + ": not an option of " + command + " (" + command +
                   " --help lists its options)";
        return "'" + *it + "': an argument " + command + " does not take (" + command +
               " --help lists what it takes)";
    }
    return "arguments " + command + " does not take (" + command + " --help lists them)";
}

}  // namespace

int run_zraster(std::vector<std::string> args) {
    CLI::App app{"zraster: an exact, fast CPU rasterizer", "zraster"};
    app.require_subcommand(0, 1);
    app.set_version_flag("--version", std::string("zraster ") + kVersionString);
    RenderArguments render_args;
    add_render_command(app, render_args);
    InfoArguments info_args;
    add_info_command(app, info_args);
    BenchArguments bench_args;
    add_bench_command(app, bench_args);
    SvgArguments svg_args;
    add_svg_command(app, svg_args);
    BatchArguments batch_args;
    add_batch_command(app, batch_args);
    ExplainArguments explain_args;
    add_explain_command(app, explain_args);
    ViewArguments view_args;
    add_view_command(app, view_args);
    PvsArguments pvs_args;
    add_pvs_command(app, pvs_args);
    // Loading: Assimp (every format but the OBJ files zraster reads itself) runs in a worker
    // process, so that a crash in it is a refused file (RELIABILITY.md). Accepted after the
    // subcommand too.
    bool load_in_process = false;
    app.add_flag("--load-in-process", load_in_process,
                 "Run the Assimp importer in this process instead of a worker process (faster "
                 "for many small files; a crash in Assimp then ends zraster)");
    bool allow_outside_references = false;
    app.add_flag("--allow-outside-references", allow_outside_references,
                 "Read a model's external files (glTF buffers and images, OBJ material libraries "
                 "and textures) outside its folder too; by default they are refused");
    std::size_t max_instances = LoadOptions{}.max_instances;
    app.add_option("--max-instances", max_instances,
                   "Refuse models whose node hierarchy places more meshes than this (nodes that "
                   "share children multiply them)")
        ->check(CLI::Range(std::size_t{1}, std::size_t{1'000'000'000}))
        ->capture_default_str();
    std::size_t max_materials = LoadOptions{}.max_materials;
    app.add_option("--max-materials", max_materials,
                   "Refuse models that define more materials than this (an OBJ's material "
                   "libraries are counted before they are read)")
        ->check(CLI::Range(std::size_t{1}, std::size_t{1'000'000'000}))
        ->capture_default_str();
    // `zraster batch` has its own --max-triangles (over a file's instances, with --max-memory),
    // which takes precedence after `batch`.
    std::size_t max_load_triangles = LoadOptions{}.max_triangles;
    app.add_option("--max-triangles", max_load_triangles,
                   "Refuse model files of more triangles than this (over their instances)")
        ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 40))
        ->capture_default_str();
    std::uint64_t max_triangulation_work = LoadOptions{}.max_triangulation_work;
    app.add_option("--max-triangulation-work", max_triangulation_work,
                   "Refuse OBJ and PLY files whose polygons of more than 4 corners sum to more "
                   "corners^2 than this (the importer's triangulation takes quadratic time)")
        ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 40))
        ->capture_default_str();
    double max_load_seconds = 0;
    app.add_option("--max-load-seconds", max_load_seconds,
                   "Stop the importer (Assimp, in its worker process) after this many seconds "
                   "(default: 30 s plus 1 s per MiB of the file)")
        ->check([](const std::string& text) -> std::string {
            // (CLI::Range lets NaN through: no comparison with it is true.)
            double seconds = 0;
            const char* end = text.data() + text.size();
            const auto [ptr, ec] = std::from_chars(text.data(), end, seconds);
            if (ec != std::errc() || ptr != end || !(seconds >= 1.0 && seconds <= 1e6))
                return "'" + text + "' is not a number of seconds from 1 to 1000000";
            return {};
        });
    std::string max_geometry_memory = "1G";
    app.add_option("--max-geometry-memory", max_geometry_memory,
                   "Refuse glTF files the importer would decode to more bytes than this (e.g. "
                   "2G; an accessor counts once per primitive that reads it; buffers, animation "
                   "keys, skin bones per placement and materials count too), COLLADA and "
                   "LightWave scenes that expand past it; the importer's memory in its worker "
                   "process is 256 MiB, 4 times the file's size, this and twice the texture budget")
        ->capture_default_str();
    int max_texture_side = LoadOptions{}.max_texture_side;
    app.add_option("--max-texture-side", max_texture_side,
                   "Reduce textures wider or taller than this many texels (halving them, with a "
                   "warning)")
        ->check(CLI::Range(1, 1 << 16))
        ->capture_default_str();
    std::string max_texture_memory = "512M";
    app.add_option("--max-texture-memory", max_texture_memory,
                   "Decoded bytes of a model's textures, mip levels included (e.g. 1G): a "
                   "texture past it is not used, with a warning")
        ->capture_default_str();
    for (CLI::App* sub : app.get_subcommands({})) sub->fallthrough();
    read_numbers_in_decimal(app);

    // `zraster -o x.png --size ...` means `zraster render -o x.png --size ...`. The flags above
    // may come first (`zraster --load-in-process render FILE`, `zraster --load-in-process -o
    // x.png`): "render" goes after them, unless a subcommand follows them.
    std::size_t first = 0;
    while (first < args.size() && args[first].starts_with("--")) {
        const std::string name = args[first].substr(0, args[first].find('='));
        const CLI::Option* option = app.get_option_no_throw(name);
        if (option == nullptr || name == "--help" || name == "--version") break;
        const bool value_follows = option->get_expected_min() > 0 && name == args[first];
        first += value_follows ? 2 : 1;
    }
    if (first < args.size() && args[first].starts_with("-") && args[first] != "-h" &&
        args[first] != "--help" && args[first] != "--version")
        args.insert(args.begin() + std::ptrdiff_t(first), "render");
    std::string names;
    bool names_subcommand = false;
    for (const CLI::App* sub : app.get_subcommands({})) {
        names += (names.empty() ? "" : ", ") + sub->get_name();
        names_subcommand |= first < args.size() && args[first] == sub->get_name();
    }
    if (first < args.size() && !args[first].starts_with("-") && !names_subcommand) {
        std::string before, after;
        for (std::size_t i = 0; i < args.size(); ++i) (i < first ? before : after) += " " + args[i];
        fmt::print(stderr,
                   "zraster: '{}' is not a subcommand ({}): to render it, zraster{} render{}\n",
                   args[first], names, before, after);
        return kExitBadInput;
    }
    // An empty argument is never a value or a name zraster can use; CLI11 would take it as "not
    // given" for an option with a default (`--fovy ''` drew with the default field of view).
    for (std::size_t i = 0; i < args.size(); ++i) {
        const bool after_equals = args[i].starts_with("--") && args[i].ends_with("=");
        if (!args[i].empty() && !after_equals) continue;
        const std::string where =
            after_equals ? args[i].substr(0, args[i].size() - 1)
                         : (i > 0 ? "after " + io::one_line(args[i - 1]) : "as the first argument");
        fmt::print(stderr, "zraster: {}: an empty value (give one, or leave the option out)\n",
                   where);
        return kExitBadInput;
    }
    const std::vector<std::string> given = args;
    std::reverse(args.begin(), args.end());  // CLI11 takes a reversed vector (and consumes it)
    try {
        app.parse(args);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ExtrasError&) {
        // CLI11: "The following arguments were not expected: 4 --aa" (reversed, no command).
        fmt::print(stderr, "zraster: {}\n", io::one_line(unexpected_arguments_cause(app, given)));
        return kExitBadInput;
    } catch (const CLI::ParseError& e) {
        fmt::print(stderr, "zraster: {}\n", io::one_line(parse_error_cause(e.what())));
        return kExitBadInput;
    }

    set_load_in_process(load_in_process);
    set_allow_outside_references(allow_outside_references);
    set_max_instances(max_instances);
    set_max_materials(max_materials);
    set_max_load_triangles(max_load_triangles);
    set_max_triangulation_work(max_triangulation_work);
    set_max_load_seconds(max_load_seconds > 0 ? max_load_seconds
                                              : LoadOptions::kWorkerTimeoutFromFile);
    try {
        set_texture_limits(max_texture_side,
                           parse_byte_size("--max-texture-memory", max_texture_memory));
        set_max_geometry_bytes(parse_byte_size("--max-geometry-memory", max_geometry_memory));
        if (app.got_subcommand("info")) return run_info(info_args);
        if (app.got_subcommand("bench")) return run_bench(bench_args);
        if (app.got_subcommand("svg")) return run_svg(svg_args);
        if (app.got_subcommand("batch")) return run_batch(batch_args);
        if (app.got_subcommand("view")) return run_view(view_args);
        if (app.got_subcommand("explain")) return run_explain(explain_args);
        if (app.got_subcommand("pvs")) return run_pvs(pvs_args);
        // No subcommand at all: render the built-in default scene to zraster.png.
        return run_render(render_args);
    } catch (const zraster::LimitExceeded& e) {
        // (One line whatever the names in it hold: a path may contain a newline.)
        fmt::print(stderr, "zraster: {}{}\n", io::one_line(e.what()), limit_advice(e.limit()));
        return kExitBadInput;
    } catch (const zraster::InputError& e) {
        fmt::print(stderr, "zraster: {}\n", io::one_line(e.what()));
        return kExitBadInput;
    } catch (const std::bad_alloc&) {
        // The default budgets keep a run within a few GB: past them is a request this machine
        // cannot hold (a budget or --max-pixels raised), the user's to change, not a bug.
        fmt::print(stderr,
                   "zraster: out of memory: the run needs more than this machine gives it "
                   "(the default budgets fit a few GB; a model file may be up to 4 GiB): lower "
                   "--size or --aa, a budget raised past its default, or the model's size "
                   "(docs/limits.md)\n");
        return kExitBadInput;
    } catch (const std::exception& e) {
        fmt::print(stderr, "zraster: internal error: {}\n", io::one_line(e.what()));
        return kExitInternal;
    }
}

}  // namespace zraster::cli
