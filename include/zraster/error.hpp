// User errors (bad input files, bad options) as opposed to internal bugs.
//
// Every failure the user can cause is reported as an InputError whose message is one line,
// "FILE: cause", so the command can print it and exit with status 2. Internal invariants use
// assertions instead; they mean a bug in zraster, not in the input.
#pragma once
#include <stdexcept>
#include <string>
#include <utility>

namespace zraster {

class InputError : public std::runtime_error {
  public:
    InputError(std::string file, std::string cause)
        : InputError(std::move(file), one_line(std::move(cause)), 0) {}

    const std::string& file() const { return file_; }
    const std::string& cause() const { return cause_; }

  private:
    InputError(std::string file, std::string cause, int)
        : std::runtime_error(file.empty() ? cause : file + ": " + cause),
          file_(std::move(file)),
          cause_(std::move(cause)) {}

    // Causes quote the input (names, texture paths, a library's message): line breaks and other
    // control characters there would break the one-line contract; they become spaces and '?'.
    // A quote of megabytes (a 10 MB field name) is cut in its middle, at character boundaries:
    // the head names what is quoted, the tail keeps the reason that follows a long quote (a
    // path of 5 KB "is too long").
    static constexpr std::size_t kMaxCauseBytes = 4096;
    static std::string one_line(std::string text) {
        if (text.size() > kMaxCauseBytes) {
            const auto continuation = [&](std::size_t i) {
                return (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80;
            };
            std::size_t head = kMaxCauseBytes / 2;
            while (head > 0 && continuation(head)) --head;
            std::size_t tail = text.size() - (kMaxCauseBytes / 2 - 64);
            while (tail < text.size() && continuation(tail)) ++tail;
            text = text.substr(0, head) + "... (" + std::to_string(tail - head) +
                   " bytes cut) ..." + text.substr(tail);
        }
        for (char& c : text) {
            if (c == '\n' || c == '\r')
                c = ' ';
            else if ((c >= 0 && c < ' ' && c != '\t') || c == 0x7f)
                c = '?';
        }
        return text;
    }

    std::string file_;
    std::string cause_;
};

// An input refused because it would exceed one of the budgets that keep a run bounded in time
// and memory (RenderLimits, the algorithms' options, LoadOptions). limit() names the field, e.g.
// "max_bsp_polygons", so that a front end can name its own way to raise it (the command's
// --max-bsp-polygons, the Python keyword). The cause says what was exceeded and by what input.
class LimitExceeded : public InputError {
  public:
    LimitExceeded(std::string file, std::string limit, std::string cause)
        : InputError(std::move(file), std::move(cause)), limit_(std::move(limit)) {}

    const std::string& limit() const { return limit_; }

  private:
    std::string limit_;
};

}  // namespace zraster
