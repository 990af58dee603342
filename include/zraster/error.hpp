// User errors (bad input files, bad options) as opposed to internal bugs.
//
// Every failure the user can cause is reported as an InputError whose message is one line,
// "FILE: cause", so the command can print it and exit with status 2. Internal invariants use
// assertions instead; they mean a bug in zraster, not in the input.
#pragma once
#include <stdexcept>
#include <string>

namespace zraster {

class InputError : public std::runtime_error {
  public:
    InputError(std::string file, std::string cause)
        : std::runtime_error(file.empty() ? cause : file + ": " + cause),
          file_(std::move(file)),
          cause_(std::move(cause)) {}

    const std::string& file() const { return file_; }
    const std::string& cause() const { return cause_; }

  private:
    std::string file_;
    std::string cause_;
};

}  // namespace zraster
