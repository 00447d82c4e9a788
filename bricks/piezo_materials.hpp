#pragma once
// Piezoelectric material presets: the 3D constants of a poled ceramic as the literature gives them
// (stress-charge form, poled along z, Voigt order of voigt.hpp), turned into the tensors a model reads
// for another poling axis (3D) or for a plane-strain model in (x, y) poled in its plane (2D):
//
//   const PiezoMaterialPreset& m = piezo_material("PZT-5H");
//   const PiezoTensors t = m.tensors(2, Axis::y);  // t.B = c^E, t.E = e, t.beta = eps^S, t.rho
//
// The presets are entries of a registry (name, one line with the source, the constants), so that the
// list of names is discoverable and a user or plugin may add a material with PC_REGISTER. Sources and
// the values are listed in docs/bricks.md ("Material presets").
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "assembly/registry.hpp"

namespace pc {

// A coordinate axis, e.g. the poling direction.
enum class Axis { x = 0, y = 1, z = 2 };

// "x", "y" or "z"; anything else is refused with `where` (a scene path) in the message.
Axis axis_from_name(const std::string& name, const std::string& where);
const char* axis_name(Axis axis);

// What a model reads: elasticity B = c^E [Pa], piezoelectric E = e [C/m^2], permittivity beta = eps^S
// [F/m], density rho [kg/m^3]; n x n, dim x n and dim x dim with n = voigt_size(dim).
struct PiezoTensors {
  Eigen::MatrixXd B, E, beta;
  double rho = 0;
};

struct PiezoMaterialPreset {
  // 3D constants, poled along +z: c^E (6 x 6) [Pa], e (3 x 6) [C/m^2], eps^S (3 x 3) [F/m].
  Eigen::MatrixXd c, e, eps;
  double rho = 0;  // [kg/m^3]

  // The tensors poled along `poling`: in 3D the rotation of the constants carrying z onto that axis; in
  // 2D (plane strain in (x, y), eps_zz = 0 and E_z = 0) the reduction of those, which needs the poling
  // axis in the plane (x or y; z is refused).
  PiezoTensors tensors(int dim, Axis poling) const;
};

// A transversely isotropic (6mm) ceramic poled along z from its independent constants: stiffnesses
// c11 c12 c13 c33 c44 c66 [Pa], piezoelectric e31 e33 e15 [C/m^2], permittivities eps11^S eps33^S
// [F/m], density [kg/m^3].
struct HexagonalConstants {
  double c11, c12, c13, c33, c44, c66;
  double e31, e33, e15;
  double eps11, eps33;
  double rho;
};
PiezoMaterialPreset hexagonal_piezo_material(const HexagonalConstants& k);

// Vacuum permittivity [F/m] (CODATA 2018).
inline constexpr double kVacuumPermittivity = 8.8541878128e-12;

// The registry of presets ("piezoelectric material", scene key material.preset). An entry's `create`
// holds the preset itself (a preset is data, there is nothing to build; shared, so that a reference to
// it outlives later registrations) and `doc` its source:
//   PC_REGISTER(piezo_material_registry(), {"my-PZT", "source", {},
//                                           std::make_shared<const PiezoMaterialPreset>(...)});
using PiezoMaterialRegistry = Registry<std::shared_ptr<const PiezoMaterialPreset>>;
PiezoMaterialRegistry& piezo_material_registry();

// The preset called `name`; an unknown name is refused naming the known ones ("<where>: unknown
// piezoelectric material 'X' (known: ...)").
const PiezoMaterialPreset& piezo_material(const std::string& name, const std::string& where = "piezo_material");
std::vector<std::string> piezo_material_names();

// The pieces of PiezoMaterialPreset::tensors, for tensors of other origins.
// The proper rotation whose columns are the material axes in model coordinates, carrying the material's
// poling axis z onto `poling` (identity for z; x: (x, y, z) -> (-z, y, x); y: (x, y, z) -> (x, -z, y)),
// for rotate_stiffness, rotate_piezoelectric and rotate_permittivity.
Eigen::Matrix3d poling_rotation(Axis poling);
// Plane strain in (x, y) of 3D Voigt tensors: the rows and columns xx, yy, xy of C; the rows x, y and
// the columns xx, yy, xy of E; the (x, y) block of beta.
Eigen::MatrixXd plane_strain_stiffness(const Eigen::MatrixXd& C);
Eigen::MatrixXd plane_strain_piezoelectric(const Eigen::MatrixXd& E);
Eigen::MatrixXd plane_strain_permittivity(const Eigen::MatrixXd& beta);

}  // namespace pc
