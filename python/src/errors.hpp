// Errors as Python sees them: zraster::InputError becomes zraster.InputError (a ValueError),
// a wrong type a TypeError, both naming the argument.
#pragma once
#include <zraster/error.hpp>

#include <pybind11/pybind11.h>

#include <string>

namespace zraster::python {

// The argument's name and the cause, raised as zraster.InputError.
[[noreturn]] inline void input_error(const std::string& argument, const std::string& cause) {
    throw InputError(argument, cause);
}

// "ARGUMENT: expected WHAT, got TYPE", raised as TypeError.
[[noreturn]] void type_error(const std::string& argument, const std::string& expected,
                             pybind11::handle got);

// Issues `message` as a zraster.LoadWarning (warnings.warn: shown once per call site by default,
// an exception under -W error).
void warn_load(const std::string& message);

// The Python name of a type, for messages.
std::string type_name(pybind11::handle object);

}  // namespace zraster::python
