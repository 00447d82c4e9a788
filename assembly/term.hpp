#pragma once
// A weak-form term: what the engine integrates over a region. The engine owns the loops over cells or
// faces, the geometry and the scatter; a term only sees one element at a time, through ElementData
// (geometry at the quadrature points, and for each field it names: shape functions, local coefficients,
// interpolated values and gradients), and adds its local residual and tangent blocks to LocalSystem.
//
// Residual convention: R(x) = internal - external. The tangent block of coupling (test, trial) is
// dR_test / d(trial field coefficients).
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace pc {

enum class Integration { Cells, Faces };

// A field the term reads. On faces, terms see values only (no gradients).
struct FieldUse {
  std::string name;
  bool gradient = false;
};

// A tangent block: rows of test field `test`, columns of field `trial` (indices into Term::fields()).
struct Coupling {
  int test;
  int trial;
};

// What a term sees of one element. Arrays are flat, indexed as their comments say; q runs over
// quadrature points, i over the element's local shape functions of a field (on faces, only those that
// do not vanish on the face), c over components and d over space directions.
struct ElementData {
  struct Field {
    int num_shapes = 0;
    int num_components = 0;
    const double* N = nullptr;         // N[q * num_shapes + i]
    std::vector<double> dN;            // dN[(q * num_shapes + i) * dim + d], physical; cells only
    std::vector<double> coefficients;  // [i * num_components + c]
    std::vector<double> value;         // [q * num_components + c]
    std::vector<double> grad;          // [(q * num_components + c) * dim + d]; cells only

    double shape(int q, int i) const { return N[q * num_shapes + i]; }
    const double* shape_grad(int q, int i, int dim) const { return dN.data() + (q * num_shapes + i) * dim; }
  };

  int dim = 0;
  int num_points = 0;
  double time = 0;
  int cell = -1;
  int local_face = -1;                         // -1 for cell integration
  std::vector<double> weights;                 // quadrature weight * |det J| (or face measure factor)
  std::vector<std::array<double, 3>> points;   // physical points
  std::vector<std::array<double, 3>> normals;  // outward unit normals; faces only
  std::vector<Field> fields;                   // in the order of Term::fields()
};

// Local contributions of one element, zeroed and sized by the engine before Term::assemble.
struct LocalSystem {
  std::vector<Eigen::VectorXd> residual;  // one per Term::tests() entry, size num_shapes * num_components
  std::vector<Eigen::MatrixXd> tangent;   // one per Term::couplings() entry
};

class Term {
 public:
  Term(std::string name, Integration integration, std::vector<FieldUse> fields, std::vector<int> tests,
       std::vector<Coupling> couplings);
  virtual ~Term() = default;

  const std::string& name() const { return name_; }
  Integration integration() const { return integration_; }
  const std::vector<FieldUse>& fields() const { return fields_; }
  const std::vector<int>& tests() const { return tests_; }
  const std::vector<Coupling>& couplings() const { return couplings_; }
  // Position of a field in fields(), or -1.
  int field_index(const std::string& name) const;
  // Position of a test field in tests(), or -1.
  int test_index(int field) const;

  // Quadrature degree used when the fields are of polynomial order `order`. The default, 2 * order,
  // integrates mass-type products exactly on affine cells.
  virtual int quadrature_degree(int order) const { return 2 * order; }

  // Adds this element's contributions to local (residual blocks if want_residual, tangent blocks if
  // want_tangent).
  virtual void assemble(const ElementData& element, LocalSystem& local, bool want_residual,
                        bool want_tangent) const = 0;

 private:
  std::string name_;
  Integration integration_;
  std::vector<FieldUse> fields_;
  std::vector<int> tests_;
  std::vector<Coupling> couplings_;
};

}  // namespace pc
