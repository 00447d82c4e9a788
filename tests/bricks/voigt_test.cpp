// Voigt material tensors: the isotropic helpers against Lame's law, the strain operators against each
// other, the 3D rotations against the tensor rotation written with full indices, and the validation
// messages.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "assembly/error.hpp"
#include "bricks/voigt.hpp"
#include "support/test_helpers.hpp"

namespace pc {
namespace {

// Voigt position of the tensor entry (i, j), in the order of voigt.hpp.
int voigt_index(int dim, int i, int j) {
  if (i == j) return i;
  return dim == 2 ? 2 : 6 - (i + j);  // yz -> 3, xz -> 4, xy -> 5
}

Eigen::Matrix3d random_symmetric(int dim, std::mt19937& rng) {
  std::uniform_real_distribution<double> uniform(-1, 1);
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j <= i; ++j) m(i, j) = m(j, i) = uniform(rng);
  return m;
}

// Engineering-shear Voigt vector of a symmetric strain tensor, and the tensor of a Voigt stress vector.
Eigen::VectorXd strain_to_voigt(int dim, const Eigen::Matrix3d& eps) {
  Eigen::VectorXd v(voigt_size(dim));
  for (int i = 0; i < dim; ++i)
    for (int j = i; j < dim; ++j) v[voigt_index(dim, i, j)] = i == j ? eps(i, j) : 2 * eps(i, j);
  return v;
}

Eigen::Matrix3d stress_to_tensor(int dim, const Eigen::VectorXd& s) {
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) m(i, j) = s[voigt_index(dim, i, j)];
  return m;
}

// An orthotropic, transversely coupled 3D stiffness (symmetric positive definite, no symmetry under 90
// degree rotations).
Eigen::MatrixXd orthotropic_stiffness() {
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(6, 6);
  C.topLeftCorner(3, 3) << 12.0, 4.0, 3.0, 4.0, 9.0, 2.5, 3.0, 2.5, 7.0;
  C(3, 3) = 2.0;
  C(4, 4) = 3.0;
  C(5, 5) = 4.0;
  C(0, 5) = C(5, 0) = 0.7;
  return C;
}

Eigen::Matrix3d rotation(double angle, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

using testing::error_of;

TEST(Voigt, IsotropicStiffnessIsLameLaw) {
  std::mt19937 rng(3);
  const double lambda = 1.7, mu = 0.6;
  for (int dim : {2, 3}) {
    const Eigen::MatrixXd C = isotropic_stiffness(dim, lambda, mu);
    for (int sample = 0; sample < 5; ++sample) {
      const Eigen::Matrix3d eps = random_symmetric(dim, rng);
      const Eigen::Matrix3d got = stress_to_tensor(dim, C * strain_to_voigt(dim, eps));
      Eigen::Matrix3d want = 2 * mu * eps;
      for (int d = 0; d < dim; ++d) want(d, d) += lambda * eps.trace();
      EXPECT_LT((got - want).cwiseAbs().maxCoeff(), 1e-14) << dim << "D";
    }
  }
}

TEST(Voigt, YoungAndPoissonGiveTheLameConstants) {
  // E = 2.5, nu = 0.25: lambda = E nu / ((1 + nu)(1 - 2 nu)) = 1, mu = E / (2 (1 + nu)) = 1.
  for (int dim : {2, 3})
    EXPECT_LT((isotropic_stiffness_from_young(dim, 2.5, 0.25) - isotropic_stiffness(dim, 1.0, 1.0)).norm(), 1e-14);
  EXPECT_CONTAINS(error_of([] { isotropic_stiffness_from_young(2, 1.0, 0.5); }), "Poisson");
  EXPECT_CONTAINS(error_of([] { isotropic_stiffness(4, 1.0, 1.0); }), "dimension 2 or 3");
  EXPECT_EQ(isotropic_permittivity(3, 2.0), 2.0 * Eigen::MatrixXd::Identity(3, 3));
}

TEST(Voigt, StrainDisplacementMatchesStrainOfTheGradient) {
  // u = sum_i N_i u_i has grad u = sum_i u_i g_i^T, so sum_i B_i u_i must be the strain of that gradient.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (int dim : {2, 3}) {
    const int n = voigt_size(dim);
    Eigen::VectorXd eps_b = Eigen::VectorXd::Zero(n);
    Eigen::MatrixXd grad = Eigen::MatrixXd::Zero(dim, dim);  // grad(c, d) = d u_c / d x_d
    for (int shape = 0; shape < 4; ++shape) {
      Eigen::VectorXd g(dim), u(dim);
      for (int d = 0; d < dim; ++d) g[d] = uniform(rng), u[d] = uniform(rng);
      Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> B(n, dim);
      strain_displacement(dim, g.data(), B.data());
      eps_b += B * u;
      grad += u * g.transpose();
    }
    const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> grad_rows = grad;
    Eigen::VectorXd eps_g(n);
    strain_from_gradient(dim, grad_rows.data(), eps_g.data());
    EXPECT_LT((eps_b - eps_g).cwiseAbs().maxCoeff(), 1e-14);
    Eigen::Matrix3d sym = Eigen::Matrix3d::Zero();
    sym.topLeftCorner(dim, dim) = 0.5 * (grad + grad.transpose());
    EXPECT_LT((eps_g - strain_to_voigt(dim, sym)).cwiseAbs().maxCoeff(), 1e-14);
  }
}

