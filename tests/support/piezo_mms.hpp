#pragma once
// Test support: a manufactured solution of the coupled piezoelectric problem on the unit square, and the
// model that should reproduce it, assembled from the bulk bricks with a given time scheme:
//   rho u'' - div(A eps(u') + B eps(u) + E^T grad phi) = f0,   div(E eps(u) - beta grad phi) = q0,
// with u_i(x, t) = g(t) U_i s(x), phi(x, t) = g(t) P s(x), s a shifted sine product, and Dirichlet data
// (v = g'(t) U s, phi = g(t) P s) on the whole boundary. Inertia and viscosity are optional.
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <utility>

#include "assembly/fe_space.hpp"
#include "assembly/mesh.hpp"
#include "assembly/norms.hpp"
#include "bricks/dirichlet_brick.hpp"
#include "bricks/elasticity_brick.hpp"
#include "bricks/inertia_brick.hpp"
#include "bricks/permittivity_brick.hpp"
#include "bricks/piezoelectric_brick.hpp"
#include "bricks/source_bricks.hpp"
#include "bricks/viscosity_brick.hpp"
#include "models/model.hpp"
#include "models/time_scheme.hpp"
#include "support/manufactured.hpp"
#include "support/piezo_material.hpp"

namespace pc::testing {

// The spatial profile of the exact fields and the loads it needs (per unit g).
struct PiezoMmsExact {
  SineProduct s{2};
  double U[2] = {1.0, -0.7};
  double P = 0.8;
  PiezoTensors m = scaled_pzt5h();

  // The Hessian of s at x (the loads need nothing else: evaluate it once per point).
  using Hessian = std::array<std::array<double, 2>, 2>;
  Hessian hessian(const double* x) const {
    const double xy = s.hessian(x, 0, 1);
    return {{{s.hessian(x, 0, 0), xy}, {xy, s.hessian(x, 1, 1)}}};
  }
  // -div(C eps(w) + E^T grad(chi)) for w_i = U_i s, chi = P s, from the Hessian H of s.
  double minus_div_stress(const Hessian& H, int i, const Eigen::MatrixXd& C, bool with_piezo) const {
    double div = 0;
    for (int j = 0; j < 2; ++j) {
      for (int k = 0; k < 2; ++k)
        for (int l = 0; l < 2; ++l) div += C(voigt_index_2d(i, j), voigt_index_2d(k, l)) * U[k] * H[j][l];
      if (with_piezo)
        for (int k = 0; k < 2; ++k) div += m.E(k, voigt_index_2d(i, j)) * P * H[j][k];
    }
    return -div;
  }
  // div D for D = E eps(w) - beta grad chi.
  double div_displacement(const Hessian& H) const {
    double div = 0;
    for (int k = 0; k < 2; ++k)
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) div += m.E(k, voigt_index_2d(i, j)) * U[i] * H[k][j];
    for (int k = 0; k < 2; ++k)
      for (int l = 0; l < 2; ++l) div -= m.beta(k, l) * P * H[k][l];
    return div;
  }
  // The vector field c U s interpolated on a space (e.g. u, v or a at a time: c = g, g', g'').
  Eigen::VectorXd interpolate_vector(const FESpace& space, double c) const {
    return space.interpolate([&](const double* x, double* out) {
      for (int i = 0; i < 2; ++i) out[i] = c * U[i] * s.value(x);
    });
  }
};

// The time profile g and its first two derivatives.
struct TimeProfile {
  std::function<double(double)> g, g_dot, g_ddot;
};

// g = sin 2t: smooth, starting from rest in u (g(0) = 0) with a velocity (g'(0) = 2).
inline TimeProfile sine_profile() {
  return {[](double t) { return std::sin(2 * t); }, [](double t) { return 2 * std::cos(2 * t); },
          [](double t) { return -4 * std::sin(2 * t); }};
}

struct PiezoMmsProblem {
  std::unique_ptr<Model> model;
  std::unique_ptr<TimeScheme> scheme;
};

struct PiezoMmsPhysics {
  bool inertia = false;
  bool viscosity = false;
  double rho = 1.3;
};

