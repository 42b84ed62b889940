// The input rules shared by every function of the Python module (module.cpp defines them):
// coordinates taken exactly, the one range of threads.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace exactccd::python {

/// A C-contiguous float64 array.
using DoubleArray = pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;

/// `obj` as a C-contiguous float64 array of `shape.size()` dimensions, each of the given size
/// (-1: any), else ValueError naming `name` and the `expected` shape. Coordinates are taken
/// exactly, never rounded: float64 as it is, float32 and float16 widened (exact), integer
/// arrays only when every value is a double.
DoubleArray float_array(const pybind11::handle& obj, const std::string& name, std::vector<pybind11::ssize_t> shape,
                        const std::string& expected);

/// The number of worker threads for `threads`, which must be in 0..kMaxThreads (0: every
/// hardware thread); anything else is a ValueError, never capped.
unsigned to_threads(long long threads);

}  // namespace exactccd::python
