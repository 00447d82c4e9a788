#pragma once
// The differential operators of the hand-written linear terms at one quadrature point, as dense matrices
// over an element's local coefficients (ordered i * num_components + c, as in ElementData):
//   strain:   n x (dim * shapes), eps_v = B x_e (Voigt, engineering shear, n = 3 or 6);
//   gradient: dim x shapes,       grad phi = G phi_e.
// A bilinear form (L_w w) . M (L_x x) then has the local block weight * L_w^T M L_x, one matrix product.
#include <initializer_list>
#include <string>

#include <Eigen/Core>

#include "assembly/term.hpp"

namespace pc {

// Fixed upper sizes keep these on the stack: 6 Voigt rows, 27 shapes (Q2 hexahedron) of 3 components.
inline constexpr int kMaxOperatorColumns = 81;
using OperatorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, 6, kMaxOperatorColumns>;

void strain_matrix(const ElementData::Field& field, int q, int dim, OperatorMatrix& B);
void gradient_matrix(const ElementData::Field& field, int q, int dim, OperatorMatrix& G);

// Throws naming the term and its datum when the element's dimension is not the one the datum was written
// for (tensor_dim), or when field f does not have dim components (vector[f]) or one component.
void require_element_fits(const Term& term, const ElementData& e, const std::string& datum, int tensor_dim,
                          std::initializer_list<bool> vector);

}  // namespace pc
