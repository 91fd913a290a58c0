#pragma once
// The Python class of a robot, the same for the runtime (rbdgen.Robot) and for the generated code
// (rbdgen.compile): numpy in, numpy out, one state or a batch, threads, the GIL released for batches.
//
// A Model provides (all arrays row-major float64, sizes from the model):
//   int nq(), nv(), nbodies(); bool hasForwardDynamics();
//   std::vector<std::string> dofNames(), bodyNames(); std::string name();
//   Workspace makeWorkspace();  (scratch of one thread)
//   void forwardKinematics(Workspace &, const double * q, double * out);  // nbodies x 4 x 4
//   void inverseDynamics(Workspace &, const double * q, const double * v, const double * a, double * tau);
//   void massMatrix(Workspace &, const double * q, double * H);              // nv x nv
//   std::vector<std::array<int, 2>> massMatrixEntries();  (row, col) of H's entries that are not
//                                   structurally zero, row >= col; massMatrixPacked writes them:
//   void massMatrixPacked(Workspace &, const double * q, double * Hp);      // massMatrixEntries().size()
//   void forwardDynamics(Workspace &, const double * q, const double * v, const double * tau, double * a);
//   void jacobian(Workspace &, int body, const double * q, double * J);    // 6 x nv
//   void centerOfMass(Workspace &, const double * q, double * c);          // 3
//   bool hasDerivatives(); std::string noDerivativesReason();  (when false the two below are not called)
//   void inverseDynamicsDerivatives(Workspace &, const double * q, const double * v, const double * a,
//                                   double * dtauDq, double * dtauDv);     // nv x nv each
//   void forwardDynamicsDerivatives(Workspace &, const double * q, const double * v, const double * tau,
//                                   double * a, double * daDq, double * daDv, double * Minv);  // nv, nv x nv
// Derivatives with respect to q are taken in the tangent space (size nv: q ⊕ ε e_m moves joint j of
// dof m by its motion subspace S_m; for a free joint [dw; dv] in the child frame, like v).
// A Model with `static constexpr bool kBatched = true` evaluates blocks of consecutive states: each
// function above then takes a last argument `std::ptrdiff_t n`, the number of states (consecutive
// items of the arrays), 0 for a single-state call (the compiled robots: the single-state generated
// function for 0, the batch API on SIMD packs for n >= 1, even n = 1, so that a state of a batch is
// evaluated the same way whatever the thread count).
#include <algorithm>
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "parallel.hpp"

namespace rbdgen_py
{

/// Whether Model evaluates blocks of states (Model::kBatched, see the top of this file).
template<class Model, class = void>
struct Batched : std::false_type
{
};
template<class Model>
struct Batched<Model, std::void_t<decltype(Model::kBatched)>> : std::bool_constant<Model::kBatched>
{
};

/// (md.*f)(args..., n) for a batched Model; (md.*f)(args...) otherwise (n is then 0: one state).
template<class Model, class F, class... A>
void callModel(const Model & md, F f, std::ptrdiff_t n, A &&... args)
{
  if constexpr(Batched<Model>::value) (md.*f)(std::forward<A>(args)..., n);
  else (md.*f)(std::forward<A>(args)...);
}

/// A model and the workspace of single-state calls (used with the GIL held, so one at a time).
template<class Model>
class Robot
{
public:
  using Workspace = decltype(std::declval<const Model &>().makeWorkspace());

  explicit Robot(std::shared_ptr<const Model> model) : model_(std::move(model)) {}
  const Model & model() const { return *model_; }
  Workspace & single()
  {
    if(!single_) single_.emplace(model_->makeWorkspace());
    return *single_;
  }