TEST(Voigt, QuarterTurnAboutZSwapsTheXAndYEntries) {
  const Eigen::MatrixXd C = orthotropic_stiffness();
  const Eigen::MatrixXd Cr = rotate_stiffness(C, rotation(M_PI / 2, Eigen::Vector3d::UnitZ()));
  EXPECT_NEAR(Cr(0, 0), C(1, 1), 1e-12);
  EXPECT_NEAR(Cr(1, 1), C(0, 0), 1e-12);
  EXPECT_NEAR(Cr(0, 2), C(1, 2), 1e-12);
  EXPECT_NEAR(Cr(1, 2), C(0, 2), 1e-12);
  EXPECT_NEAR(Cr(2, 2), C(2, 2), 1e-12);
  EXPECT_NEAR(Cr(3, 3), C(4, 4), 1e-12);  // yz <-> xz
  EXPECT_NEAR(Cr(4, 4), C(3, 3), 1e-12);
  EXPECT_NEAR(Cr(5, 5), C(5, 5), 1e-12);
  // x -> y, y -> -x: the xy shear changes sign relative to the y normal stress.
  EXPECT_NEAR(Cr(1, 5), -C(0, 5), 1e-12);
}

TEST(Voigt, IdentityRotationChangesNothing) {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const Eigen::MatrixXd C = orthotropic_stiffness();
  Eigen::MatrixXd E(3, 6);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 6; ++c) E(r, c) = std::sin(1.0 + 7 * r + c);
  const Eigen::MatrixXd beta = Eigen::Vector3d(1, 2, 3).asDiagonal();
  EXPECT_EQ(rotate_stiffness(C, I), C);
  EXPECT_EQ(rotate_piezoelectric(E, I), E);
  EXPECT_EQ(rotate_permittivity(beta, I), beta);
}

// The rotations written with full tensor indices, C'_ijkl = R_ip R_jq R_kr R_ls C_pqrs and
// E'_i,kl = R_ip R_kq R_lr E_p,qr, where C_pqrs = C[voigt(p, q)][voigt(r, s)] and E_p,qr = E[p][voigt(q, r)]
// (stress rows are plain components, engineering strain columns count eps_qr and eps_rq together).
TEST(Voigt, RotationsAgreeWithTheFullIndexTensorRotation) {
  const Eigen::Matrix3d R = rotation(0.83, Eigen::Vector3d(1, -2, 0.5));
  const Eigen::MatrixXd C = orthotropic_stiffness();
  Eigen::MatrixXd E(3, 6);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 6; ++c) E(r, c) = std::sin(1.0 + 7 * r + c);
  const Eigen::MatrixXd Cr = rotate_stiffness(C, R), Er = rotate_piezoelectric(E, R);
  auto v = [](int i, int j) { return voigt_index(3, i, j); };
  double worst = 0;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l) {
        double e = 0;
        for (int p = 0; p < 3; ++p)
          for (int q = 0; q < 3; ++q)
            for (int r = 0; r < 3; ++r) e += R(i, p) * R(k, q) * R(l, r) * E(p, v(q, r));
        worst = std::max(worst, std::abs(e - Er(i, v(k, l))));
        for (int j = 0; j < 3; ++j) {
          double c = 0;
          for (int p = 0; p < 3; ++p)
            for (int q = 0; q < 3; ++q)
              for (int r = 0; r < 3; ++r)
                for (int s = 0; s < 3; ++s) c += R(i, p) * R(j, q) * R(k, r) * R(l, s) * C(v(p, q), v(r, s));
          worst = std::max(worst, std::abs(c - Cr(v(i, j), v(k, l))));
        }
      }
  EXPECT_LT(worst, 1e-12);
}

