#pragma once
// Finds the cell and reference coordinates of arbitrary physical points, through a uniform bucket grid
// over the cells' bounding boxes, and evaluates fields there (e.g. to sample results on a grid).
#include <array>
#include <functional>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "assembly/fe_space.hpp"

namespace pc {

struct LocatedPoint {
  int cell = -1;
  std::array<double, 3> xi{};  // reference coordinates
};

class PointLocator {
 public:
  explicit PointLocator(const Mesh& mesh);
  // The cell containing x (within a relative tolerance, so points on boundaries are found), or nothing.
  std::optional<LocatedPoint> locate(const double* x) const;
  // Like locate, among the cells for which accept(cell) holds only (e.g. the cells of a space on a
  // region, so that a point on the region's border is found in the region's cell, not its neighbour's).
  std::optional<LocatedPoint> locate(const double* x, const std::function<bool(int cell)>& accept) const;
  // Like locate, but throws naming the point when it lies outside the mesh.
  LocatedPoint locate_or_throw(const double* x) const;
  const Mesh& mesh() const { return mesh_; }

 private:
  const Mesh& mesh_;
  std::array<double, 3> lower_{}, cell_size_{};
  std::array<int, 3> counts_{1, 1, 1};
  // The cells of bucket b: bucket_cells_[bucket_start_[b] .. bucket_start_[b + 1]), in increasing order.
  std::vector<int> bucket_start_, bucket_cells_;
  double tolerance_ = 0;
};

// Value of a field at a physical point (num_components values); throws if x is outside the mesh.
std::vector<double> evaluate_at(const FESpace& space, const Eigen::VectorXd& coefficients, const PointLocator& locator,
                                const double* x);
// Its gradient there: out[c * dim + d] = d f_c / d x_d (on a cell boundary, the gradient of the cell found).
std::vector<double> gradient_at(const FESpace& space, const Eigen::VectorXd& coefficients, const PointLocator& locator,
                                const double* x);

}  // namespace pc
