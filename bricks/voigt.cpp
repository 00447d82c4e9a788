#include "bricks/voigt.hpp"

#include <array>
#include <cmath>
#include <utility>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "assembly/error.hpp"

namespace pc {
namespace {

// Tensor index pairs (i, j) of the Voigt entries, in the order of voigt.hpp.
constexpr std::array<std::pair<int, int>, 3> kPairs2d = {{{0, 0}, {1, 1}, {0, 1}}};
constexpr std::array<std::pair<int, int>, 6> kPairs3d = {{{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}}};

void require_dimension(int dim) {
  require(dim == 2 || dim == 3, "Voigt notation is defined for dimension 2 or 3, got ", dim);
}

void check_shape(const std::string& name, const Eigen::MatrixXd& M, int rows, int cols, int dim) {
  require(M.rows() == rows && M.cols() == cols, "datum '", name, "' must be ", rows, " x ", cols, " in ", dim,
          "D, got ", M.rows(), " x ", M.cols());
}

void check_finite(const std::string& name, const Eigen::MatrixXd& M) {
  for (int r = 0; r < M.rows(); ++r)
    for (int c = 0; c < M.cols(); ++c)
      require(std::isfinite(M(r, c)), "datum '", name, "' has a non-finite entry ", M(r, c), " at (", r, ", ", c,
              ") (0-based)");
}

// Symmetric (relative to the largest entry) and positive definite; the zero matrix passes if allowed.
void check_symmetric_positive(const std::string& name, const Eigen::MatrixXd& M, bool allow_zero) {
  const double largest = M.cwiseAbs().maxCoeff();
  if (allow_zero && largest == 0) return;
  for (int r = 0; r < M.rows(); ++r)
    for (int c = 0; c < r; ++c)
      require(std::abs(M(r, c) - M(c, r)) <= 1e-10 * largest, "datum '", name, "' is not symmetric: entry (", r, ", ",
              c, ") = ", M(r, c), " but (", c, ", ", r, ") = ", M(c, r));
  const double smallest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(M, Eigen::EigenvaluesOnly).eigenvalues()(0);
  const bool factorizes = Eigen::LLT<Eigen::MatrixXd>(M).info() == Eigen::Success;
  require(factorizes && smallest > 0, "datum '", name, "' is not positive definite (smallest eigenvalue ", smallest,
          ")", allow_zero ? "; only the zero matrix may be semi-definite" : "");
}

// Dimension whose expected size (rows x cols) the tensor has.
int dimension_from_size(const std::string& name, const Eigen::MatrixXd& M, std::array<int, 2> rows_2d3d,
                        std::array<int, 2> cols_2d3d) {
  for (int k = 0; k < 2; ++k)
    if (M.rows() == rows_2d3d[k] && M.cols() == cols_2d3d[k]) return k + 2;
  fail("datum '", name, "' must be ", rows_2d3d[0], " x ", cols_2d3d[0], " (2D) or ", rows_2d3d[1], " x ", cols_2d3d[1],
       " (3D), got ", M.rows(), " x ", M.cols());
}

// Rows: sigma' = R sigma R^T in Voigt form (engineering shear strains make the strain rule T^-T).
Eigen::Matrix<double, 6, 6> stress_transformation(const Eigen::Matrix3d& R) {
  Eigen::Matrix<double, 6, 6> T;
  for (int I = 0; I < 6; ++I) {
    const auto [i, j] = kPairs3d[I];
    for (int K = 0; K < 6; ++K) {
      const auto [k, l] = kPairs3d[K];
      T(I, K) = k == l ? R(i, k) * R(j, k) : R(i, k) * R(j, l) + R(i, l) * R(j, k);
    }
  }
  return T;
}

void check_rotation(const Eigen::Matrix3d& R) {
  require(R.allFinite(), "rotation R has a non-finite entry");
  const double orthogonality = (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  require(orthogonality <= 1e-10, "rotation R is not orthogonal (|R^T R - I| = ", orthogonality, ")");
  require(R.determinant() > 0, "rotation R is a reflection (det R = ", R.determinant(), "), not a rotation");
}

void check_3d(const char* what, const Eigen::MatrixXd& M, int rows, int cols) {
  require(M.rows() == rows && M.cols() == cols, "rotate_", what, ": rotations are for 3D tensors (", rows, " x ", cols,
          "), got ", M.rows(), " x ", M.cols());
}

}  // namespace

int voigt_size(int dim) {
  require_dimension(dim);
  return dim == 2 ? 3 : 6;
}

void strain_displacement(int dim, const double* g, double* B) {
  const int n = voigt_size(dim);
  for (int a = 0; a < n * dim; ++a) B[a] = 0;
  // Row I = (i, j) of B holds d eps_ij / d u_c: g_j for c = i, plus g_i for c = j when i != j (engineering).
  for (int I = 0; I < n; ++I) {
    const auto [i, j] = dim == 2 ? kPairs2d[I] : kPairs3d[I];
    B[I * dim + i] += g[j];
    if (i != j) B[I * dim + j] += g[i];
  }
}

void strain_from_gradient(int dim, const double* grad, double* eps) {
  const int n = voigt_size(dim);
  for (int I = 0; I < n; ++I) {
    const auto [i, j] = dim == 2 ? kPairs2d[I] : kPairs3d[I];
    eps[I] = i == j ? grad[i * dim + i] : grad[i * dim + j] + grad[j * dim + i];
  }
}

Eigen::MatrixXd isotropic_stiffness(int dim, double lambda, double mu) {
  require(std::isfinite(lambda) && std::isfinite(mu), "isotropic_stiffness: lambda (", lambda, ") and mu (", mu,
          ") must be finite");
  const int n = voigt_size(dim);
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(n, n);
  for (int a = 0; a < dim; ++a) {
    for (int b = 0; b < dim; ++b) C(a, b) = lambda;
    C(a, a) += 2 * mu;
  }
  for (int s = dim; s < n; ++s) C(s, s) = mu;  // engineering shear: sigma_ij = mu gamma_ij
  return C;
}

Eigen::MatrixXd isotropic_stiffness_from_young(int dim, double young, double poisson) {
  require(std::isfinite(young) && young >= 0, "isotropic_stiffness_from_young: Young's modulus must be >= 0, got ",
          young);
  require(poisson > -1 && poisson < 0.5, "isotropic_stiffness_from_young: Poisson's ratio must lie in (-1, 0.5), got ",
          poisson);
  // Plane strain keeps the 3D Lame constants, so the same formulas serve both dimensions.
  const double lambda = young * poisson / ((1 + poisson) * (1 - 2 * poisson));
  const double mu = young / (2 * (1 + poisson));
  return isotropic_stiffness(dim, lambda, mu);
}

Eigen::MatrixXd isotropic_permittivity(int dim, double beta) {
  require(std::isfinite(beta), "isotropic_permittivity: beta must be finite, got ", beta);
  require_dimension(dim);
  return beta * Eigen::MatrixXd::Identity(dim, dim);
}

Eigen::MatrixXd rotate_stiffness(const Eigen::MatrixXd& C, const Eigen::Matrix3d& R) {
  check_3d("stiffness", C, 6, 6);
  check_rotation(R);
  const Eigen::Matrix<double, 6, 6> T = stress_transformation(R);
  return T * C * T.transpose();
}

Eigen::MatrixXd rotate_piezoelectric(const Eigen::MatrixXd& E, const Eigen::Matrix3d& R) {
  check_3d("piezoelectric", E, 3, 6);
  check_rotation(R);
  return R * E * stress_transformation(R).transpose();
}

Eigen::MatrixXd rotate_permittivity(const Eigen::MatrixXd& beta, const Eigen::Matrix3d& R) {
  check_3d("permittivity", beta, 3, 3);
  check_rotation(R);
  return R * beta * R.transpose();
}

int stiffness_dimension(const std::string& name, const Eigen::MatrixXd& C) {
  return dimension_from_size(name, C, {3, 6}, {3, 6});
}

int piezoelectric_dimension(const std::string& name, const Eigen::MatrixXd& E) {
  return dimension_from_size(name, E, {2, 3}, {3, 6});
}

int permittivity_dimension(const std::string& name, const Eigen::MatrixXd& beta) {
  return dimension_from_size(name, beta, {2, 3}, {2, 3});
}

void check_stiffness(const std::string& name, const Eigen::MatrixXd& C, int dim, bool allow_zero) {
  const int n = voigt_size(dim);
  check_shape(name, C, n, n, dim);
  check_finite(name, C);
  check_symmetric_positive(name, C, allow_zero);
}

void check_piezoelectric(const std::string& name, const Eigen::MatrixXd& E, int dim) {
  check_shape(name, E, dim, voigt_size(dim), dim);
  check_finite(name, E);
}

void check_permittivity(const std::string& name, const Eigen::MatrixXd& beta, int dim, bool allow_zero) {
  require_dimension(dim);
  check_shape(name, beta, dim, dim, dim);
  check_finite(name, beta);
  check_symmetric_positive(name, beta, allow_zero);
}

}  // namespace pc
