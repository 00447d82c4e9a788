#pragma once
// Derived fields of a Kelvin-Voigt piezoelectric body for output, one value set per cell, evaluated at
// the cell's centroid (exact for P1 fields on simplices, whose gradients are constant per cell):
//   strain                  eps(u)                                       (Voigt, engineering shear)
//   stress                  sigma = A eps(v) + B eps(u) + E^T grad phi   (Voigt)
//   electric field          E_field = -grad phi
//   electric displacement   D = E eps(u) - beta grad phi
// Voigt orders and tensor shapes are those of bricks/voigt.hpp. Cells outside a field's space get zero
// contributions from that field (VTK has no partial fields).
//
// The tensors are the model's constants, read at each call so that a constant changed in the model shows
// in the output: "A" (viscosity, n x n), "B" (elasticity, n x n), "E" (piezoelectric, dim x n) and "beta"
// (permittivity, dim x dim). A term is there when the model has its field, and its tensor is then
// required, except A: a model without "A" has no viscosity.
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "assembly/vtu_writer.hpp"
#include "models/model.hpp"

namespace pc {

// The model's field names; a term whose field the model does not have is dropped.
struct PiezoFieldNames {
  std::string velocity = "v";
  std::string displacement = "u";
  std::string potential = "phi";
};

// num_cells * n values (n = 3 in 2D, 6 in 3D). The field must be a vector field.
std::vector<double> cell_strain(const Model& model, const std::string& displacement = "u");
// num_cells * n values.
std::vector<double> cell_stress(const Model& model, const PiezoFieldNames& names = {});
// num_cells * dim values. The field must be a scalar field.
std::vector<double> cell_electric_field(const Model& model, const std::string& potential = "phi");
// num_cells * dim values.
std::vector<double> cell_electric_displacement(const Model& model, const PiezoFieldNames& names = {});

// Von Mises equivalent stress of a Voigt stress (n values). In 3D the standard
//   sqrt(((sxx - syy)^2 + (syy - szz)^2 + (szz - sxx)^2) / 2 + 3 (syz^2 + sxz^2 + sxy^2)).
// In 2D (plane strain) the in-plane formula sqrt(sxx^2 - sxx syy + syy^2 + 3 sxy^2), i.e. the 3D one with
// szz = 0: the plane-strain szz needs the full 3D stiffness, which a 2D model does not have, so the value
// is the in-plane measure, not the true plane-strain von Mises stress.
double von_mises(std::span<const double> stress, int dim);

// Adds the point fields velocity, displacement and potential (those the model has) and the cell data
// "strain" (with a displacement), "stress" and "von_mises" (with a displacement or a velocity), and
// "electric_field" and "electric_displacement" (with a potential); with `wanted`, only the arrays whose
// name it accepts (an array left out is not computed either).
void add_piezo_output(VtuWriter& writer, const Model& model, const PiezoFieldNames& names = {},
                      const std::function<bool(const std::string&)>& wanted = nullptr);

}  // namespace pc
