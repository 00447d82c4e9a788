#include "bricks/piezo_materials.hpp"

#include <array>

#include "assembly/error.hpp"
#include "bricks/voigt.hpp"

namespace pc {
namespace {

// Voigt positions of xx, yy, xy among the 3D ones (xx, yy, zz, yz, xz, xy).
constexpr std::array<int, 3> kPlaneStrain = {0, 1, 5};

void require_size(const char* what, const Eigen::MatrixXd& M, int rows, int cols) {
  require(M.rows() == rows && M.cols() == cols, what, ": expects a 3D tensor (", rows, " x ", cols, "), got ", M.rows(),
          " x ", M.cols());
}

std::shared_ptr<const PiezoMaterialPreset> preset(const HexagonalConstants& k) {
  return std::make_shared<const PiezoMaterialPreset>(hexagonal_piezo_material(k));
}

}  // namespace

Axis axis_from_name(const std::string& name, const std::string& where) {
  if (name == "x") return Axis::x;
  if (name == "y") return Axis::y;
  if (name == "z") return Axis::z;
  fail(where, ": unknown axis '", name, "' (known: x, y, z)");
}

const char* axis_name(Axis axis) {
  switch (axis) {
    case Axis::x: return "x";
    case Axis::y: return "y";
    case Axis::z: return "z";
  }
  return "?";
}

Eigen::Matrix3d poling_rotation(Axis poling) {
  // Columns: the material axes x_m, y_m, z_m in model coordinates; z_m is the poling axis. Entries are
  // 0 and +-1, so the rotated constants are the tabulated ones, permuted, to the last bit.
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  if (poling == Axis::x) R << 0, 0, 1, 0, 1, 0, -1, 0, 0;  // x_m = -z, y_m = y, z_m = x
  if (poling == Axis::y) R << 1, 0, 0, 0, 0, 1, 0, -1, 0;  // x_m = x, y_m = -z, z_m = y
  return R;
}

Eigen::MatrixXd plane_strain_stiffness(const Eigen::MatrixXd& C) {
  require_size("plane_strain_stiffness", C, 6, 6);
  Eigen::MatrixXd out(3, 3);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out(r, c) = C(kPlaneStrain[r], kPlaneStrain[c]);
  return out;
}

Eigen::MatrixXd plane_strain_piezoelectric(const Eigen::MatrixXd& E) {
  require_size("plane_strain_piezoelectric", E, 3, 6);
  Eigen::MatrixXd out(2, 3);
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 3; ++c) out(r, c) = E(r, kPlaneStrain[c]);
  return out;
}

Eigen::MatrixXd plane_strain_permittivity(const Eigen::MatrixXd& beta) {
  require_size("plane_strain_permittivity", beta, 3, 3);
  return beta.topLeftCorner(2, 2);
}

PiezoTensors PiezoMaterialPreset::tensors(int dim, Axis poling) const {
  require(dim == 2 || dim == 3, "piezoelectric material preset: dimension must be 2 or 3, got ", dim);
  require(dim == 3 || poling != Axis::z,
          "piezoelectric material preset: a 2D (plane strain, x-y) model is poled "
          "in its plane (x or y), not along z");
  const Eigen::Matrix3d R = poling_rotation(poling);
  PiezoTensors t;
  t.rho = rho;
  t.B = rotate_stiffness(c, R);
  t.E = rotate_piezoelectric(e, R);
  t.beta = rotate_permittivity(eps, R);
  if (dim == 2) {
    t.B = plane_strain_stiffness(t.B);
    t.E = plane_strain_piezoelectric(t.E);
    t.beta = plane_strain_permittivity(t.beta);
  }
  return t;
}

PiezoMaterialPreset hexagonal_piezo_material(const HexagonalConstants& k) {
  PiezoMaterialPreset m;
  m.c = Eigen::MatrixXd::Zero(6, 6);
  m.c.topLeftCorner(3, 3) << k.c11, k.c12, k.c13, k.c12, k.c11, k.c13, k.c13, k.c13, k.c33;
  m.c(3, 3) = m.c(4, 4) = k.c44;  // yz, xz: shears across the poling axis
  m.c(5, 5) = k.c66;              // xy: shear in the isotropic plane
  m.e = Eigen::MatrixXd::Zero(3, 6);
  m.e(0, 4) = m.e(1, 3) = k.e15;  // D_x from gamma_xz, D_y from gamma_yz
  m.e(2, 0) = m.e(2, 1) = k.e31;
  m.e(2, 2) = k.e33;
  m.eps = Eigen::Vector3d(k.eps11, k.eps11, k.eps33).asDiagonal();
  m.rho = k.rho;
  check_stiffness("piezoelectric material preset c^E", m.c, 3);
  check_permittivity("piezoelectric material preset eps^S", m.eps, 3);
  require(k.rho > 0, "piezoelectric material preset: density must be > 0, got ", k.rho);
  return m;
}

PiezoMaterialRegistry& piezo_material_registry() {
  static PiezoMaterialRegistry registry("piezoelectric material", "material.preset");
  return registry;
}

const PiezoMaterialPreset& piezo_material(const std::string& name, const std::string& where) {
  return *piezo_material_registry().at(name, where).create;
}

