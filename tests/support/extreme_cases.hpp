#pragma once
// The extremes of the paper's scene (scenes/paper2d.json) as --set overrides: contact and foundation
// parameters from zero to the largest values double arithmetic allows the model to hold, time steps from
// 1e-9 s to the whole span, no inertia or viscosity, degenerate meshes. Shared by the test
// (tests/models/extremes_test.cpp, on a coarse mesh) and the study (benchmarks/extremes_study.cpp, on the
// scene's mesh), so that the two run the same cases. Each case runs one foundation of the scene; the
// overrides come after the caller's own (mesh size, steps), so a case that sets the mesh or the steps wins.
#include <string>
#include <vector>

namespace pc::testing {

struct ExtremeCase {
  std::string name;        // a C identifier: it names the ctest entry
  std::string foundation;  // "insulated" or "conductive"
  std::vector<std::string> overrides;
};

// The normal damping coefficients over which the penetration must fall monotonically.
inline const std::vector<double>& penetration_c_nu() {
  static const std::vector<double> values = {1e6, 1e9, 1e12, 1e16};
  return values;
}

inline std::vector<ExtremeCase> extreme_cases() {
  const std::string zero_A = "material.viscosity_A=[[0,0,0],[0,0,0],[0,0,0]]";
  return {
      {"baseline_insulated", "insulated", {}},
      {"baseline_conductive", "conductive", {}},
      // Normal damping: none (the strip hangs from its clamp), soft, the scene's, and stiff.
      {"c_nu_0", "insulated", {"contact.c_nu=0"}},
      {"c_nu_1e6", "insulated", {"contact.c_nu=1e6"}},
      {"c_nu_1e9", "insulated", {"contact.c_nu=1e9"}},
      {"c_nu_1e16", "insulated", {"contact.c_nu=1e16"}},
      {"c_nu_1e16_conductive", "conductive", {"contact.c_nu=1e16"}},
      {"c_nu_1e16_full_newton", "conductive", {"contact.c_nu=1e16", "solver.condensed=false"}},
      // Tangential damping: frictionless to sticking.
      {"c_tau_0", "insulated", {"contact.c_tau=0"}},
      {"c_tau_1e12", "insulated", {"contact.c_tau=1e12"}},
      // Foundation conductance: none (must equal the insulated run) to an imposed potential.
      {"k_e_0", "conductive", {"foundation.conductive.k_e=0"}},
      {"k_e_1e15", "conductive", {"foundation.conductive.k_e=1e15"}},
      // Foundation voltage.
      {"phi_f_0", "conductive", {"foundation.conductive.phi_f=0"}},
      {"phi_f_plus_1e5", "conductive", {"foundation.conductive.phi_f=1e5"}},
      {"phi_f_minus_1e5", "conductive", {"foundation.conductive.phi_f=-1e5"}},
      // Time steps: 1e-9 s, and the whole span in one step (alone and with the stiffest contact).
      {"dt_1e_9", "conductive", {"time.T=1e-8", "time.steps=10"}},
      {"dt_1e_9_c_nu_1e16", "conductive", {"time.T=1e-8", "time.steps=10", "contact.c_nu=1e16"}},
      {"one_step", "conductive", {"time.steps=1"}},
      {"one_step_c_nu_1e16", "conductive", {"time.steps=1", "contact.c_nu=1e16"}},
      {"one_step_c_nu_1e16_full_newton", "conductive", {"time.steps=1", "contact.c_nu=1e16", "solver.condensed=false"}},
      {"one_step_k_e_1e15", "conductive", {"time.steps=1", "foundation.conductive.k_e=1e15"}},
      // No inertia (quasi-static), no viscosity, neither.
      {"rho_0", "conductive", {"material.rho=0"}},
      {"A_0", "conductive", {zero_A}},
      {"rho_0_A_0", "conductive", {"material.rho=0", zero_A}},
      {"rho_0_A_0_c_nu_1e16", "conductive", {"material.rho=0", zero_A, "contact.c_nu=1e16"}},
      // Meshes: cells of aspect ratio 150, second order, a single quadrilateral, two triangles.
      {"aspect_150", "conductive", {"mesh.nx=2", "mesh.ny=100"}},
      {"aspect_150_quads", "conductive", {"mesh.nx=2", "mesh.ny=100", "mesh.cell=\"quadrilateral\""}},
      {"p2", "conductive", {"mesh.order=2"}},
      {"p2_c_nu_1e16", "conductive", {"mesh.order=2", "contact.c_nu=1e16"}},
      {"single_quad", "conductive", {"mesh.nx=1", "mesh.ny=1", "mesh.cell=\"quadrilateral\""}},
      {"single_quad_p2", "conductive", {"mesh.nx=1", "mesh.ny=1", "mesh.cell=\"quadrilateral\"", "mesh.order=2"}},
      {"two_triangles", "conductive", {"mesh.nx=1", "mesh.ny=1"}},
      {"two_triangles_insulated", "insulated", {"mesh.nx=1", "mesh.ny=1"}},
  };
}

}  // namespace pc::testing
