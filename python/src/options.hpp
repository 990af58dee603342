// Render keywords -> the command's RenderArguments, through the command's own flag parser
// (tools/zraster/render_arguments.hpp): a keyword is a flag's name with dashes as underscores,
// its value the flag's value, so the names, value syntax and checks are the command's.
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <zraster/error.hpp>

#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "render_arguments.hpp"

namespace zraster::python {

namespace py = pybind11;

// The keywords of Renderer.render that are flags of `zraster render`.
struct RenderKeywords {
    cli::RenderArguments arguments;
    std::set<std::string> given;  // the keywords passed (Python names)
};

// Parses `keywords` (with size, threads and max_pixels fixed by the Renderer). Raises TypeError
// for a keyword that names no flag or a value of the wrong kind, InputError for a bad value.
RenderKeywords parse_render_keywords(const py::kwargs& keywords, int width, int height, int threads,
                                     std::uint64_t max_pixels);

// Keywords -> "--flag=value" arguments for `app`: a keyword is an option's name with dashes as
// underscores, True/False a flag without a value, a number or a string a flag's value, a sequence
// of numbers "X,Y,Z", a list of those a repeatable flag given once per item. `is_keyword` says
// which options are keywords; for any other keyword a TypeError with the message unknown(keyword).
// The keywords passed are added to `given` (may be null).
std::vector<std::string> flag_arguments(
    const py::kwargs& keywords, const CLI::App& app,
    const std::function<bool(const CLI::Option*)>& is_keyword,
    const std::function<std::string(const std::string&)>& unknown, std::set<std::string>* given);

// CLI11's parse error as the InputError of the keyword it names ("--light-dir" -> "light_dir").
InputError keyword_error(const CLI::ParseError& e);

// A flag's name as a keyword ("--light-dir" -> "light_dir"); error messages are rewritten so.
std::string keyword_name(const std::string& flag);
std::string with_keyword_names(std::string message);

// "    name: description [default]" for every keyword, for the docstrings.
std::string render_keywords_doc();
// The keywords' names, in the command's order.
py::list render_keyword_names();

}  // namespace zraster::python
