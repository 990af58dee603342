// numpy arrays in: the checks and the one copy, when one is needed, of arrays.hpp.
#include "arrays.hpp"

#include <zraster/error.hpp>
#include <zraster/precision.hpp>
#include <zraster/render.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

#include "errors.hpp"

namespace zraster::python {
namespace {

// A texture side past which an image array is refused rather than copied (the loaders' images
// are bounded by their decoder; 65536 keeps width * height * 4 well inside 64 bits).
constexpr py::ssize_t kMaxTextureSide = 65536;

using namespace pybind11::literals;

py::module_ numpy() {
    return py::module_::import("numpy");
}

std::string shape_text(const py::array& a) {
    std::string s = "(";
    for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
    return s + (a.ndim() == 1 ? ",)" : ")");
}

// The argument as an ndarray (lists and other array-likes through numpy.asarray).
py::array as_array(py::handle object, const std::string& argument, const std::string& expected) {
    if (py::isinstance<py::array>(object)) return py::reinterpret_borrow<py::array>(object);
    if (object.is_none() || py::isinstance<py::str>(object) || py::isinstance<py::bytes>(object))
        type_error(argument, expected, object);
    try {
        return numpy().attr("asarray")(object);
    } catch (py::error_already_set& e) {
        // A ragged list: numpy refuses it with a ValueError of its own.
        if (!e.matches(PyExc_ValueError)) type_error(argument, expected, object);
        input_error(argument, "not a rectangular array of numbers (" + std::string(e.what()) + ")");
    }
}

void require_kind(const py::array& a, const std::string& kinds, const std::string& argument,
                  const std::string& expected) {
    if (kinds.find(a.dtype().kind()) == std::string::npos)
        throw py::type_error(argument + ": expected " + expected + ", got an array of dtype " +
                             py::str(a.dtype()).cast<std::string>());
}

bool aligned(const void* p, std::size_t alignment) {
    return reinterpret_cast<std::uintptr_t>(p) % alignment == 0;
}

}  // namespace

FloatRows float_rows(py::handle object, std::size_t columns, const std::string& argument) {
    const std::string expected =
        "an array of shape (N, " + std::to_string(columns) + ") of real numbers";
    py::array a = as_array(object, argument, expected);
    require_kind(a, "fiu", argument, expected);
    if (a.ndim() != 2 || a.shape(1) != py::ssize_t(columns))
        input_error(argument,
                    "expected shape (N, " + std::to_string(columns) + "), got " + shape_text(a));
    // Before any copy: a broadcast view of 10^9 rows is a few bytes, its copy 11 GiB.
    if (const std::uint64_t most = RenderLimits{}.max_vertices; std::uint64_t(a.shape(0)) > most)
        throw LimitExceeded(argument, "max_vertices",
                            std::to_string(a.shape(0)) + " rows, more than the renderer's " +
                                std::to_string(most) + " vertices");
    FloatRows rows;
    // Referenced as it is: float32 in native order, each row's floats adjacent, rows at a
    // positive stride (a stride of 0, numpy's broadcast rows, means "packed" to a MeshView).
    const bool fits = py::isinstance<py::array_t<float>>(a) && a.strides(1) == 4 &&
                      a.strides(0) >= py::ssize_t(columns * 4) && a.strides(0) % 4 == 0 &&
                      aligned(a.data(), 4);
    if (!fits && a.shape(0) > 0) {
        a = numpy().attr("ascontiguousarray")(a, "dtype"_a = "float32");
        rows.copied = true;
    }
    rows.array = a;
    const std::size_t count = std::size_t(a.shape(0));
    const std::size_t stride = count > 0 ? std::size_t(a.strides(0)) : 0;
    rows.view = {count > 0 ? static_cast<const float*>(a.data()) : nullptr, count, stride};
    const char* base = static_cast<const char*>(a.data());
    for (std::size_t i = 0; i < count; ++i) {
        const float* row = reinterpret_cast<const float*>(base + i * stride);
        for (std::size_t c = 0; c < columns; ++c)
            if (!std::isfinite(row[c]))
                input_error(argument, "row " + std::to_string(i) + " has a non-finite value (" +
                                          std::to_string(row[c]) + ")");
    }
    return rows;
}

Indices triangle_indices(py::handle object, std::size_t vertex_count, const std::string& argument) {
    const std::string expected = "an integer array of shape (M, 3) or (3M,)";
    py::array a = as_array(object, argument, expected);
    require_kind(a, "iu", argument, expected);
    const bool shape_ok =
        (a.ndim() == 2 && a.shape(1) == 3) || (a.ndim() == 1 && a.size() % 3 == 0);
    if (!shape_ok) input_error(argument, "expected shape (M, 3) or (3M,), got " + shape_text(a));
    // Before any copy or temporary: a broadcast view of 3 * 10^9 indices is a few bytes.
    if (const std::uint64_t most = RenderLimits{}.max_triangles; std::uint64_t(a.size() / 3) > most)
        throw LimitExceeded(argument, "max_triangles",
                            std::to_string(a.size() / 3) + " triangles, more than the renderer's " +
                                std::to_string(most));
    // The range by the smallest and largest index (no temporary the size of the array); the
    // first index out of range is looked for only then.
    if (a.size() > 0 && (a.attr("min")().attr("__lt__")(0).cast<bool>() ||
                         a.attr("max")().attr("__ge__")(vertex_count).cast<bool>())) {
        py::object flat = a.attr("reshape")(-1);
        py::object bad = numpy().attr("flatnonzero")(
            (flat.attr("__lt__")(0)).attr("__or__")(flat.attr("__ge__")(vertex_count)));
        if (py::len(bad) > 0) {
            const py::ssize_t at = bad.attr("__getitem__")(0).cast<py::ssize_t>();
            input_error(argument, "index " +
                                      py::str(flat.attr("__getitem__")(at)).cast<std::string>() +
                                      " (element " + std::to_string(at) + ") is out of range for " +
                                      std::to_string(vertex_count) + " positions");
        }
    }
    Indices indices;
    const bool contiguous = (a.flags() & py::array::c_style) != 0;
    IndexType type = IndexType::UInt32;
    bool fits = false;
    if (contiguous && (py::isinstance<py::array_t<std::uint32_t>>(a) ||
                       py::isinstance<py::array_t<std::int32_t>>(a)))
        fits = aligned(a.data(), 4);
    else if (contiguous && py::isinstance<py::array_t<std::uint16_t>>(a)) {
        fits = aligned(a.data(), 2);
        type = IndexType::UInt16;
    }
    if (!fits && a.size() > 0) {
        // In range, checked above: the conversion cannot wrap.
        a = numpy().attr("ascontiguousarray")(a, "dtype"_a = "uint32");
        type = IndexType::UInt32;
        indices.copied = true;
    }
    indices.array = a;
    indices.view = {a.size() > 0 ? a.data() : nullptr, std::size_t(a.size()), type};
    return indices;
}

std::shared_ptr<const Texture> texture_image(py::handle object, const std::string& argument,
                                             int max_side) {
    const std::string expected = "an image array of shape (H, W, 3) or (H, W, 4), uint8 or float";
    py::array a = as_array(object, argument, expected);
    require_kind(a, "uf", argument, expected);
    if (a.ndim() != 3 || (a.shape(2) != 3 && a.shape(2) != 4))
        input_error(argument, "expected shape (H, W, 3) or (H, W, 4), got " + shape_text(a));
    if (a.shape(0) < 1 || a.shape(1) < 1)
        input_error(argument, "the image is empty, shape " + shape_text(a));
    if (a.shape(0) > kMaxTextureSide || a.shape(1) > kMaxTextureSide)
        input_error(argument, "the image is " + std::to_string(a.shape(1)) + "x" +
                                  std::to_string(a.shape(0)) + ", more than " +
                                  std::to_string(kMaxTextureSide) + " texels a side");
    const bool bytes = a.dtype().kind() == 'u';
    if (bytes && a.itemsize() != 1)
        throw py::type_error(argument + ": expected " + expected + ", got an array of dtype " +
                             py::str(a.dtype()).cast<std::string>());
    const auto height = std::size_t(a.shape(0)), width = std::size_t(a.shape(1));
    const auto channels = std::size_t(a.shape(2));
    std::vector<std::uint8_t> rgba(width * height * 4, 255);
    if (bytes) {
        auto c = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(a);
        const std::uint8_t* in = c.data();
        for (std::size_t i = 0; i < width * height; ++i)
            for (std::size_t k = 0; k < channels; ++k) rgba[i * 4 + k] = in[i * channels + k];
    } else {
        auto c = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
        const double* in = c.data();
        for (std::size_t i = 0; i < width * height * channels; ++i) {
            const double v = in[i];
            if (!(v >= 0.0 && v <= 1.0))
                input_error(argument, "float texels must be in [0, 1], got " + std::to_string(v) +
                                          " at element " + std::to_string(i));
            rgba[i / channels * 4 + i % channels] = std::uint8_t(std::lround(v * 255.0));
        }
    }
    return std::make_shared<const Texture>(int(width), int(height), rgba, max_side);
}

long long integer_in_range(py::handle object, const std::string& argument, long long lo,
                           long long hi) {
    if (py::isinstance<py::bool_>(object) || !py::hasattr(object, "__index__"))
        type_error(argument, "an integer", object);
    const py::int_ value(py::reinterpret_borrow<py::object>(object));
    if (value < py::int_(lo) || value > py::int_(hi))
        input_error(argument, "must be in " + std::to_string(lo) + ".." + std::to_string(hi) +
                                  ", got " + std::string(py::str(py::handle(value))));
    return value.cast<long long>();
}

int image_side(py::handle object, const std::string& argument) {
    return int(integer_in_range(object, argument, 1, kMaxViewport));
}

double finite_number(py::handle object, const std::string& argument) {
    if (py::isinstance<py::bool_>(object) ||
        !(py::isinstance<py::int_>(object) || py::isinstance<py::float_>(object) ||
          py::hasattr(object, "__float__")))
        type_error(argument, "a number", object);
    const double v = py::float_(py::reinterpret_borrow<py::object>(object)).cast<double>();
    if (!std::isfinite(v)) input_error(argument, "must be finite, got " + std::to_string(v));
    return v;
}

glm::dmat4 matrix4(py::handle object, const std::string& argument) {
    const std::string expected = "a 4x4 matrix of real numbers";
    py::array a = as_array(object, argument, expected);
    require_kind(a, "fiu", argument, expected);
    if (a.ndim() != 2 || a.shape(0) != 4 || a.shape(1) != 4)
        input_error(argument, "expected a 4x4 matrix, got shape " + shape_text(a));
    auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    glm::dmat4 m;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            const double v = d.at(r, c);
            if (!std::isfinite(v))
                input_error(argument, "element [" + std::to_string(r) + ", " + std::to_string(c) +
                                          "] is not finite");
            m[c][r] = v;
        }
    return m;
}

glm::dvec4 vector_n(py::handle object, int n, const std::string& argument) {
    const std::string expected = std::to_string(n) + " numbers";
    py::array a = as_array(object, argument, expected);
    require_kind(a, "fiu", argument, expected);
    if (a.ndim() != 1 || a.shape(0) != n)
        input_error(argument,
                    "expected " + std::to_string(n) + " numbers, got shape " + shape_text(a));
    auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    glm::dvec4 v(0.0);
    for (int i = 0; i < n; ++i) {
        v[i] = d.at(i);
        if (!std::isfinite(v[i]))
            input_error(argument, "element " + std::to_string(i) + " is not finite");
    }
    return v;
}

py::array_t<double> to_numpy(const glm::dmat4& m) {
    py::array_t<double> a({4, 4});
    auto w = a.mutable_unchecked<2>();
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) w(r, c) = m[c][r];
    return a;
}

py::array_t<double> to_numpy(const glm::dvec3& v) {
    py::array_t<double> a(3);
    auto w = a.mutable_unchecked<1>();
    for (int i = 0; i < 3; ++i) w(i) = v[i];
    return a;
}

}  // namespace zraster::python