  /// Evaluate f(ws, inputs, outputs, n) on the states of `in` (all checked, same batch size) into M
  /// new arrays, output m of shape itemShapes[m] (prefixed by N for a batch): f evaluates the n
  /// states from the given pointers on (n = 0: one state, a single-state call; a batched Model gets
  /// blocks of up to kScanBlock states, any other one state per call with n = 0).
  template<std::size_t K, std::size_t M, class F>
  std::array<py::object, M> runMany(const char * fn, const std::array<Input, K> & in,
                                    const std::array<py::ssize_t, K> & width,
                                    std::array<std::vector<py::ssize_t>, M> itemShapes, int threads, F && f)
  {
    if(threads < 1) throw py::value_error(std::string(fn) + ": threads must be >= 1, got " + std::to_string(threads));
    std::array<py::object, M> out; // (py::array's default constructor would make an empty numpy array)
    std::array<double *, M> o;
    std::array<py::ssize_t, M> itemSize;
    for(std::size_t m = 0; m < M; ++m)
    {
      itemSize[m] = 1;
      for(py::ssize_t d : itemShapes[m]) itemSize[m] *= d;
      if(in[0].batch) itemShapes[m].insert(itemShapes[m].begin(), in[0].rows);
      py::array_t<double> a(itemShapes[m]);
      o[m] = a.mutable_data();
      out[m] = std::move(a);
    }
    // states from i on (n of them; 0: one state, single-state call)
    auto evaluate = [&](Workspace & ws, std::ptrdiff_t i, std::ptrdiff_t n) {
      std::array<const double *, K> p;
      for(std::size_t k = 0; k < K; ++k) p[k] = in[k].data + i * width[k];
      std::array<double *, M> r;
      for(std::size_t m = 0; m < M; ++m) r[m] = o[m] + i * itemSize[m];
      f(ws, p, r, n);
    };
    try
    {
      if(!in[0].batch) evaluate(single(), 0, 0); // (its values were checked by checkInput)
      else
      {
        const Model & md = *model_;
        const std::ptrdiff_t rows = in[0].rows;
        py::gil_scoped_release release;
        parallelFor(rows, threads, [&md] { return md.makeWorkspace(); },
                    [&](Workspace & ws, std::ptrdiff_t begin, std::ptrdiff_t end, std::ptrdiff_t & at) {
                      for(at = begin; at < end;)
                      {
                        // the next block of states: its values, about to be read, are checked first
                        const std::ptrdiff_t blockEnd = std::min(end, at + kScanBlock);
                        checkFinite(fn, in, width, at, blockEnd);
                        if constexpr(Batched<Model>::value)
                        {
                          evaluate(ws, at, blockEnd - at);
                          at = blockEnd;
                        }
                        else
                          for(; at < blockEnd; ++at) evaluate(ws, at, 0);
                      }
                    });
      }
    }
    catch(const InputError & e)
    {
      throw py::value_error(e.what());
    }
    catch(const std::exception & e)
    {
      throw std::runtime_error(std::string(fn) + ": " + e.what());
    }
    return out;
  }

  /// Inputs of states [begin, end) of a batch are finite, else InputError for the first bad state
  /// (then the first bad argument, the first bad value).
  template<std::size_t K>
  static void checkFinite(const char * fn, const std::array<Input, K> & in, const std::array<py::ssize_t, K> & width,
                          std::ptrdiff_t begin, std::ptrdiff_t end)
  {
    bool ok = true;
    for(std::size_t k = 0; k < K; ++k) ok = ok && allFinite(in[k].data + begin * width[k], (end - begin) * width[k]);
    if(ok) return;
    for(std::ptrdiff_t i = begin; i < end; ++i)
      for(std::size_t k = 0; k < K; ++k)
        if(!allFinite(in[k].data + i * width[k], width[k]))
          throw InputError(nonFiniteMessage(fn, in[k], i, in[k].data + i * width[k], width[k]));
  }

  /// runMany with one output: f(ws, inputs, out, n).
  template<std::size_t K, class F>
  py::object run(const char * fn, const std::array<Input, K> & in, const std::array<py::ssize_t, K> & width,
                 std::vector<py::ssize_t> itemShape, int threads, F && f)
  {
    auto out = runMany<K, 1>(fn, in, width, {std::move(itemShape)}, threads,
                             [&f](auto & ws, const auto & p, const std::array<double *, 1> & o, std::ptrdiff_t n) {
                               f(ws, p, o[0], n);
                             });
    return std::move(out[0]);
  }

  void requireDerivatives(const char * fn) const
  {
    if(!model_->hasDerivatives())
      throw std::runtime_error(std::string(fn) + ": not available for '" + model_->name() + "' (" + model_->noDerivativesReason()
                               + ")");
  }

