// Keywords -> flags -> RenderArguments: see options.hpp. Values become the flags' text the way a
// shell user would type them (numbers in their shortest round-trip form, so nothing is lost).
#include "options.hpp"

#include <zraster/error.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>

#include "errors.hpp"

namespace zraster::python {
namespace {

// Flags that are not render keywords: the image size, threads and pixel limit belong to the
// Renderer (its constructor's arguments), help is CLI11's.
bool is_keyword_flag(const CLI::Option* option) {
    if (option->get_lnames().empty()) return false;  // the positional scene
    const std::string& name = option->get_lnames().front();
    return name != "help" && name != "size" && name != "threads" && name != "max-pixels";
}

struct FlagParser {
    CLI::App app;
    cli::RenderArguments arguments;
    FlagParser() {
        cli::add_render_arguments(app, arguments);
        cli::add_frame_arguments(app, arguments);
    }
};

bool is_text(py::handle value) {
    return py::isinstance<py::str>(value);
}

bool is_sequence(py::handle value) {
    return !is_text(value) && !py::isinstance<py::bytes>(value) &&
           (py::isinstance<py::sequence>(value) || py::isinstance<py::array>(value));
}

std::string number_text(py::handle value, const std::string& keyword) {
    if (py::isinstance<py::bool_>(value) ||
        !(py::hasattr(value, "__index__") || py::hasattr(value, "__float__")))
        type_error(keyword, "a number, a sequence of numbers or a string", value);
    if (py::hasattr(value, "__index__"))
        return py::str(py::int_(py::reinterpret_borrow<py::object>(value))).cast<std::string>();
    return py::repr(py::float_(py::reinterpret_borrow<py::object>(value))).cast<std::string>();
}

// One flag value: a string as it is, a number, or numbers joined by commas ("X,Y,Z").
std::string value_text(py::handle value, const std::string& keyword) {
    if (is_text(value)) return value.cast<std::string>();
    if (!is_sequence(value)) return number_text(value, keyword);
    std::string text;
    for (py::handle item : py::iter(value)) {
        if (is_sequence(item) || is_text(item))
            type_error(keyword, "numbers, not nested sequences", value);
        text += (text.empty() ? "" : ",") + number_text(item, keyword);
    }
    return text;
}

std::string source_in(const std::string& message) {
    const std::size_t at = message.find("--");
    if (at == std::string::npos) return "";
    std::size_t end = at + 2;
    while (end < message.size() &&
           (std::isalnum(static_cast<unsigned char>(message[end])) || message[end] == '-'))
        ++end;
    return keyword_name(message.substr(at, end - at));
}

}  // namespace

std::string keyword_name(const std::string& flag) {
    std::string name = flag.starts_with("--") ? flag.substr(2) : flag;
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
}

std::string with_keyword_names(std::string message) {
    std::size_t at = 0;
    while ((at = message.find("--", at)) != std::string::npos) {
        std::size_t end = at + 2;
        while (end < message.size() &&
               (std::isalnum(static_cast<unsigned char>(message[end])) || message[end] == '-'))
            ++end;
        const std::string name = keyword_name(message.substr(at, end - at));
        message.replace(at, end - at, name);
        at += name.size();
    }
    return message;
}

std::vector<std::string> flag_arguments(
    const py::kwargs& keywords, const CLI::App& app,
    const std::function<bool(const CLI::Option*)>& is_keyword,
    const std::function<std::string(const std::string&)>& unknown, std::set<std::string>* given) {
    std::vector<std::string> args;
    for (const auto& [key, value] : keywords) {
        const std::string keyword = py::str(key).cast<std::string>();
        std::string flag = "--" + keyword;
        std::replace(flag.begin(), flag.end(), '_', '-');
        const CLI::Option* option =
            keyword.find('-') == std::string::npos ? app.get_option_no_throw(flag) : nullptr;
        if (option == nullptr || !is_keyword(option)) throw py::type_error(unknown(keyword));
        if (given != nullptr) given->insert(keyword);
        if (option->get_expected_max() == 0) {  // a flag without a value: True or False
            if (!py::isinstance<py::bool_>(value) &&
                !(py::hasattr(value, "dtype") &&
                  py::str(value.attr("dtype")).cast<std::string>() == "bool"))
                type_error(keyword, "True or False", value);
            if (value.cast<bool>()) args.push_back(flag);
            continue;
        }
        if (py::isinstance<py::bool_>(value) || value.is_none())
            type_error(keyword, "a value (see help(zraster.Renderer.render))", value);
        // Repeatable flags (--light-dir, --point-light, --clip-plane) take one value or a list.
        const bool repeatable = option->get_expected_max() > 1;
        bool many = false;
        if (repeatable && is_sequence(value)) {
            if (py::isinstance<py::array>(value))
                many = py::reinterpret_borrow<py::array>(value).ndim() == 2;
            else if (py::len(value) == 0)
                many = true;
            else {
                py::handle first = py::reinterpret_borrow<py::sequence>(value)[0];
                many = is_sequence(first) || is_text(first);
            }
        }
        if (many) {
            for (py::handle item : py::iter(value))
                args.push_back(flag + "=" + value_text(item, keyword));
        } else {
            args.push_back(flag + "=" + value_text(value, keyword));
        }
    }
    return args;
}

InputError keyword_error(const CLI::ParseError& e) {
    const std::string message = with_keyword_names(e.what());
    const std::string source = source_in(e.what());
    std::string cause = message;
    if (!source.empty() && cause.starts_with(source + ": ")) cause.erase(0, source.size() + 2);
    return InputError(source, cause);
}

RenderKeywords parse_render_keywords(const py::kwargs& keywords, int width, int height, int threads,
                                     std::uint64_t max_pixels) {
    thread_local FlagParser parser;  // one per thread, cleared for every parse
    RenderKeywords result;
    std::vector<std::string> args = {
        "--size=" + std::to_string(width) + "x" + std::to_string(height),
        "--threads=" + std::to_string(threads), "--max-pixels=" + std::to_string(max_pixels)};
    const std::vector<std::string> given = flag_arguments(
        keywords, parser.app, is_keyword_flag,
        [](const std::string& keyword) {
            std::string message = "render() got an unexpected keyword argument '" + keyword + "'";
            if (keyword == "size" || keyword == "threads" || keyword == "max_pixels")
                message += " (the Renderer's: Renderer(width, height, threads, max_pixels))";
            return message;
        },
        &result.given);
    args.insert(args.end(), given.begin(), given.end());
    // The same keywords as this thread's last call (a render loop): the same arguments, without
    // CLI11's parse (most of the 0.15 ms a small frame spent outside the renderer).
    thread_local std::vector<std::string> last_args;
    thread_local cli::RenderArguments last_arguments;
    if (args == last_args) {
        result.arguments = last_arguments;
        return result;
    }
    parser.app.clear();
    parser.arguments = cli::RenderArguments{};
    std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes it reversed
    try {
        parser.app.parse(reversed);
    } catch (const CLI::ParseError& e) {
        throw keyword_error(e);
    }
    last_args = std::move(args);
    last_arguments = parser.arguments;
    result.arguments = parser.arguments;
    return result;
}

namespace {

// Words of `text` in lines of at most `width` columns, the first starting with `indent`, the
// others indented four more.
std::string wrapped(const std::string& text, std::string indent, std::size_t width) {
    std::string out, line = indent;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find(' ', start);
        if (end == std::string::npos) end = text.size();
        const std::string word = text.substr(start, end - start);
        if (line.size() > indent.size() && line.size() + 1 + word.size() > width) {
            out += line + "\n";
            if (out.size() == line.size() + 1) indent += "    ";
            line = indent;
        }
        line += (line.size() > indent.size() ? " " : "") + word;
        start = end + 1;
    }
    return out + line + "\n";
}

}  // namespace

std::string render_keywords_doc() {
    FlagParser parser;
    std::string doc;
    for (const CLI::Option* option : parser.app.get_options()) {
        if (!is_keyword_flag(option)) continue;
        const std::string name = keyword_name(option->get_lnames().front());
        std::string text = name + ": ";
        if (option->get_expected_max() == 0) text += "bool. ";
        text += with_keyword_names(option->get_description());
        if (option->get_expected_max() != 0 && !option->get_default_str().empty()) {
            text += " [default ";
            text += option->get_default_str();
            text += "]";
        }
        if (option->get_expected_max() > 1) text += " (one value or a list of them)";
        doc += wrapped(text, "    ", 92);
    }
    return doc;
}

py::list render_keyword_names() {
    FlagParser parser;
    py::list names;
    for (const CLI::Option* option : parser.app.get_options())
        if (is_keyword_flag(option)) names.append(keyword_name(option->get_lnames().front()));
    return names;
}

}  // namespace zraster::python
