// Material presets: the registry's names, each preset's constants well posed, the rotations to another
// poling axis undone by the inverse rotation, the plane-strain reduction of PZT-5H poled along y equal to
// the tensors written in scenes/paper2d.json (and the 3D ones to scenes/box3d.json), and the stored
// stress-charge constants equal to the conversion of the sources' strain-charge data.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <Eigen/LU>

#include "assembly/error.hpp"
#include "bricks/piezo_materials.hpp"
#include "bricks/voigt.hpp"
#include "models/scene/json.hpp"
#include "support/test_helpers.hpp"

namespace pc {
namespace {

const char* const kPresets[] = {"BaTiO3", "PZT-4", "PZT-5A", "PZT-5H"};

using testing::error_of;

// The fewest significant digits (1..17) that write x back exactly, as a scene file gives it.
int digits_given(double x) {
  for (int k = 1; k < 17; ++k) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*g", k, x);
    if (std::strtod(text, nullptr) == x) return k;
  }
  return 17;
}

// `actual` agrees with `given` to the digits `given` is written with: it rounds to `given` (a tie counts).
void expect_agrees_to_the_digits_given(const Eigen::MatrixXd& actual, const Eigen::MatrixXd& given,
                                       const std::string& what) {
  ASSERT_EQ(actual.rows(), given.rows()) << what;
  ASSERT_EQ(actual.cols(), given.cols()) << what;
  for (int r = 0; r < given.rows(); ++r)
    for (int c = 0; c < given.cols(); ++c) {
      const double b = given(r, c), a = actual(r, c);
      if (b == 0) {
        EXPECT_EQ(a, 0.0) << what << " (" << r << ", " << c << ")";
        continue;
      }
      const double unit = std::pow(10.0, std::floor(std::log10(std::abs(b))) - (digits_given(b) - 1));
      EXPECT_LE(std::abs(a - b), 0.5 * unit * (1 + 1e-9))
          << what << " (" << r << ", " << c << "): preset " << a << ", scene " << b;
    }
}

TEST(PiezoMaterials, TheRegistryListsThePresetsAndRefusesAnUnknownNameNamingThem) {
  for (const char* name : kPresets) EXPECT_NO_THROW(piezo_material(name)) << name;
  const std::vector<std::string> names = piezo_material_names();
  for (const char* name : kPresets) EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  EXPECT_EQ(piezo_material_registry().key(), "material.preset");
  EXPECT_EQ(error_of([] { piezo_material("PZT-5X", "here"); }),
            "here: unknown piezoelectric material 'PZT-5X' (known: BaTiO3, PZT-4, PZT-5A, PZT-5H); did you mean "
            "'PZT-5A' or 'PZT-5H'?");
  for (const auto& entry : piezo_material_registry().entries()) EXPECT_FALSE(entry.doc.empty()) << entry.name;
}

TEST(PiezoMaterials, EachPresetHasSymmetricPositiveDefiniteStiffnessAndPermittivity) {
  for (const char* name : kPresets) {
    const PiezoMaterialPreset& m = piezo_material(name);
    EXPECT_NO_THROW(check_stiffness(name, m.c, 3)) << name;
    EXPECT_NO_THROW(check_permittivity(name, m.eps, 3)) << name;
    EXPECT_NO_THROW(check_piezoelectric(name, m.e, 3)) << name;
    EXPECT_EQ((m.c - m.c.transpose()).cwiseAbs().maxCoeff(), 0.0) << name;
    EXPECT_GT(m.rho, 1000.0) << name;
    // The coupled operator [[c, -e^T], [-e, -eps]] is a saddle point: c and eps positive definite, and so
    // is the stiffened c + e^T eps^-1 e (what the electric field adds under open circuit).
    const Eigen::MatrixXd stiffened = m.c + m.e.transpose() * m.eps.inverse() * m.e;
    EXPECT_NO_THROW(check_stiffness(name, 0.5 * (stiffened + stiffened.transpose()), 3)) << name;
    // The material's own symmetry: poled along z, e has e31 = e32, e15 = e24 and nothing else.
    EXPECT_EQ(m.e(2, 0), m.e(2, 1)) << name;
    EXPECT_EQ(m.e(0, 4), m.e(1, 3)) << name;
    EXPECT_LT(m.e(2, 0), 0.0) << name;
    EXPECT_GT(m.e(2, 2), 0.0) << name;
    EXPECT_GT(m.e(0, 4), 0.0) << name;
    const PiezoTensors z = m.tensors(3, Axis::z);
    EXPECT_EQ(z.B, m.c) << name;
    EXPECT_EQ(z.E, m.e) << name;
    EXPECT_EQ(z.beta, m.eps) << name;
  }
}

TEST(PiezoMaterials, RotatingToAnotherPolingAxisAndBackReturnsTheTabulatedConstants) {
  for (const char* name : kPresets) {
    const PiezoMaterialPreset& m = piezo_material(name);
    for (Axis axis : {Axis::x, Axis::y, Axis::z}) {
      const Eigen::Matrix3d R = poling_rotation(axis);
      EXPECT_NEAR((R.transpose() * R - Eigen::Matrix3d::Identity()).norm(), 0.0, 0.0);
      EXPECT_EQ(R.determinant(), 1.0);
      EXPECT_EQ(R.col(2), Eigen::Vector3d::Unit(static_cast<int>(axis))) << axis_name(axis);
      const PiezoTensors t = m.tensors(3, axis);
      // The rotation only permutes entries (and signs), so the way back is exact.
      EXPECT_EQ(rotate_stiffness(t.B, R.transpose()), m.c) << name << " " << axis_name(axis);
      EXPECT_EQ(rotate_piezoelectric(t.E, R.transpose()), m.e) << name << " " << axis_name(axis);
      EXPECT_EQ(rotate_permittivity(t.beta, R.transpose()), m.eps) << name << " " << axis_name(axis);
      // Poled along `axis`: c33 and e33, eps33 now sit on that axis.
      const int a = static_cast<int>(axis);
      EXPECT_EQ(t.B(a, a), m.c(2, 2));
      EXPECT_EQ(t.E(a, a), m.e(2, 2));
      EXPECT_EQ(t.beta(a, a), m.eps(2, 2));
      EXPECT_EQ(t.rho, m.rho);
    }
  }
}

TEST(PiezoMaterials, PlaneStrainKeepsTheInPlaneRowsAndColumnsAndRefusesPolingOutOfPlane) {
  const PiezoMaterialPreset& m = piezo_material("PZT-4");
  const PiezoTensors y = m.tensors(2, Axis::y);
  Eigen::MatrixXd B(3, 3), E(2, 3), beta(2, 2);
  B << m.c(0, 0), m.c(0, 2), 0, m.c(0, 2), m.c(2, 2), 0, 0, 0, m.c(3, 3);
  E << 0, 0, m.e(0, 4), m.e(2, 0), m.e(2, 2), 0;
  beta << m.eps(0, 0), 0, 0, m.eps(2, 2);
  EXPECT_EQ(y.B, B);
  EXPECT_EQ(y.E, E);
  EXPECT_EQ(y.beta, beta);
  // Poled along x: the same with x and y exchanged.
  const PiezoTensors x = m.tensors(2, Axis::x);
  B << m.c(2, 2), m.c(0, 2), 0, m.c(0, 2), m.c(0, 0), 0, 0, 0, m.c(3, 3);
  E << m.e(2, 2), m.e(2, 0), 0, 0, 0, m.e(0, 4);
  beta << m.eps(2, 2), 0, 0, m.eps(0, 0);
  EXPECT_EQ(x.B, B);
  EXPECT_EQ(x.E, E);
  EXPECT_EQ(x.beta, beta);
  EXPECT_EQ(
      error_of([&] { m.tensors(2, Axis::z); }),
      "piezoelectric material preset: a 2D (plane strain, x-y) model is poled in its plane (x or y), not along z");
  EXPECT_EQ(error_of([&] { plane_strain_stiffness(y.B); }),
            "plane_strain_stiffness: expects a 3D tensor (6 x 6), got 3 x 3");
  EXPECT_EQ(error_of([] { axis_from_name("w", "scene: 'material.poling'"); }),
            "scene: 'material.poling': unknown axis 'w' (known: x, y, z)");
}

// The acceptance check of the presets: the paper scene's hand-written 2D tensors are PZT-5H poled
// along y, reduced to plane strain, to every digit they are written with; likewise the 3D box's.
TEST(PiezoMaterials, Pzt5hPoledAlongYReproducesThePaperScenesTensors) {
  const PiezoMaterialPreset& m = piezo_material("PZT-5H");
  for (const char* file : {"paper2d.json", "box3d.json"}) {
    const Json material = read_json_file(std::string(PIEZOCONTACT_SCENES) + "/" + file).at("material");
    const int dim = file[0] == 'p' ? 2 : 3;
    const PiezoTensors t = m.tensors(dim, Axis::y);
    expect_agrees_to_the_digits_given(t.B, material.at("elasticity_B").as_matrix(), std::string(file) + " B");
    expect_agrees_to_the_digits_given(t.E, material.at("piezo_E").as_matrix(), std::string(file) + " E");
    expect_agrees_to_the_digits_given(t.beta, material.at("permittivity_beta").as_matrix(),
                                      std::string(file) + " beta");
  }
  // The 2D values are the six-digit constants themselves, not merely close to them.
  const PiezoTensors t = m.tensors(2, Axis::y);
  EXPECT_EQ(t.B(0, 0), 127205000000.0);
  EXPECT_EQ(t.B(0, 1), 84670200000.0);
  EXPECT_EQ(t.B(1, 1), 117436000000.0);
  EXPECT_EQ(t.B(2, 2), 22988500000.0);
  EXPECT_EQ(t.E(1, 0), -6.62281);
  EXPECT_EQ(t.E(1, 1), 23.2403);
  EXPECT_EQ(t.E(0, 2), 17.0345);
}

// The sources give the strain-charge form; the presets hold its conversion. s [1e-12 m^2/N], d [1e-12
// C/N], eps^T relative, as listed in bricks/piezo_materials.cpp.
struct StrainCharge {
  const char* name;
  double s11, s12, s13, s33, s44, s66, d31, d33, d15, eps11_T, eps33_T;
  double tolerance;  // relative, per entry: the precision the conversion is tabulated with
};

TEST(PiezoMaterials, TheStressChargeConstantsAreTheConversionOfTheSourcesStrainChargeData) {
  const StrainCharge data[] = {
      {"PZT-4", 12.3, -4.05, -5.31, 15.5, 39.0, 32.7, -123, 289, 496, 1475, 1300, 1e-4},
      {"PZT-5A", 16.4, -5.74, -7.22, 18.8, 47.5, 44.3, -171, 374, 584, 1730, 1700, 1e-4},
      {"PZT-5H", 16.5, -4.78, -8.45, 20.7, 43.5, 42.6, -274, 593, 741, 3130, 3400, 1e-4},
      // Three-digit tables on both sides.
      {"BaTiO3", 8.55, -2.61, -2.85, 8.93, 23.3, 2 * (8.55 + 2.61), -79, 191, 270, 1623, 1900, 1e-2},
  };
  for (const StrainCharge& k : data) {
    Eigen::MatrixXd s = Eigen::MatrixXd::Zero(6, 6);
    s.topLeftCorner(3, 3) << k.s11, k.s12, k.s13, k.s12, k.s11, k.s13, k.s13, k.s13, k.s33;
    s(3, 3) = s(4, 4) = k.s44;
    s(5, 5) = k.s66;
    Eigen::MatrixXd d = Eigen::MatrixXd::Zero(3, 6);
    d(0, 4) = d(1, 3) = k.d15;
    d(2, 0) = d(2, 1) = k.d31;
    d(2, 2) = k.d33;
    const Eigen::MatrixXd c = (1e-12 * s).inverse();
    const Eigen::MatrixXd e = 1e-12 * d * c;
    const Eigen::MatrixXd eps_T = (kVacuumPermittivity * Eigen::Vector3d(k.eps11_T, k.eps11_T, k.eps33_T)).asDiagonal();
    const Eigen::MatrixXd eps = eps_T - 1e-12 * d * e.transpose();
    const PiezoMaterialPreset& m = piezo_material(k.name);
    const auto expect_close = [&](const Eigen::MatrixXd& stored, const Eigen::MatrixXd& converted, const char* what) {
      for (int r = 0; r < stored.rows(); ++r)
        for (int col = 0; col < stored.cols(); ++col) {
          if (stored(r, col) == 0) {
            EXPECT_NEAR(converted(r, col), 0.0, 1e-9 * converted.cwiseAbs().maxCoeff()) << k.name << " " << what;
            continue;
          }
          EXPECT_NEAR(converted(r, col) / stored(r, col), 1.0, k.tolerance)
              << k.name << " " << what << " (" << r << ", " << col << "): stored " << stored(r, col) << ", converted "
              << converted(r, col);
        }
    };
    expect_close(m.c, c, "c^E");
    expect_close(m.e, e, "e");
    expect_close(m.eps, eps, "eps^S");
  }
}

}  // namespace
}  // namespace pc