  /// Body index from a link name (KeyError) or an index (IndexError).
  int bodyIndex(const char * fn, const py::object & body) const
  {
    const std::vector<std::string> names = model_->bodyNames();
    if(py::isinstance<py::str>(body))
    {
      const std::string name = body.cast<std::string>();
      for(std::size_t i = 0; i < names.size(); ++i)
        if(names[i] == name) return static_cast<int>(i);
      std::string known;
      for(std::size_t i = 0; i < names.size(); ++i) known += (i ? ", '" : "'") + names[i] + "'";
      throw py::key_error(std::string(fn) + ": argument 'body': unknown link '" + name + "'; links: " + known);
    }
    if(PyIndex_Check(body.ptr()) && !py::isinstance<py::bool_>(body)) // int, numpy integers
    {
      const Py_ssize_t i = PyNumber_AsSsize_t(body.ptr(), nullptr); // clamped when out of range
      if(i == -1 && PyErr_Occurred()) throw py::error_already_set();
      if(i < 0 || i >= static_cast<Py_ssize_t>(names.size()))
        throw py::index_error(std::string(fn) + ": argument 'body': index " + std::to_string(i) + " out of range [0, "
                              + std::to_string(names.size()) + ")");
      return static_cast<int>(i);
    }
    throw py::type_error(std::string(fn) + ": argument 'body' must be a link name (str) or an index (int)");
  }

private:
  std::shared_ptr<const Model> model_;
  std::optional<Workspace> single_;
};

inline constexpr const char * kArrayPolicy =
    "Arrays: float64, C-contiguous numpy arrays (a list or tuple is converted with numpy.asarray(x, "
    "dtype=float64)); another dtype raises TypeError, a strided view ValueError (nothing is copied behind "
    "your back); non-finite values and wrong shapes raise ValueError. One state (n,) gives one result; a "
    "batch (N, n) gives N results (N, ...), computed with the GIL released on `threads` threads "
    "(at most 256, contiguous chunks of the batch; bitwise the same results for any thread count).";

inline std::string doc(const std::string & what) { return what + "\n\n" + kArrayPolicy; }

/// Define method `name`(q, *, threads=1) of a function of q alone: q checked (shape, dtype, finite),
/// then Model::*method over the state or the batch into an array of shape itemShape(model) per state.
template<class R, class Method, class Shape>
void defFunctionOfQ(py::class_<R> & cls, const char * name, Method method, Shape itemShape, const std::string & what)
{
  cls.def(
      name,
      [name, method, itemShape](R & r, const py::object & q, int threads) {
        const auto & md = r.model();
        const std::array<Input, 1> in{checkInput(name, "q", q, md.nq())};
        return r.run(name, in, {md.nq()}, itemShape(md), threads,
                     [&md, method](auto & ws, const auto & p, double * o, std::ptrdiff_t states) {
                       callModel(md, method, states, ws, p[0], o);
                     });
      },
      py::arg("q"), py::kw_only(), py::arg("threads") = 1, doc(what).c_str());
}

/// Define the Python class `name` for Robot<Model> in module m. local: visible to this module only
/// (each module made by rbdgen.compile has its own).
template<class Model>
py::class_<Robot<Model>> bindRobot(py::module_ & m, const char * name, const char * classDoc, bool local = false)
{
  using R = Robot<Model>;
  py::class_<R> cls(m, name, classDoc, py::module_local(local));
  cls.def_property_readonly("nq", [](const R & r) { return r.model().nq(); }, "size of q")
      .def_property_readonly("nv", [](const R & r) { return r.model().nv(); }, "size of v (alpha), a and tau")
      .def_property_readonly("name", [](const R & r) { return r.model().name(); }, "robot name")
      .def_property_readonly("dof_names", [](const R & r) { return r.model().dofNames(); },
                             "joint owning each velocity coordinate (length nv; the floating base is 'Root')")
      .def_property_readonly("body_names", [](const R & r) { return r.model().bodyNames(); },
                             "URDF links in body order (forward_kinematics' first axis)")
      .def_property_readonly("has_forward_dynamics", [](const R & r) { return r.model().hasForwardDynamics(); },
                             "false when the mass matrix is singular (forward_dynamics then raises RuntimeError)")
      .def_property_readonly("has_derivatives", [](const R & r) { return r.model().hasDerivatives(); },
                             "whether inverse_dynamics_derivatives and forward_dynamics_derivatives are available "
                             "(not for rbdgen.compile(..., derivatives=False))")
      .def("__repr__", [name](const R & r) {
        return std::string("<rbdgen.") + name + " '" + r.model().name() + "' nq=" + std::to_string(r.model().nq())
               + " nv=" + std::to_string(r.model().nv()) + ">";
      });

  using Shape = std::vector<py::ssize_t>;
  defFunctionOfQ(cls, "forward_kinematics", &Model::forwardKinematics, [](const Model & md) { return Shape{md.nbodies(), 4, 4}; },
                 "World pose of every link: (nbodies, 4, 4) homogeneous transforms [R p; 0 1], R the link's "
                 "orientation in world (the transpose of sva's E), p its origin in world; (N, nbodies, 4, 4) for a batch.");

  cls.def(
      "inverse_dynamics",
      [](R & r, const py::object & q, const py::object & v, const py::object & a, int threads) {
        const Model & md = r.model();
        const std::array<Input, 3> in{checkInput("inverse_dynamics", "q", q, md.nq()),
                                      checkInput("inverse_dynamics", "v", v, md.nv()),
                                      checkInput("inverse_dynamics", "a", a, md.nv())};
        checkSameBatch("inverse_dynamics", "q", in[0], "v", in[1], md.nv());
        checkSameBatch("inverse_dynamics", "q", in[0], "a", in[2], md.nv());
        return r.run("inverse_dynamics", in, {md.nq(), md.nv(), md.nv()}, {md.nv()}, threads,
                     [&md](auto & ws, const auto & p, double * o, std::ptrdiff_t states) {
                       callModel(md, &Model::inverseDynamics, states, ws, p[0], p[1], p[2], o);
                     });
      },
      py::arg("q"), py::arg("v"), py::arg("a"), py::kw_only(), py::arg("threads") = 1,
      doc("Joint torques tau (nv,) for accelerations a at (q, v), gravity included (RNEA).").c_str());

  defFunctionOfQ(cls, "mass_matrix", &Model::massMatrix, [](const Model & md) { return Shape{md.nv(), md.nv()}; },
                 "Joint-space inertia matrix H(q), (nv, nv).");

  cls.def_property_readonly(
      "mass_matrix_entries",
      [](const R & r) {
        const auto entries = r.model().massMatrixEntries();
        py::array_t<int> a({static_cast<py::ssize_t>(entries.size()), py::ssize_t{2}});
        auto w = a.mutable_unchecked<2>();
        for(std::size_t k = 0; k < entries.size(); ++k)
        {
          w(static_cast<py::ssize_t>(k), 0) = entries[k][0];
          w(static_cast<py::ssize_t>(k), 1) = entries[k][1];
        }
        return a;
      },
      "(nnz, 2) int array: the (row, col) of the entries of the mass matrix that are not structurally zero, "
      "row >= col (H is symmetric; every other entry is 0); mass_matrix_packed(q)[k] is H[row_k, col_k]");

  defFunctionOfQ(cls, "mass_matrix_packed", &Model::massMatrixPacked,
                 [](const Model & md) { return Shape{static_cast<py::ssize_t>(md.massMatrixEntries().size())}; },
                 "The entries of H(q) listed by mass_matrix_entries, (nnz,): the mass matrix without its structural "
                 "zeros (a compiled robot's batch computes only these).");

  cls.def(
      "forward_dynamics",
      [](R & r, const py::object & q, const py::object & v, const py::object & tau, int threads) {
        const Model & md = r.model();
        if(!md.hasForwardDynamics())
          throw std::runtime_error("forward_dynamics: the mass matrix of '" + md.name()
                                   + "' is singular (joints moving only massless links): no forward dynamics");
        const std::array<Input, 3> in{checkInput("forward_dynamics", "q", q, md.nq()),
                                      checkInput("forward_dynamics", "v", v, md.nv()),
                                      checkInput("forward_dynamics", "tau", tau, md.nv())};
        checkSameBatch("forward_dynamics", "q", in[0], "v", in[1], md.nv());
        checkSameBatch("forward_dynamics", "q", in[0], "tau", in[2], md.nv());
        return r.run("forward_dynamics", in, {md.nq(), md.nv(), md.nv()}, {md.nv()}, threads,
                     [&md](auto & ws, const auto & p, double * o, std::ptrdiff_t states) {
                       callModel(md, &Model::forwardDynamics, states, ws, p[0], p[1], p[2], o);
                     });
      },
      py::arg("q"), py::arg("v"), py::arg("tau"), py::kw_only(), py::arg("threads") = 1,
      doc("Joint accelerations a (nv,) = H(q)^-1 (tau - C(q, v)), gravity included.").c_str());

  cls.def(
      "inverse_dynamics_derivatives",
      [](R & r, const py::object & q, const py::object & v, const py::object & a, int threads) {
        const Model & md = r.model();
        r.requireDerivatives("inverse_dynamics_derivatives");
        const std::array<Input, 3> in{checkInput("inverse_dynamics_derivatives", "q", q, md.nq()),
                                      checkInput("inverse_dynamics_derivatives", "v", v, md.nv()),
                                      checkInput("inverse_dynamics_derivatives", "a", a, md.nv())};
        checkSameBatch("inverse_dynamics_derivatives", "q", in[0], "v", in[1], md.nv());
        checkSameBatch("inverse_dynamics_derivatives", "q", in[0], "a", in[2], md.nv());
        const py::ssize_t n = md.nv();
        auto out = r.template runMany<3, 2>(
            "inverse_dynamics_derivatives", in, {md.nq(), n, n}, {{{n, n}, {n, n}}}, threads,
            [&md](auto & ws, const auto & p, const auto & o, std::ptrdiff_t states) {
              callModel(md, &Model::inverseDynamicsDerivatives, states, ws, p[0], p[1], p[2], o[0], o[1]);
            });
        return py::make_tuple(std::move(out[0]), std::move(out[1]));
      },
      py::arg("q"), py::arg("v"), py::arg("a"), py::kw_only(), py::arg("threads") = 1,
      doc("Derivatives of inverse_dynamics at (q, v, a): a tuple (dtau_dq, dtau_dv), each (nv, nv) (row: "
          "torque, column: coordinate), (N, nv, nv) for a batch; dtau/da is mass_matrix(q). d/dq is taken in the "
          "tangent space (nv columns): column m moves joint j of dof m by its motion subspace, for a free joint "
          "[dw; dv] in the child frame (the coordinates of v).")
          .c_str());

  cls.def(
      "forward_dynamics_derivatives",
      [](R & r, const py::object & q, const py::object & v, const py::object & tau, int threads) {
        const Model & md = r.model();
        r.requireDerivatives("forward_dynamics_derivatives");
        if(!md.hasForwardDynamics())
          throw std::runtime_error("forward_dynamics_derivatives: the mass matrix of '" + md.name()
                                   + "' is singular (joints moving only massless links): no forward dynamics");
        const std::array<Input, 3> in{checkInput("forward_dynamics_derivatives", "q", q, md.nq()),
                                      checkInput("forward_dynamics_derivatives", "v", v, md.nv()),
                                      checkInput("forward_dynamics_derivatives", "tau", tau, md.nv())};
        checkSameBatch("forward_dynamics_derivatives", "q", in[0], "v", in[1], md.nv());
        checkSameBatch("forward_dynamics_derivatives", "q", in[0], "tau", in[2], md.nv());
        const py::ssize_t n = md.nv();
        auto out = r.template runMany<3, 4>(
            "forward_dynamics_derivatives", in, {md.nq(), n, n}, {{{n}, {n, n}, {n, n}, {n, n}}}, threads,
            [&md](auto & ws, const auto & p, const auto & o, std::ptrdiff_t states) {
              callModel(md, &Model::forwardDynamicsDerivatives, states, ws, p[0], p[1], p[2], o[0], o[1], o[2], o[3]);
            });
        return py::make_tuple(std::move(out[0]), std::move(out[1]), std::move(out[2]), std::move(out[3]));
      },
      py::arg("q"), py::arg("v"), py::arg("tau"), py::kw_only(), py::arg("threads") = 1,
      doc("Forward dynamics and its derivatives at (q, v, tau): a tuple (a, da_dq, da_dv, Minv), a = "
          "forward_dynamics(q, v, tau) (nv,), the others (nv, nv); Minv = mass_matrix(q)^-1 = da/dtau; with a batch "
          "(N, nv) and (N, nv, nv). d/dq in the tangent space, as inverse_dynamics_derivatives.")
          .c_str());

  cls.def(
      "jacobian",
      [](R & r, const py::object & body, const py::object & q, int threads) {
        const Model & md = r.model();
        const int b = r.bodyIndex("jacobian", body);
        const std::array<Input, 1> in{checkInput("jacobian", "q", q, md.nq())};
        return r.run("jacobian", in, {md.nq()}, {6, md.nv()}, threads,
                     [&md, b](auto & ws, const auto & p, double * o, std::ptrdiff_t states) {
                       callModel(md, &Model::jacobian, states, ws, b, p[0], o);
                     });
      },
      py::arg("body"), py::arg("q"), py::kw_only(), py::arg("threads") = 1,
      doc("Jacobian (6, nv) of a link (name or index in body_names): rows [angular; linear] in world axes, "
          "at the link origin, J v = [w; v_origin].")
          .c_str());

  defFunctionOfQ(cls, "center_of_mass", &Model::centerOfMass, [](const Model &) { return Shape{3}; },
                 "Centre of mass (3,) in world coordinates.");
  return cls;
}

} // namespace rbdgen_py
