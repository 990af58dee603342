// numpy arrays in: checked (shape, dtype, finite values, index range) and referenced as they are
// when their layout is one zraster reads directly, else copied once into one it does.
#pragma once
#include <zraster/mesh_view.hpp>
#include <zraster/texture.hpp>

#include <pybind11/numpy.h>
#include <glm/glm.hpp>

#include <cstddef>
#include <memory>
#include <string>

namespace zraster::python {

namespace py = pybind11;

// Rows of `columns` floats: shape (N, columns), any real dtype. Referenced when float32 with
// contiguous rows (row stride >= one row, any padding); otherwise copied to float32, C order.
// Non-finite values are an InputError naming the argument.
struct FloatRows {
    py::array array;  // what the view points into: the argument itself, or the copy
    AttributeView view;
    bool copied = false;
};
FloatRows float_rows(py::handle object, std::size_t columns, const std::string& argument);

// Triangle indices: shape (M, 3) or flat (3M,), any integer dtype. Referenced when uint32,
// int32 or uint16 and contiguous; otherwise copied to uint32. Every index must be in
// 0..vertex_count - 1 (an InputError naming the argument and the first bad index).
struct Indices {
    py::array array;
    IndexView view;
    bool copied = false;
};
Indices triangle_indices(py::handle object, std::size_t vertex_count, const std::string& argument);

// An image as a texture: shape (H, W, 3) or (H, W, 4), uint8, or floats in [0, 1] (scaled by 255
// and rounded to the nearest byte); rows top to bottom, as an image file's. RGB gets alpha 255.
// Copied into a zraster::Texture with its mip chain, reduced as the loaders reduce an image to
// max_side. A wrong dtype is a TypeError, a wrong shape or a float out of [0, 1] an InputError,
// both naming the argument.
std::shared_ptr<const Texture> texture_image(py::handle object, const std::string& argument,
                                             int max_side);

// A 4x4 matrix (row-major as numpy shows it, acting on column vectors) as glm's column-major.
glm::dmat4 matrix4(py::handle object, const std::string& argument);
// A vector of `n` finite numbers.
glm::dvec4 vector_n(py::handle object, int n, const std::string& argument);
// A glm matrix as a (4, 4) float64 array.
py::array_t<double> to_numpy(const glm::dmat4& m);
py::array_t<double> to_numpy(const glm::dvec3& v);

// An image width or height: an integer in 1..kMaxViewport, else TypeError / InputError naming
// the argument.
int image_side(py::handle object, const std::string& argument);

// An integer (not a bool) in lo..hi, else TypeError / InputError naming the argument; compared
// as a Python int first, so that 2**64 or -2**70 is a range error, not a failed conversion.
long long integer_in_range(py::handle object, const std::string& argument, long long lo,
                           long long hi);

// A finite number (int or float), else TypeError / InputError naming the argument.
double finite_number(py::handle object, const std::string& argument);

}  // namespace zraster::python
