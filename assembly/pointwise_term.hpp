#pragma once
// The generic weak form: a term defined by a point-wise kernel in flux form,
//   R_t(w) = sum over quadrature points of weight * ( f0_t . w + f1_t : grad w ),
// where f0 and f1 are functions of the fields' values and gradients at the point. The kernel is written
// once for a template scalar S; residuals run it with S = double and tangents with S = Dual, one pass
// per trial field, so no derivative is ever written by hand.
//
//   struct Reaction {  // f0 = k u^3 for a scalar field u at index 0
//     double k;
//     template <class S> void operator()(const PointInput<S>& in, PointFlux<S>& out) const {
//       out.f0[0][0] = k * in.value[0][0] * in.value[0][0] * in.value[0][0];
//     }
//   };
#include <array>
#include <type_traits>
#include <utility>

#include "assembly/dual.hpp"
#include "assembly/error.hpp"
#include "assembly/term.hpp"

namespace pc {

inline constexpr int kMaxTermFields = 6;
// Derivative directions of one field at a point: value and gradient of up to 3 components in 3D.
inline constexpr int kPointDirections = 12;
using PointDual = Dual<kPointDirections>;

template <class S> struct PointInput {
  int dim = 0;
  double time = 0;
  const double* x = nullptr;                                           // physical point
  const double* normal = nullptr;                                      // outward unit normal (faces), else null
  std::array<std::array<S, 3>, kMaxTermFields> value{};                // value[field][component]
  std::array<std::array<std::array<S, 3>, 3>, kMaxTermFields> grad{};  // grad[field][component][direction]
};

template <class S> struct PointFlux {
  std::array<std::array<S, 3>, kMaxTermFields> f0{};                 // f0[test field][component]
  std::array<std::array<std::array<S, 3>, 3>, kMaxTermFields> f1{};  // f1[test field][component][direction]
};

template <class Kernel> class PointwiseTerm : public Term {
 public:
  PointwiseTerm(std::string name, Integration integration, std::vector<FieldUse> fields, std::vector<int> tests,
                std::vector<Coupling> couplings, Kernel kernel, int extra_degree = 0)
      : Term(std::move(name), integration, std::move(fields), std::move(tests), std::move(couplings)),
        kernel_(std::move(kernel)),
        extra_degree_(extra_degree) {
    require(int(this->fields().size()) <= kMaxTermFields, "term '", this->name(), "' names more than ", kMaxTermFields,
            " fields");
  }

  const Kernel& kernel() const { return kernel_; }
  int quadrature_degree(int order) const override { return 2 * order + extra_degree_; }

  void assemble(const ElementData& e, LocalSystem& local, bool want_residual, bool want_tangent) const override {
    const int n_fields = static_cast<int>(fields().size());
    for (int q = 0; q < e.num_points; ++q) {
      bool residual_done = !want_residual;
      if (want_tangent) {
        for (int s = 0; s < n_fields; ++s) {
          if (!is_trial(s)) continue;
          PointInput<PointDual> in;
          load(e, q, in, s);
          PointFlux<PointDual> out;
          kernel_(in, out);
          if (!residual_done) {
            add_residual(e, q, out, local);
            residual_done = true;
          }
          add_tangent(e, q, s, out, local);
        }
      }
      if (!residual_done) {
        PointInput<double> in;
        load(e, q, in, -1);
        PointFlux<double> out;
        kernel_(in, out);
        add_residual(e, q, out, local);
      }
    }
  }

 private:
  bool is_trial(int field) const {
    for (const Coupling& c : couplings())
      if (c.trial == field) return true;
    return false;
  }

  // Loads values and gradients at point q; with S = PointDual, field `seeded` carries the directions
  // value(c) -> c * (1 + dim), grad(c, d) -> c * (1 + dim) + 1 + d.
  template <class S> void load(const ElementData& e, int q, PointInput<S>& in, int seeded) const {
    in.dim = e.dim;
    in.time = e.time;
    in.x = e.points[q].data();
    in.normal = e.normals.empty() ? nullptr : e.normals[q].data();
    for (int f = 0; f < int(e.fields.size()); ++f) {
      const ElementData::Field& field = e.fields[f];
      const bool has_grad = !field.grad.empty();
      for (int c = 0; c < field.num_components; ++c) {
        const double v = field.value[q * field.num_components + c];
        if constexpr (std::is_same_v<S, double>) {
          in.value[f][c] = v;
        } else {
          in.value[f][c] = f == seeded ? S::variable(v, c * (1 + e.dim)) : S(v);
        }
        if (!has_grad) continue;
        for (int d = 0; d < e.dim; ++d) {
          const double g = field.grad[(q * field.num_components + c) * e.dim + d];
          if constexpr (std::is_same_v<S, double>) {
            in.grad[f][c][d] = g;
          } else {
            in.grad[f][c][d] = f == seeded ? S::variable(g, c * (1 + e.dim) + 1 + d) : S(g);
          }
        }
      }
    }
  }

  template <class S> void add_residual(const ElementData& e, int q, const PointFlux<S>& out, LocalSystem& local) const {
    const double w = e.weights[q];
    for (int ti = 0; ti < int(tests().size()); ++ti) {
      const int t = tests()[ti];
      const ElementData::Field& field = e.fields[t];
      const bool has_grad = !field.dN.empty();
      Eigen::VectorXd& r = local.residual[ti];
      for (int i = 0; i < field.num_shapes; ++i) {
        const double Ni = field.shape(q, i);
        const double* dNi = has_grad ? field.shape_grad(q, i, e.dim) : nullptr;
        for (int c = 0; c < field.num_components; ++c) {
          double value = Ni * value_of(out.f0[t][c]);
          if (has_grad)
            for (int d = 0; d < e.dim; ++d) value += dNi[d] * value_of(out.f1[t][c][d]);
          r[i * field.num_components + c] += w * value;
        }
      }
    }
  }

  // K(i ct, j cs) += w * (a_i N_j + sum_e b_i[e] dN_j[e]) with a_i = N_i df0/du + dN_i . df1/du and
  // b_i[e] = N_i df0/dgrad_e + dN_i . df1/dgrad_e.
  void add_tangent(const ElementData& e, int q, int s, const PointFlux<PointDual>& out, LocalSystem& local) const {
    const double w = e.weights[q];
    const int dim = e.dim;
    const ElementData::Field& trial = e.fields[s];
    const bool trial_grad = !trial.dN.empty();
    for (int k = 0; k < int(couplings().size()); ++k) {
      if (couplings()[k].trial != s) continue;
      const int t = couplings()[k].test;
      const ElementData::Field& test = e.fields[t];
      const bool test_grad = !test.dN.empty();
      Eigen::MatrixXd& K = local.tangent[k];
      for (int ct = 0; ct < test.num_components; ++ct) {
        for (int cs = 0; cs < trial.num_components; ++cs) {
          const int base = cs * (1 + dim);
          for (int i = 0; i < test.num_shapes; ++i) {
            const double Ni = test.shape(q, i);
            const double* dNi = test_grad ? test.shape_grad(q, i, dim) : nullptr;
            double a = Ni * out.f0[t][ct].d[base];
            double b[3] = {0, 0, 0};
            for (int d = 0; d < dim; ++d) {
              b[d] = Ni * out.f0[t][ct].d[base + 1 + d];
              if (!test_grad) continue;
              a += dNi[d] * out.f1[t][ct][d].d[base];
            }
            if (test_grad)
              for (int d = 0; d < dim; ++d)
                for (int g = 0; g < dim; ++g) b[g] += dNi[d] * out.f1[t][ct][d].d[base + 1 + g];
            const int row = i * test.num_components + ct;
            for (int j = 0; j < trial.num_shapes; ++j) {
              double value = a * trial.shape(q, j);
              if (trial_grad) {
                const double* dNj = trial.shape_grad(q, j, dim);
                for (int g = 0; g < dim; ++g) value += b[g] * dNj[g];
              }
              K(row, j * trial.num_components + cs) += w * value;
            }
          }
        }
      }
    }
  }

  Kernel kernel_;
  int extra_degree_;
};

}  // namespace pc
