#include "assembly/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

#include "assembly/cell_geometry.hpp"
#include "assembly/error.hpp"

namespace pc {
namespace {

using Point = std::array<double, 3>;

// A face identified independently of the cell that owns it: its sorted node indices, padded with -1
// (every face of a one-shape mesh has the same number of nodes, so the padding never differs).
using FaceKey = std::array<int, 4>;

std::string join(std::span<const int> values) {
  std::string out;
  for (int v : values) out += (out.empty() ? "" : " ") + std::to_string(v);
  return out;
}

Point sub(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Point cross(const Point& a, const Point& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Point& a) { return std::sqrt(dot(a, a)); }

Point position(const Mesh& mesh, int node) {
  Point p{0, 0, 0};
  const auto x = mesh.node(node);
  std::copy(x.begin(), x.end(), p.begin());
  return p;
}

std::vector<Point> positions(const Mesh& mesh, std::span<const int> nodes) {
  std::vector<Point> out;
  for (int n : nodes) out.push_back(position(mesh, n));
  return out;
}

Point reference_centroid(Shape shape) {
  Point centroid{0, 0, 0};
  for (int k = 0; k < num_vertices(shape); ++k) {
    const Point v = reference_vertex(shape, k);
    for (int i = 0; i < 3; ++i) centroid[i] += v[i] / num_vertices(shape);
  }
  return centroid;
}

Point mean(const std::vector<Point>& points) {
  Point m{0, 0, 0};
  for (const Point& p : points)
    for (int i = 0; i < 3; ++i) m[i] += p[i] / double(points.size());
  return m;
}

// Tangent vectors x_s, x_t of the bilinear quadrilateral P0 P1 P2 P3 (cyclic order) at (s, t).
std::array<Point, 2> quad_tangents(const std::vector<Point>& P, double s, double t) {
  Point xs, xt;
  for (int i = 0; i < 3; ++i) {
    xs[i] = (1 - t) * (P[1][i] - P[0][i]) + t * (P[2][i] - P[3][i]);
    xt[i] = (1 - s) * (P[3][i] - P[0][i]) + s * (P[2][i] - P[1][i]);
  }
  return {xs, xt};
}

// Points of the two-point Gauss rule on [0, 1] (weights 1/2): exact for cubics, hence for the det J of
// bilinear and trilinear maps and for the area element of planar bilinear faces.
constexpr double kGaussLow = 0.5 - 0.28867513459481288225;  // 1/2 - 1/(2 sqrt 3)
constexpr double kGaussHigh = 0.5 + 0.28867513459481288225;

void check_cell_index(const Mesh& mesh, int c) {
  require(c >= 0 && c < mesh.num_cells(), "cell ", c, " does not exist (the mesh has ", mesh.num_cells(), " cells)");
}

void check_face(const Mesh& mesh, FaceRef f) {
  require(f.cell >= 0 && f.cell < mesh.num_cells() && f.local_face >= 0 && f.local_face < num_faces(mesh.cell_shape()),
          "face (cell ", f.cell, ", local face ", f.local_face, ") does not exist (the mesh has ", mesh.num_cells(),
          " cells of ", num_faces(mesh.cell_shape()), " faces)");
}

void check_new_region(const Mesh& mesh, const std::string& name, bool empty) {
  require(!name.empty(), "a region name must not be empty");
  if (mesh.has_region(name))
    fail("region '", name, "' already exists (a ", mesh.region_kind(name) == RegionKind::Cells ? "cell" : "face",
         " region)");
  require(!empty, "region '", name, "' is empty");
}

}  // namespace

Mesh::Mesh(int dim, Shape cell_shape, std::vector<double> coordinates, std::vector<int> connectivity)
    : dim_(dim),
      cell_shape_(cell_shape),
      vertices_per_cell_(num_vertices(cell_shape)),
      coordinates_(std::move(coordinates)),
      connectivity_(std::move(connectivity)) {
  require(dim == 2 || dim == 3, "Mesh: dim must be 2 or 3, got ", dim);
  require(dimension(cell_shape) == dim, "Mesh: ", to_string(cell_shape), " cells have dimension ",
          dimension(cell_shape), " but the mesh has dim ", dim);
  require(coordinates_.size() % dim == 0, "Mesh: the number of coordinates (", coordinates_.size(),
          ") is not a multiple of dim ", dim);
  require(connectivity_.size() % vertices_per_cell_ == 0, "Mesh: the connectivity size (", connectivity_.size(),
          ") is not a multiple of ", vertices_per_cell_, " nodes per ", to_string(cell_shape));
  require(!connectivity_.empty(), "Mesh: the mesh has no cells");
  check_cells();
  find_boundary_faces();
  std::vector<int> all(num_cells());
  std::iota(all.begin(), all.end(), 0);
  cell_regions_["all"] = std::move(all);
}

void Mesh::check_cells() const {
  const bool simplex = is_simplex(cell_shape_);
  // Simplices have a constant det J; the multilinear maps of quadrilaterals and hexahedra are valid
  // when det J is positive at every vertex.
  std::vector<Point> points;
  if (simplex) {
    points.push_back(reference_centroid(cell_shape_));
  } else {
    for (int k = 0; k < vertices_per_cell_; ++k) points.push_back(reference_vertex(cell_shape_, k));
  }
  for (int c = 0; c < num_cells(); ++c) {
    const auto nodes = cell(c);
    // `if` rather than require(): the node list in the message is worth building only on failure.
    for (int k = 0; k < vertices_per_cell_; ++k) {
      if (nodes[k] < 0 || nodes[k] >= num_nodes())
        fail("cell ", c, " (nodes ", join(nodes), ") refers to node ", nodes[k], ", but the mesh has ", num_nodes(),
             " nodes");
      for (int l = 0; l < k; ++l)
        if (nodes[l] == nodes[k]) fail("cell ", c, " (nodes ", join(nodes), ") repeats node ", nodes[k]);
    }
    double min_det = 0;
    int worst = 0;
    for (int p = 0; p < int(points.size()); ++p) {
      double J[9];
      const double det = cell_jacobian(*this, c, points[p].data(), J);
      if (p == 0 || det < min_det) {
        min_det = det;
        worst = p;
      }
    }
    // Degeneracy is relative to the cell's size (its longest edge), so that it does not depend on units.
    double size = 0;
    for (int e = 0; e < num_edges(cell_shape_); ++e) {
      const auto ends = edge_vertices(cell_shape_, e);
      size = std::max(size, norm(sub(position(*this, nodes[ends[0]]), position(*this, nodes[ends[1]]))));
    }
    const double tolerance = 1e-12 * std::pow(size, dim_);
    if (min_det > tolerance) continue;
    const std::string where = simplex ? "" : message(" at its vertex ", worst);
    require(min_det >= -tolerance, "cell ", c, " (nodes ", join(nodes), ") is inverted: det J = ", min_det, where);
    fail("cell ", c, " (nodes ", join(nodes), ") is degenerate: det J = ", min_det, where, " for a cell of size ",
         size);
  }
}

void Mesh::find_boundary_faces() {
  struct Entry {
    FaceKey key;
    FaceRef face;
  };
  std::vector<Entry> entries;
  entries.reserve(size_t(num_cells()) * num_faces(cell_shape_));
  for (int c = 0; c < num_cells(); ++c) {
    for (int f = 0; f < num_faces(cell_shape_); ++f) {
      FaceKey key;
      key.fill(-1);
      const auto nodes = face_nodes({c, f});
      std::copy(nodes.begin(), nodes.end(), key.begin());
      std::sort(key.begin(), key.begin() + nodes.size());
      entries.push_back({key, {c, f}});
    }
  }
  std::sort(entries.begin(), entries.end(),
            [](const Entry& a, const Entry& b) { return std::tie(a.key, a.face) < std::tie(b.key, b.face); });

  std::vector<FaceRef> boundary;
  for (size_t first = 0; first < entries.size();) {
    size_t last = first;
    while (last < entries.size() && entries[last].key == entries[first].key) ++last;
    if (last - first == 1) boundary.push_back(entries[first].face);
    if (last - first > 2) {
      std::vector<int> owners;
      for (size_t i = first; i < last; ++i) owners.push_back(entries[i].face.cell);
      fail("non-manifold mesh: the face with nodes ", join(face_nodes(entries[first].face)), " is shared by ",
           owners.size(), " cells (", join(owners), ")");
    }
    first = last;
  }
  std::sort(boundary.begin(), boundary.end());
  face_regions_["boundary"] = std::move(boundary);
}

std::vector<int> Mesh::face_nodes(FaceRef face) const {
  check_face(*this, face);
  const auto nodes = cell(face.cell);
  std::vector<int> out;
  for (int v : face_vertices(cell_shape_, face.local_face)) out.push_back(nodes[v]);
  return out;
}

void Mesh::add_cell_region(const std::string& name, std::vector<int> cells) {
  check_new_region(*this, name, cells.empty());
  for (int c : cells)
    require(c >= 0 && c < num_cells(), "cell region '", name, "': cell ", c, " does not exist (the mesh has ",
            num_cells(), " cells)");
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  cell_regions_[name] = std::move(cells);
}

void Mesh::add_face_region(const std::string& name, std::vector<FaceRef> faces) {
  check_new_region(*this, name, faces.empty());
  for (const FaceRef& f : faces) {
    try {
      check_face(*this, f);
    } catch (const Error& e) {
      fail("face region '", name, "': ", e.what());
    }
  }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  face_regions_[name] = std::move(faces);
}

bool Mesh::has_region(const std::string& name) const {
  return cell_regions_.contains(name) || face_regions_.contains(name);
}

RegionKind Mesh::region_kind(const std::string& name) const {
  if (cell_regions_.contains(name)) return RegionKind::Cells;
  if (face_regions_.contains(name)) return RegionKind::Faces;
  fail("unknown region '", name, "'; the mesh has: ", known_region_names());
}

const std::vector<int>& Mesh::cell_region(const std::string& name) const {
  if (const auto it = cell_regions_.find(name); it != cell_regions_.end()) return it->second;
  require(!face_regions_.contains(name), "region '", name, "' is a face region, not a cell region");
  fail("unknown region '", name, "'; the mesh has: ", known_region_names());
}

const std::vector<FaceRef>& Mesh::face_region(const std::string& name) const {
  if (const auto it = face_regions_.find(name); it != face_regions_.end()) return it->second;
  require(!cell_regions_.contains(name), "region '", name, "' is a cell region, not a face region");
  fail("unknown region '", name, "'; the mesh has: ", known_region_names());
}

std::vector<std::string> Mesh::region_names() const {
  std::vector<std::string> names;
  for (const auto& [name, cells] : cell_regions_) names.push_back(name);
  for (const auto& [name, faces] : face_regions_) names.push_back(name);
  std::sort(names.begin(), names.end());
  return names;
}

std::string Mesh::known_region_names() const {
  std::string out;
  for (const std::string& name : region_names()) out += (out.empty() ? "" : ", ") + name;
  return out;
}

double Mesh::cell_measure(int c) const {
  check_cell_index(*this, c);
  double J[9];
  if (is_simplex(cell_shape_)) {
    return cell_jacobian(*this, c, reference_centroid(cell_shape_).data(), J) / (dim_ == 2 ? 2 : 6);
  }
  const double gauss[2] = {kGaussLow, kGaussHigh};
  const double weight = dim_ == 2 ? 0.25 : 0.125;
  double measure = 0;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < (dim_ == 3 ? 2 : 1); ++k) {
        const double xi[3] = {gauss[i], gauss[j], gauss[k]};
        measure += weight * cell_jacobian(*this, c, xi, J);
      }
  return measure;
}

double Mesh::face_measure(FaceRef f) const {
  const auto P = positions(*this, face_nodes(f));
  switch (P.size()) {
    case 2: return norm(sub(P[1], P[0]));
    case 3: return 0.5 * norm(cross(sub(P[1], P[0]), sub(P[2], P[0])));
    default: {
      double area = 0;
      for (double s : {kGaussLow, kGaussHigh})
        for (double t : {kGaussLow, kGaussHigh}) {
          const auto [xs, xt] = quad_tangents(P, s, t);
          area += 0.25 * norm(cross(xs, xt));
        }
      return area;
    }
  }
}

double Mesh::region_measure(const std::string& name) const {
  double measure = 0;
  if (region_kind(name) == RegionKind::Cells) {
    for (int c : cell_region(name)) measure += cell_measure(c);
  } else {
    for (const FaceRef& f : face_region(name)) measure += face_measure(f);
  }
  return measure;
}

std::array<double, 3> Mesh::face_normal(FaceRef f) const {
  const auto P = positions(*this, face_nodes(f));
  Point n;
  switch (P.size()) {
    case 2: {
      const Point t = sub(P[1], P[0]);
      n = {t[1], -t[0], 0};
      break;
    }
    case 3: n = cross(sub(P[1], P[0]), sub(P[2], P[0])); break;
    default: {
      const auto [xs, xt] = quad_tangents(P, 0.5, 0.5);
      n = cross(xs, xt);
    }
  }
  // Face vertex order does not fix the side: orient away from the owning cell's centroid.
  const Point outward = sub(mean(P), mean(positions(*this, cell(f.cell))));
  const double scale = (dot(n, outward) < 0 ? -1 : 1) / norm(n);
  for (double& component : n) component *= scale;
  return n;
}

}  // namespace pc
