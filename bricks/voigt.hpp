#pragma once
// Material tensors in Voigt form. Order: 2D (plane strain) xx, yy, xy; 3D xx, yy, zz, yz, xz, xy; shear
// strains are engineering strains (gamma = 2 eps), so that sigma : eps = sigma_v . eps_v.
//   elasticity / viscosity C: n x n (n = 3 or 6), symmetric positive definite;
//   piezoelectric E: dim x n, rows are field directions (D = E eps + beta E_field);
//   permittivity beta: dim x dim, symmetric positive definite.
#include <string>

#include <Eigen/Core>

namespace pc {

int voigt_size(int dim);

// Strain-displacement rows of one shape function with physical gradient g (dim values): the n x dim
// matrix B_i with eps_v = sum_i B_i u_i.
void strain_displacement(int dim, const double* g, double* B_rowmajor);
// Voigt strain of a displacement gradient grad[c * dim + d] = d u_c / d x_d (n values).
void strain_from_gradient(int dim, const double* grad, double* eps);

// Isotropic stiffness from Lame constants, and from Young's modulus and Poisson's ratio (in 2D the
// plane-strain reduction of the 3D tensor).
Eigen::MatrixXd isotropic_stiffness(int dim, double lambda, double mu);
Eigen::MatrixXd isotropic_stiffness_from_young(int dim, double young, double poisson);
Eigen::MatrixXd isotropic_permittivity(int dim, double beta);

// Rotations of 3D Voigt tensors by a proper rotation R (3 x 3, columns = new axes in old coordinates),
// e.g. to pole a material along another axis: C' = T C T^T, E' = R E T^T, beta' = R beta R^T with T the
// stress (Bond) transformation.
Eigen::MatrixXd rotate_stiffness(const Eigen::MatrixXd& C, const Eigen::Matrix3d& R);
Eigen::MatrixXd rotate_piezoelectric(const Eigen::MatrixXd& E, const Eigen::Matrix3d& R);
Eigen::MatrixXd rotate_permittivity(const Eigen::MatrixXd& beta, const Eigen::Matrix3d& R);

// The dimension (2 or 3) a tensor is written for, read from its size, so that a brick learns the mesh
// dimension from its data; throws naming the datum when the size fits neither.
int stiffness_dimension(const std::string& name, const Eigen::MatrixXd& C);
int piezoelectric_dimension(const std::string& name, const Eigen::MatrixXd& E);
int permittivity_dimension(const std::string& name, const Eigen::MatrixXd& beta);

// Validation with messages that name the datum: shape, finiteness, symmetry, positive definiteness.
void check_stiffness(const std::string& name, const Eigen::MatrixXd& C, int dim, bool allow_zero = false);
void check_piezoelectric(const std::string& name, const Eigen::MatrixXd& E, int dim);
void check_permittivity(const std::string& name, const Eigen::MatrixXd& beta, int dim, bool allow_zero = false);

}  // namespace pc