std::vector<std::string> piezo_material_names() { return piezo_material_registry().names(); }

// The presets. They are registered in this file, next to the registry, so that they exist whenever the
// registry is used (a static library keeps a translation unit only when something in it is referenced).
//
// PZT-4, PZT-5A, PZT-5H: the Clevite (later Vernitron, Morgan Electro Ceramics) compositions measured by
// D. A. Berlincourt, D. R. Curran, H. Jaffe, "Piezoelectric and piezomagnetic materials and their function
// in transducers", Physical Acoustics vol. I-A (W. P. Mason, ed.), Academic Press 1964, tabulated in
// B. Jaffe, W. R. Cook, H. Jaffe, "Piezoelectric Ceramics", Academic Press 1971. The sources give the
// strain-charge form (s^E [1e-12 m^2/N]; d [1e-12 C/N]; eps^T / eps0):
//   PZT-4:  s11 12.3, s12 -4.05, s13 -5.31, s33 15.5, s44 39.0, s66 32.7; d31 -123, d33 289, d15 496;
//           eps11^T 1475, eps33^T 1300; rho 7500
//   PZT-5A: s11 16.4, s12 -5.74, s13 -7.22, s33 18.8, s44 47.5, s66 44.3; d31 -171, d33 374, d15 584;
//           eps11^T 1730, eps33^T 1700; rho 7750
//   PZT-5H: s11 16.5, s12 -4.78, s13 -8.45, s33 20.7, s44 43.5, s66 42.6; d31 -274, d33 593, d15 741;
//           eps11^T 3130, eps33^T 3400; rho 7500
// The stress-charge constants below are their conversion c^E = (s^E)^-1, e = d c^E, eps^S = eps^T - d e^T
// to six digits, the values of the widely used COMSOL Multiphysics material library (c66 = 1 / s66 with
// the tabulated s66, so c66 and (c11 - c12) / 2 differ in the fourth digit). The PZT-5H constants are
// those of scenes/paper2d.json (plane strain, poled along y) and scenes/box3d.json;
// tests/bricks/piezo_materials_test.cpp checks both, and the conversion of the data above.
// BaTiO3: poled polycrystalline barium titanate (not the single crystal of Berlincourt & Jaffe, Phys.
// Rev. 111 (1958) 143), as tabulated in Jaffe, Cook & Jaffe 1971 (stress-charge form, three digits:
// c^E 16.6 7.66 7.75 16.2 4.29 4.48 [1e10 Pa]; e31 -4.4, e33 18.6, e15 11.6 [C/m^2]; eps11^S 11.2e-9,
// eps33^S 12.6e-9 [F/m]; rho 5700 kg/m^3). Its strain-charge data (s^E 8.55 -2.61 -2.85 8.93 23.3
// [1e-12 m^2/N]; d31 -79, d33 191, d15 270 [1e-12 C/N]; eps11^T / eps0 1623, eps33^T / eps0 1900) convert
// to these to within their three digits.

namespace {

// Name, source, constants (c11 c12 c13 c33 c44 c66 [Pa]; e31 e33 e15 [C/m^2]; eps11^S eps33^S [F/m]; rho).
struct TabulatedPreset {
  const char* name;
  const char* source;
  HexagonalConstants constants;
};
const TabulatedPreset kPresets[] = {
    {"PZT-4",
     "PZT-4 (Berlincourt et al. 1964; Jaffe, Cook & Jaffe 1971), stress-charge form",
     {1.38999e11, 7.78366e10, 7.42836e10, 1.15412e11, 2.5641e10, 3.0581e10, -5.20279, 15.0804, 12.7179,
      762.5 * kVacuumPermittivity, 663.2 * kVacuumPermittivity, 7500}},
    {"PZT-5A",
     "PZT-5A (Berlincourt et al. 1964; Jaffe, Cook & Jaffe 1971), stress-charge form",
     {1.20346e11, 7.51791e10, 7.50901e10, 1.10867e11, 2.10526e10, 2.25734e10, -5.35116, 15.7835, 12.2947,
      919.1 * kVacuumPermittivity, 826.6 * kVacuumPermittivity, 7750}},
    {"PZT-5H",
     "PZT-5H (Berlincourt et al. 1964; Jaffe, Cook & Jaffe 1971), stress-charge form",
     {1.27205e11, 8.02122e10, 8.46702e10, 1.17436e11, 2.29885e10, 2.34742e10, -6.62281, 23.2403, 17.0345,
      1704.4 * kVacuumPermittivity, 1433.6 * kVacuumPermittivity, 7500}},
    {"BaTiO3",
     "poled BaTiO3 ceramic (Jaffe, Cook & Jaffe 1971), stress-charge form",
     {1.66e11, 7.66e10, 7.75e10, 1.62e11, 4.29e10, 4.48e10, -4.4, 18.6, 11.6, 11.2e-9, 12.6e-9, 5700}},
};

[[maybe_unused]] const bool kPresetsRegistered = [] {
  for (const TabulatedPreset& p : kPresets) piezo_material_registry().add({p.name, p.source, {}, preset(p.constants)});
  return true;
}();

}  // namespace
}  // namespace pc
