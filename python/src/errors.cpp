// zraster.InputError: a ValueError subclass carrying the C++ InputError's parts, so that
// `except ValueError` catches bad input and `e.source` names the file, option or argument.
#include "errors.hpp"

#include "binding.hpp"

namespace zraster::python {

std::string type_name(py::handle object) {
    return py::str(py::type::handle_of(object).attr("__name__")).cast<std::string>();
}

void type_error(const std::string& argument, const std::string& expected, py::handle got) {
    throw py::type_error(argument + ": expected " + expected + ", got " + type_name(got));
}

namespace {
PyObject* load_warning_class = nullptr;  // zraster.LoadWarning, owned by the module
}  // namespace

void warn_load(const std::string& message) {
    // stacklevel 2: the warning points at the caller's load() line.
    if (PyErr_WarnEx(load_warning_class, message.c_str(), 2) != 0) throw py::error_already_set();
}

void bind_errors(py::module_& m) {
    load_warning_class = PyErr_NewExceptionWithDoc(
        "zraster.LoadWarning",
        "A problem load() found in a file and worked around (a missing texture, an unsupported "
        "material feature, ...): the scene renders, perhaps not as its author meant. A "
        "UserWarning; the same texts are in Scene.warnings.",
        PyExc_UserWarning, nullptr);
    if (load_warning_class == nullptr) throw py::error_already_set();
    m.add_object("LoadWarning", py::handle(load_warning_class));
    // Leaked on purpose: the translator may run until the interpreter is gone, and the object's
    // destructor must not run after that.
    static auto* const exception = new py::exception<InputError>(m, "InputError", PyExc_ValueError);
    exception->doc() =
        "Bad input: a file that cannot be read, an option or argument out of range. A "
        "ValueError. str(e) is one line, 'SOURCE: cause'; e.source is the file, option or "
        "argument ('' when none applies) and e.cause the rest.";
    exception->attr("source") = "";
    exception->attr("cause") = "";
    static auto* const limit_exceeded =
        new py::exception<LimitExceeded>(m, "LimitExceeded", exception->ptr());
    limit_exceeded->doc() =
        "Bad input refused by a budget (a load() keyword such as max_instances or max_triangles, "
        "a render limit): an InputError. e.limit names the budget, the keyword or LoadOptions "
        "field that raises it.";
    limit_exceeded->attr("limit") = "";
    // Messages quote file names, which need not be UTF-8: their bytes come back as the
    // surrogate escapes Python gave them (os.fsencode's inverse), never a decoding error.
    static const auto text = [](const std::string& s) {
        return py::reinterpret_steal<py::str>(
            PyUnicode_DecodeUTF8(s.data(), py::ssize_t(s.size()), "surrogateescape"));
    };
    // NOLINTNEXTLINE(performance-unnecessary-value-param): pybind11's translator signature
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const LimitExceeded& e) {
            py::object error = py::handle(limit_exceeded->ptr())(text(e.what()));
            error.attr("source") = text(e.file());
            error.attr("cause") = text(e.cause());
            error.attr("limit") = e.limit();
            PyErr_SetObject(limit_exceeded->ptr(), error.ptr());
        } catch (const InputError& e) {
            py::object error = py::handle(exception->ptr())(text(e.what()));
            error.attr("source") = text(e.file());
            error.attr("cause") = text(e.cause());
            PyErr_SetObject(exception->ptr(), error.ptr());
        }
    });
}

}  // namespace zraster::python