// Unknowns v and phi (P`order`), the scheme attached (with an acceleration iff inertia), the bulk bricks,
// the loads of the exact solution and its Dirichlet data; finalized.
inline PiezoMmsProblem build_piezo_mms_problem(std::shared_ptr<const Mesh> mesh, int order, const PiezoMmsExact& exact,
                                               PiezoMmsPhysics physics, std::unique_ptr<TimeScheme> scheme,
                                               const TimeProfile& time) {
  PiezoMmsProblem s;
  s.model = std::make_unique<Model>(mesh);
  s.scheme = std::move(scheme);
  Model& m = *s.model;
  m.add_unknown("v", std::make_shared<const FESpace>(mesh, order, 2));
  m.add_unknown("phi", std::make_shared<const FESpace>(mesh, order, 1));
  s.scheme->attach(m, physics.inertia);
  m.set_constant("B", exact.m.B);
  m.set_constant("E", exact.m.E);
  m.set_constant("beta", exact.m.beta);
  m.add_brick(std::make_shared<ElasticityBrick>());
  m.add_brick(std::make_shared<PiezoelectricCouplingBrick>());
  m.add_brick(std::make_shared<PermittivityBrick>());
  if (physics.inertia) {
    m.set_constant("rho", physics.rho);
    m.add_brick(std::make_shared<InertiaBrick>());
  }
  if (physics.viscosity) {
    m.set_constant("A", exact.m.A);
    m.add_brick(std::make_shared<ViscosityBrick>());
  }
  const auto g = time.g, g_dot = time.g_dot, g_ddot = time.g_ddot;
  m.add_brick(std::make_shared<BodyForceBrick>(
      [=](const double* x, double t, double* out) {
        const auto H = exact.hessian(x);
        for (int i = 0; i < 2; ++i) {
          out[i] = g(t) * exact.minus_div_stress(H, i, exact.m.B, true);
          if (physics.inertia) out[i] += physics.rho * g_ddot(t) * exact.U[i] * exact.s.value(x);
          if (physics.viscosity) out[i] += g_dot(t) * exact.minus_div_stress(H, i, exact.m.A, false);
        }
      },
      LoadTime::Varying));
  m.add_brick(std::make_shared<VolumeChargeBrick>(
      [=](const double* x, double t, double* out) { out[0] = g(t) * exact.div_displacement(exact.hessian(x)); },
      LoadTime::Varying));
  m.add_brick(std::make_shared<DirichletBrick>(
      "v", "boundary", std::vector<int>{},
      [=](const double* x, double t, double* out) {
        for (int i = 0; i < 2; ++i) out[i] = g_dot(t) * exact.U[i] * exact.s.value(x);
      },
      true));
  m.add_brick(std::make_shared<DirichletBrick>(
      "phi", "boundary", std::vector<int>{},
      [=](const double* x, double t, double* out) { out[0] = g(t) * exact.P * exact.s.value(x); }, true));
  m.finalize();
  return s;
}

struct PiezoMmsErrors {
  double u_l2, u_h1, phi_l2, phi_h1;
};

// Errors of the model's u and phi against the exact fields at a time where g = gT.
inline PiezoMmsErrors piezo_mms_errors(const Model& m, const PiezoMmsExact& exact, double gT) {
  auto u = [&](const double* x, double* out) {
    for (int i = 0; i < 2; ++i) out[i] = gT * exact.U[i] * exact.s.value(x);
  };
  auto grad_u = [&](const double* x, double* out) {
    for (int i = 0; i < 2; ++i)
      for (int d = 0; d < 2; ++d) out[i * 2 + d] = gT * exact.U[i] * exact.s.gradient(x, d);
  };
  auto phi = [&](const double* x, double* out) { out[0] = gT * exact.P * exact.s.value(x); };
  auto grad_phi = [&](const double* x, double* out) {
    for (int d = 0; d < 2; ++d) out[d] = gT * exact.P * exact.s.gradient(x, d);
  };
  return {l2_error(m.space("u"), m.values("u"), u), h1_seminorm_error(m.space("u"), m.values("u"), grad_u),
          l2_error(m.space("phi"), m.values("phi"), phi), h1_seminorm_error(m.space("phi"), m.values("phi"), grad_phi)};
}

}  // namespace pc::testing
