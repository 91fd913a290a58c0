#pragma once
// Input arrays of the Python API: one state (shape (n,)) or a batch (shape (N, n)) of float64.
//
// Policy (the docstrings say the same): a numpy array must already be float64 (native byte order),
// C-contiguous and aligned, otherwise TypeError (dtype) or ValueError (layout); nothing is copied
// into another layout behind the caller's back. A Python list or tuple is converted explicitly by
// numpy.asarray(x, dtype=float64) (a new array: lists have no layout to preserve). Every value must
// be finite (ValueError naming the argument and the first bad index): a single state is scanned
// here, a batch block by block (kScanBlock states) just before the block is evaluated
// (Robot::runMany, in the worker threads, on data about to be read anyway: a separate pass over a
// large batch would cost a few per cent of a batched call). Shapes are checked against the robot (ValueError naming the
// argument and the expected shape).
#include <cstdint>
#include <cstring>
#include <string>

#include <Eigen/Core>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

namespace rbdgen_py
{

namespace py = pybind11;

/// One checked input: data pointer (row-major, N rows of n), N (1 for a single state) and whether
/// the caller passed a batch. `array` keeps the data alive.
struct Input
{
  py::object array; ///< (not py::array, whose default constructor makes an empty numpy array)
  const double * data = nullptr;
  py::ssize_t rows = 1;
  bool batch = false;
  const char * name = ""; ///< the argument's name
};

inline std::string shapeText(const py::array & a)
{
  std::string s = "(";
  for(py::ssize_t d = 0; d < a.ndim(); ++d) s += (d ? ", " : "") + std::to_string(a.shape(d));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

inline std::string expectedText(py::ssize_t n) { return "(" + std::to_string(n) + ",) or (N, " + std::to_string(n) + ")"; }

/// No NaN or infinity in x[0, n): x * 0 is 0 for every finite x and NaN otherwise, so the sum of
/// x * 0 is 0 exactly when all are finite (Eigen's sum is vectorised whatever the optimisation
/// level). Under -ffinite-math-only (-ffast-math: a downstream PYTHON_MODULE build may use it)
/// the compiler may assume that away: the exponent bits are tested instead.
inline bool allFinite(const double * x, py::ssize_t n)
{
#if defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__
  std::uint64_t bad = 0;
  for(py::ssize_t k = 0; k < n; ++k)
  {
    std::uint64_t bits;
    std::memcpy(&bits, x + k, sizeof bits);
    bad |= static_cast<std::uint64_t>((bits & 0x7ff0000000000000ULL) == 0x7ff0000000000000ULL);
  }
  return bad == 0;
#else
  return (Eigen::Map<const Eigen::ArrayXd>(x, static_cast<Eigen::Index>(n)) * 0.0).sum() == 0.0;
#endif
}

/// "fn: argument 'name' has a non-finite value at [i, j]" (or [j] for a single state) for the first
/// non-finite value of row `row` (n values at x) of `in`; empty when there is none.
inline std::string nonFiniteMessage(const char * fn, const Input & in, py::ssize_t row, const double * x, py::ssize_t n)
{
  for(py::ssize_t k = 0; k < n; ++k)
    if(!allFinite(x + k, 1))
      return std::string(fn) + ": argument '" + in.name + "' has a non-finite value at "
             + (in.batch ? "[" + std::to_string(row) + ", " + std::to_string(k) + "]" : "[" + std::to_string(k) + "]");
  return {};
}

/// States of a batch checked at a time, before they are evaluated (their inputs then stay in cache).
inline constexpr py::ssize_t kScanBlock = 64;

/// Check `obj` (argument `name` of `fn`) as one state of size n or a batch (N, n); the values of a
/// batch are checked later, block by block (Robot::runMany).
inline Input checkInput(const char * fn, const char * name, const py::object & obj, py::ssize_t n)
{
  const auto where = [fn, name] { return std::string(fn) + ": argument '" + name + "'"; }; // errors only
  const py::array a = [&]() -> py::array {
    if(py::isinstance<py::array>(obj)) return py::reinterpret_borrow<py::array>(obj);
    if(py::isinstance<py::list>(obj) || py::isinstance<py::tuple>(obj))
      return py::module_::import("numpy").attr("asarray")(obj, py::arg("dtype") = "float64");
    throw py::type_error(where() + " must be a float64 numpy array of shape " + expectedText(n) + ", got "
                         + std::string(py::str(py::type::of(obj).attr("__name__"))));
  }();
  static const py::handle float64 = py::dtype::of<double>().release(); // numpy's float64 (kept for good)
  const py::dtype dtype = a.dtype();
  if(dtype.ptr() != float64.ptr() && !py::detail::npy_api::get().PyArray_EquivTypes_(dtype.ptr(), float64.ptr()))
    throw py::type_error(where() + " must have dtype float64 (native byte order), got " + std::string(py::str(py::handle(dtype)))
                         + "; convert with numpy.asarray(" + name + ", dtype=numpy.float64)");
  if(a.ndim() != 1 && a.ndim() != 2)
    throw py::value_error(where() + " must have shape " + expectedText(n) + ", got " + shapeText(a));
  if(a.shape(a.ndim() - 1) != n)
    throw py::value_error(where() + " must have shape " + expectedText(n) + ", got " + shapeText(a));
  const int flags = a.flags();
  if(!(flags & py::detail::npy_api::NPY_ARRAY_C_CONTIGUOUS_) || !(flags & py::detail::npy_api::NPY_ARRAY_ALIGNED_))
    throw py::value_error(where() + " must be C-contiguous and aligned (shape " + shapeText(a)
                          + " is a strided view); pass numpy.ascontiguousarray(" + name + ")");
  Input in;
  in.batch = a.ndim() == 2;
  in.rows = in.batch ? a.shape(0) : 1;
  in.data = static_cast<const double *>(a.data());
  in.name = name;
  if(!in.batch)
  {
    if(!allFinite(in.data, n)) throw py::value_error(nonFiniteMessage(fn, in, 0, in.data, n));
  }
  in.array = std::move(a);
  return in;
}

/// The inputs after the first must be single iff the first is, with the same N.
inline void checkSameBatch(const char * fn, const char * first, const Input & a, const char * name, const Input & b,
                           py::ssize_t n)
{
  if(a.batch != b.batch || a.rows != b.rows)
  {
    const std::string expected = a.batch ? "(" + std::to_string(a.rows) + ", " + std::to_string(n) + ")"
                                         : "(" + std::to_string(n) + ",)";
    throw py::value_error(std::string(fn) + ": argument '" + name + "' must have shape " + expected + " like '" + first
                          + "', got " + shapeText(py::reinterpret_borrow<py::array>(b.array)));
  }
}

} // namespace rbdgen_py
