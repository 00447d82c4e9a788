#include "assembly/point_locator.hpp"

#include <algorithm>
#include <cmath>

#include "assembly/cell_geometry.hpp"
#include "assembly/error.hpp"

namespace pc {
namespace {

// Reference coordinates are dimensionless, so this tolerance is relative to the cell size: points on a
// shared face, edge or vertex are found despite round-off in map_to_reference.
constexpr double kReferenceTolerance = 1e-10;
// Physical tolerance relative to the mesh's bounding-box diagonal, for the bucket search.
constexpr double kRelativeTolerance = 1e-10;

std::string point_string(const double* x, int dim) {
  std::string text = "(";
  for (int d = 0; d < dim; ++d) text += message(d > 0 ? ", " : "", x[d]);
  return text + ")";
}

}  // namespace

PointLocator::PointLocator(const Mesh& mesh) : mesh_(mesh) {
  const int dim = mesh.dim();
  require(mesh.num_cells() > 0, "PointLocator: the mesh has no cells");

  std::array<double, 3> upper{};
  for (int d = 0; d < dim; ++d) lower_[d] = upper[d] = mesh.node(0)[d];
  for (int n = 1; n < mesh.num_nodes(); ++n)
    for (int d = 0; d < dim; ++d) {
      lower_[d] = std::min(lower_[d], mesh.node(n)[d]);
      upper[d] = std::max(upper[d], mesh.node(n)[d]);
    }
  double diagonal = 0;
  for (int d = 0; d < dim; ++d) diagonal += (upper[d] - lower_[d]) * (upper[d] - lower_[d]);
  tolerance_ = kRelativeTolerance * std::sqrt(diagonal);

  // Buckets about the size of a mean cell, so that a bucket holds about one cell.
  double box_volume = 1;
  for (int d = 0; d < dim; ++d) box_volume *= upper[d] - lower_[d];
  const double bucket_edge = std::pow(box_volume / mesh.num_cells(), 1.0 / dim);
  for (int d = 0; d < dim; ++d) {
    const double extent = upper[d] - lower_[d];
    counts_[d] = bucket_edge > 0 ? std::max(1, int(std::lround(extent / bucket_edge))) : 1;
    cell_size_[d] = extent > 0 ? extent / counts_[d] : 1;
  }
  // A first-order cell lies in the convex hull of its vertices, hence in their bounding box; the box is
  // widened by the tolerance so that a point found by inside_reference is always in a candidate bucket.
  // Two passes over the cells, counting and then filling, so that the buckets are one array (a vector per
  // bucket was a small allocation per cell, and its malloc header, at the run's peak of memory).
  const size_t num_buckets = size_t(counts_[0]) * counts_[1] * counts_[2];
  bucket_start_.assign(num_buckets + 1, 0);
  auto for_each_bucket_of = [&](int c, auto&& visit) {
    std::array<int, 3> first{0, 0, 0}, last{0, 0, 0};
    for (int d = 0; d < dim; ++d) {
      double low = mesh.node(mesh.cell(c)[0])[d], high = low;
      for (int n : mesh.cell(c)) {
        low = std::min(low, mesh.node(n)[d]);
        high = std::max(high, mesh.node(n)[d]);
      }
      first[d] = std::clamp(int(std::floor((low - tolerance_ - lower_[d]) / cell_size_[d])), 0, counts_[d] - 1);
      last[d] = std::clamp(int(std::floor((high + tolerance_ - lower_[d]) / cell_size_[d])), 0, counts_[d] - 1);
    }
    for (int k = first[2]; k <= last[2]; ++k)
      for (int j = first[1]; j <= last[1]; ++j)
        for (int i = first[0]; i <= last[0]; ++i) visit((size_t(k) * counts_[1] + j) * counts_[0] + i);
  };
  for (int c = 0; c < mesh.num_cells(); ++c) for_each_bucket_of(c, [&](size_t bucket) { ++bucket_start_[bucket + 1]; });
  for (size_t b = 0; b < num_buckets; ++b) bucket_start_[b + 1] += bucket_start_[b];
  bucket_cells_.resize(bucket_start_.back());
  std::vector<int> next(bucket_start_.begin(), bucket_start_.end() - 1);
  for (int c = 0; c < mesh.num_cells(); ++c)
    for_each_bucket_of(c, [&](size_t bucket) { bucket_cells_[next[bucket]++] = c; });
}

std::optional<LocatedPoint> PointLocator::locate(const double* x) const {
  return locate(x, [](int) { return true; });
}

std::optional<LocatedPoint> PointLocator::locate(const double* x, const std::function<bool(int cell)>& accept) const {
  const int dim = mesh_.dim();
  std::array<int, 3> index{0, 0, 0};
  for (int d = 0; d < dim; ++d) {
    const double upper = lower_[d] + cell_size_[d] * counts_[d];
    // Written so that a NaN coordinate is outside too.
    if (!(x[d] >= lower_[d] - tolerance_ && x[d] <= upper + tolerance_)) return std::nullopt;
    index[d] = std::clamp(int(std::floor((x[d] - lower_[d]) / cell_size_[d])), 0, counts_[d] - 1);
  }
  const size_t bucket = (size_t(index[2]) * counts_[1] + index[1]) * counts_[0] + index[0];
  for (int k = bucket_start_[bucket]; k < bucket_start_[bucket + 1]; ++k) {
    const int c = bucket_cells_[k];
    if (!accept(c)) continue;
    LocatedPoint hit{c, {0, 0, 0}};
    if (map_to_reference(mesh_, c, x, hit.xi.data()) &&
        inside_reference(mesh_.cell_shape(), hit.xi.data(), kReferenceTolerance))
      return hit;
  }
  return std::nullopt;
}

LocatedPoint PointLocator::locate_or_throw(const double* x) const {
  const auto hit = locate(x);
  require(hit.has_value(), "PointLocator: point ", point_string(x, mesh_.dim()), " lies outside the mesh");
  return *hit;
}

namespace {

// The cell of the field's space that holds x, and x's reference coordinates there.
LocatedPoint locate_in_space(const FESpace& space, const PointLocator& locator, const double* x, const char* what) {
  require(&space.mesh() == &locator.mesh(), what, ": the space and the point locator are on different meshes");
  const auto hit = locator.locate(x, [&space](int cell) { return space.has_cell(cell); });
  if (!hit) {
    const LocatedPoint in_mesh = locator.locate_or_throw(x);
    fail(what, ": point ", point_string(x, space.mesh().dim()), " lies in cell ", in_mesh.cell,
         ", outside the cells of the field's space");
  }
  return *hit;
}

}  // namespace

std::vector<double> evaluate_at(const FESpace& space, const Eigen::VectorXd& coefficients, const PointLocator& locator,
                                const double* x) {
  const LocatedPoint at = locate_in_space(space, locator, x, "evaluate_at");
  std::vector<double> value(space.num_components());
  space.evaluate_in_cell(coefficients, at.cell, at.xi.data(), value.data());
  return value;
}

std::vector<double> gradient_at(const FESpace& space, const Eigen::VectorXd& coefficients, const PointLocator& locator,
                                const double* x) {
  const LocatedPoint at = locate_in_space(space, locator, x, "gradient_at");
  std::vector<double> gradient(size_t(space.num_components()) * space.mesh().dim());
  space.gradient_in_cell(coefficients, at.cell, at.xi.data(), gradient.data());
  return gradient;
}

}  // namespace pc
