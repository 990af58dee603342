// Parsing of the viewer's input scripts.
#include "view_script.hpp"

#include "io/input_file_check.hpp"

#include <zraster/error.hpp>

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace zraster::cli {
namespace {

// The ranges of docs/limits.md: frames as view --frames; a drag at most a window's largest side;
// 100 notches zoom by 0.875^100, about 1.6e-6.
constexpr long long kMaxScriptFrame = 1'000'000'000;
constexpr double kMaxScriptDrag = 16384.0;
constexpr double kMaxScriptNotches = 100.0;

// A whole-token number, or an InputError naming the line.
template <typename T>
T script_number(const std::string& token, const std::string& name, int line, const char* what) {
    T value{};
    const char* end = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), end, value);
    if (ec != std::errc() || ptr != end)
        throw InputError(name, "line " + std::to_string(line) + ": " + what + " '" + token +
                                   "' is not a number");
    if constexpr (std::is_floating_point_v<T>) {
        if (!std::isfinite(value))
            throw InputError(name, "line " + std::to_string(line) + ": " + what + " '" + token +
                                       "' is not finite");
    }
    return value;
}

InputEvent parse_event(std::istringstream& words, const std::string& kind, const std::string& name,
                       int line) {
    const auto fail = [&](const std::string& cause) {
        return InputError(name, "line " + std::to_string(line) + ": " + cause);
    };
    InputEvent e;
    std::string a, b, c;
    if (kind == "key") {
        e.kind = InputEvent::Kind::Key;
        if (!(words >> a)) throw fail("key needs a key (1, v, esc, ...)");
        if (a == "esc" || a == "escape")
            e.key = kEscapeKey;
        else if (a.size() == 1)
            e.key = a[0];
        else
            throw fail("unknown key '" + a + "' (one character, or esc)");
    } else if (kind == "drag") {
        e.kind = InputEvent::Kind::Drag;
        if (!(words >> a >> b >> c)) throw fail("drag needs BUTTON DX DY");
        if (a == "left")
            e.button = MouseButton::Left;
        else if (a == "right")
            e.button = MouseButton::Right;
        else if (a == "middle")
            e.button = MouseButton::Middle;
        else
            throw fail("unknown button '" + a + "' (left, right or middle)");
        e.dx = script_number<double>(b, name, line, "DX");
        e.dy = script_number<double>(c, name, line, "DY");
        if (std::abs(e.dx) > kMaxScriptDrag || std::abs(e.dy) > kMaxScriptDrag)
            throw fail("drag by " + b + "," + c + " pixels: DX and DY must be within +-16384");
    } else if (kind == "wheel") {
        e.kind = InputEvent::Kind::Wheel;
        if (!(words >> a)) throw fail("wheel needs a number of notches");
        e.wheel = script_number<double>(a, name, line, "notches");
        if (std::abs(e.wheel) > kMaxScriptNotches)
            throw fail("wheel by " + a + " notches: must be within +-100");
    } else if (kind == "resize") {
        e.kind = InputEvent::Kind::Resize;
        if (!(words >> a >> b)) throw fail("resize needs WIDTH HEIGHT");
        e.width = script_number<int>(a, name, line, "WIDTH");
        e.height = script_number<int>(b, name, line, "HEIGHT");
        if (e.width < 1 || e.height < 1 || e.width > 16384 || e.height > 16384)
            throw fail("resize to " + a + "x" + b + ": sides must be in 1..16384");
    } else if (kind == "quit") {
        e.kind = InputEvent::Kind::Quit;
    } else {
        throw fail("unknown event '" + kind + "' (key, drag, wheel, resize, quit)");
    }
    if (words >> a) throw fail("unexpected '" + a + "' after the event");
    return e;
}

}  // namespace

std::vector<ScriptEvent> parse_view_script(const std::string& text, const std::string& name) {
    std::vector<ScriptEvent> events;
    std::istringstream lines(text);
    std::string text_line;
    int line = 0;
    long long last_frame = 0;
    while (std::getline(lines, text_line)) {
        ++line;
        const std::size_t hash = text_line.find('#');
        if (hash != std::string::npos) text_line.resize(hash);
        std::istringstream words(text_line);
        std::string frame_token, kind;
        if (!(words >> frame_token)) continue;  // blank or comment
        ScriptEvent event;
        event.frame = script_number<long long>(frame_token, name, line, "frame");
        if (event.frame > kMaxScriptFrame)
            throw InputError(name, "line " + std::to_string(line) + ": frame " + frame_token +
                                       " is past 10^9 (view --frames' range)");
        if (event.frame < 0 || event.frame < last_frame)
            throw InputError(name, "line " + std::to_string(line) + ": frame " + frame_token +
                                       " is negative or before the previous event's");
        last_frame = event.frame;
        if (!(words >> kind))
            throw InputError(name, "line " + std::to_string(line) +
                                       ": an event must follow the "
                                       "frame");
        event.event = parse_event(words, kind, name, line);
        // Resizes in a row within one frame: only the last is seen (each one was carried out: a
        // thousand alternating 1x1 and 8192x8192 took minutes before the first frame).
        if (event.event.kind == InputEvent::Kind::Resize && !events.empty() &&
            events.back().frame == event.frame &&
            events.back().event.kind == InputEvent::Kind::Resize)
            events.back() = event;
        else
            events.push_back(event);
    }
    return events;
}

std::vector<ScriptEvent> read_view_script(const std::filesystem::path& path) {
    // As a model is checked: missing, a FIFO or device, unreadable, empty; and at most 16 MiB
    // (a script of a few events is a few hundred bytes; it is read whole).
    io::check_input_file(path, std::uintmax_t{16} << 20, nullptr);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path.string(), "cannot read the script");
    std::ostringstream text;
    text << in.rdbuf();
    return parse_view_script(text.str(), path.string());
}

}  // namespace zraster::cli