TEST(Voigt, RotatedTensorsActOnRotatedFields) {
  // sigma' = C' eps' must be R sigma R^T for eps' = R eps R^T, and D' = E' eps' must be R D.
  std::mt19937 rng(11);
  const Eigen::Matrix3d R = rotation(-1.1, Eigen::Vector3d(0.3, 0.4, 1.0));
  const Eigen::MatrixXd C = orthotropic_stiffness();
  Eigen::MatrixXd E(3, 6);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 6; ++c) E(r, c) = std::cos(2.0 + 5 * r - c);
  for (int sample = 0; sample < 5; ++sample) {
    const Eigen::Matrix3d eps = random_symmetric(3, rng);
    const Eigen::Matrix3d eps_r = R * eps * R.transpose();
    const Eigen::Matrix3d sigma = stress_to_tensor(3, C * strain_to_voigt(3, eps));
    const Eigen::Matrix3d sigma_r = stress_to_tensor(3, rotate_stiffness(C, R) * strain_to_voigt(3, eps_r));
    EXPECT_LT((sigma_r - R * sigma * R.transpose()).cwiseAbs().maxCoeff(), 1e-12);
    const Eigen::VectorXd D = E * strain_to_voigt(3, eps);
    const Eigen::VectorXd D_r = rotate_piezoelectric(E, R) * strain_to_voigt(3, eps_r);
    EXPECT_LT((D_r - R * D).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(Voigt, RotationPreservesEigenvalues) {
  // Voigt matrices are not tensors in an orthonormal basis; the Mandel form (shear rows and columns
  // scaled by sqrt 2) is, and its eigenvalues are the rotation invariants.
  const Eigen::Matrix3d R = rotation(2.3, Eigen::Vector3d(-1, 0.2, 0.7));
  Eigen::VectorXd w(6);
  w << 1, 1, 1, std::sqrt(2.0), std::sqrt(2.0), std::sqrt(2.0);
  auto mandel_eigenvalues = [&](const Eigen::MatrixXd& C) {
    const Eigen::MatrixXd M = w.asDiagonal() * C * w.asDiagonal();
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(M).eigenvalues();
  };
  const Eigen::MatrixXd C = orthotropic_stiffness();
  EXPECT_LT((mandel_eigenvalues(rotate_stiffness(C, R)) - mandel_eigenvalues(C)).cwiseAbs().maxCoeff(), 1e-11);
  Eigen::Matrix3d beta;
  beta << 3, 0.5, 0.1, 0.5, 2, 0.3, 0.1, 0.3, 1;
  const Eigen::MatrixXd beta_r = rotate_permittivity(beta, R);
  EXPECT_LT((Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(beta_r).eigenvalues() -
             Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(beta)).eigenvalues())
                .cwiseAbs()
                .maxCoeff(),
            1e-13);
  // Isotropic tensors do not change at all.
  const Eigen::MatrixXd iso = isotropic_stiffness(3, 1.3, 0.4);
  EXPECT_LT((rotate_stiffness(iso, R) - iso).cwiseAbs().maxCoeff(), 1e-13);
}

TEST(Voigt, RotationsRejectNonRotationsAndWrongSizes) {
  EXPECT_CONTAINS(error_of([] { rotate_stiffness(orthotropic_stiffness(), 2 * Eigen::Matrix3d::Identity()); }),
                  "not orthogonal");
  EXPECT_CONTAINS(
      error_of([] { rotate_permittivity(Eigen::MatrixXd::Identity(3, 3), Eigen::Vector3d(1, 1, -1).asDiagonal()); }),
      "reflection");
  EXPECT_CONTAINS(error_of([] { rotate_stiffness(isotropic_stiffness(2, 1, 1), Eigen::Matrix3d::Identity()); }),
                  "3D tensors");
}

TEST(Voigt, DimensionIsReadFromTheSize) {
  EXPECT_EQ(stiffness_dimension("B", Eigen::MatrixXd::Zero(3, 3)), 2);
  EXPECT_EQ(stiffness_dimension("B", Eigen::MatrixXd::Zero(6, 6)), 3);
  EXPECT_EQ(piezoelectric_dimension("E", Eigen::MatrixXd::Zero(2, 3)), 2);
  EXPECT_EQ(piezoelectric_dimension("E", Eigen::MatrixXd::Zero(3, 6)), 3);
  EXPECT_EQ(permittivity_dimension("beta", Eigen::MatrixXd::Zero(2, 2)), 2);
  EXPECT_EQ(permittivity_dimension("beta", Eigen::MatrixXd::Zero(3, 3)), 3);
  EXPECT_EQ(error_of([] { stiffness_dimension("B", Eigen::MatrixXd::Zero(4, 4)); }),
            "datum 'B' must be 3 x 3 (2D) or 6 x 6 (3D), got 4 x 4");
  EXPECT_CONTAINS(error_of([] { piezoelectric_dimension("E", Eigen::MatrixXd::Zero(3, 2)); }), "datum 'E'");
}

TEST(Voigt, ChecksNameTheDatumAndTheProblem) {
  const Eigen::MatrixXd C2 = isotropic_stiffness(2, 1.0, 0.5);
  EXPECT_EQ(error_of([&] { check_stiffness("B", C2, 2); }), "(no error)");
  EXPECT_EQ(error_of([] { check_stiffness("B", Eigen::MatrixXd::Identity(2, 2), 2); }),
            "datum 'B' must be 3 x 3 in 2D, got 2 x 2");
  EXPECT_EQ(error_of([&] { check_stiffness("B", C2, 3); }), "datum 'B' must be 6 x 6 in 3D, got 3 x 3");

  Eigen::MatrixXd nan = C2;
  nan(1, 2) = std::numeric_limits<double>::quiet_NaN();
  const std::string nan_error = error_of([&] { check_stiffness("A", nan, 2); });
  EXPECT_CONTAINS(nan_error, "datum 'A'");
  EXPECT_CONTAINS(nan_error, "non-finite");
  EXPECT_CONTAINS(nan_error, "(1, 2)");

  Eigen::MatrixXd skew = C2;
  skew(0, 1) += 1e-3;
  const std::string skew_error = error_of([&] { check_stiffness("B", skew, 2); });
  EXPECT_CONTAINS(skew_error, "datum 'B' is not symmetric");
  Eigen::MatrixXd almost = C2;
  almost(0, 1) += 1e-12;  // within the relative tolerance
  EXPECT_EQ(error_of([&] { check_stiffness("B", almost, 2); }), "(no error)");

  const Eigen::MatrixXd indefinite = isotropic_stiffness(2, 1.0, -0.5);
  EXPECT_CONTAINS(error_of([&] { check_stiffness("B", indefinite, 2); }), "datum 'B' is not positive definite");

  const Eigen::MatrixXd zero = Eigen::MatrixXd::Zero(6, 6);
  EXPECT_EQ(error_of([&] { check_stiffness("A", zero, 3, /*allow_zero=*/true); }), "(no error)");
  EXPECT_CONTAINS(error_of([&] { check_stiffness("A", zero, 3); }), "datum 'A' is not positive definite");
  Eigen::MatrixXd semi = zero;
  semi(0, 0) = 1;  // semi-definite but not zero: refused even with allow_zero
  EXPECT_CONTAINS(error_of([&] { check_stiffness("A", semi, 3, true); }), "datum 'A' is not positive definite");

  EXPECT_EQ(error_of([] { check_piezoelectric("E", Eigen::MatrixXd::Zero(2, 3), 2); }), "(no error)");
  EXPECT_EQ(error_of([] { check_piezoelectric("E", Eigen::MatrixXd::Zero(3, 2), 2); }),
            "datum 'E' must be 2 x 3 in 2D, got 3 x 2");
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(3, 6);
  E(2, 4) = std::numeric_limits<double>::infinity();
  EXPECT_CONTAINS(error_of([&] { check_piezoelectric("E", E, 3); }), "(2, 4)");

  EXPECT_EQ(error_of([] { check_permittivity("beta", Eigen::MatrixXd::Identity(2, 2), 2); }), "(no error)");
  EXPECT_EQ(error_of([] { check_permittivity("beta", Eigen::MatrixXd::Identity(3, 3), 2); }),
            "datum 'beta' must be 2 x 2 in 2D, got 3 x 3");
  Eigen::MatrixXd beta(2, 2);
  beta << 1, 2, 2, 1;  // eigenvalues 3 and -1
  EXPECT_CONTAINS(error_of([&] { check_permittivity("beta", beta, 2); }), "datum 'beta' is not positive definite");
}

}  // namespace
}  // namespace pc
