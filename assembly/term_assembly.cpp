#include "assembly/term_assembly.hpp"

#include <algorithm>
#include <exception>

#include "assembly/error.hpp"
#include "assembly/threads.hpp"

namespace pc {
namespace {

// Element loops this short stay on one thread (the threads' start would cost more than they save), and
// longer ones go in chunks of kChunkElements computed elements (their local systems are kept until added).
constexpr int kMinElementsForThreads = 256;
constexpr int kChunkElements = 1024;

int highest_order(const std::vector<const FESpace*>& spaces) {
  int order = 1;
  for (const FESpace* s : spaces) order = std::max(order, s->order());
  return order;
}

}  // namespace

TermAssembly::TermAssembly(std::shared_ptr<const Term> term, const std::string& region,
                           std::vector<const FESpace*> spaces)
    : TermAssembly(term,
                   std::make_shared<const RegionGeometry>(spaces.at(0)->mesh(), region,
                                                          term->quadrature_degree(highest_order(spaces))),
                   spaces) {}

TermAssembly::TermAssembly(std::shared_ptr<const Term> term, const std::string& region,
                           std::vector<const FESpace*> spaces, TermAssemblyCache& cache)
    : TermAssembly(term, cache.geometry(region, term->quadrature_degree(highest_order(spaces))), spaces, &cache) {}

TermAssembly::TermAssembly(std::shared_ptr<const Term> term, std::shared_ptr<const RegionGeometry> geometry,
                           std::vector<const FESpace*> spaces)
    : TermAssembly(std::move(term), std::move(geometry), std::move(spaces), nullptr) {}

TermAssembly::TermAssembly(std::shared_ptr<const Term> term, std::shared_ptr<const RegionGeometry> geometry,
                           std::vector<const FESpace*> spaces, TermAssemblyCache* cache)
    : term_(std::move(term)), geometry_(std::move(geometry)), cache_(cache), spaces_(std::move(spaces)) {
  const Term& t = *term_;
  require(geometry_ != nullptr, "term '", t.name(), "': no region geometry");
  region_ = geometry_->region();
  degree_ = geometry_->degree();
  require(spaces_.size() == t.fields().size(), "term '", t.name(), "' names ", t.fields().size(),
          " fields but was given ", spaces_.size(), " spaces");
  for (const FESpace* s : spaces_) require(s != nullptr, "term '", t.name(), "': a field has no space");
  const Mesh& mesh = spaces_[0]->mesh();
  for (const FESpace* s : spaces_)
    require(&s->mesh() == &mesh, "term '", t.name(), "': its fields live on different meshes");
  require(&geometry_->mesh() == &mesh, "term '", t.name(), "': the region geometry is on another mesh");
  const Integration expected = t.integration();
  require(geometry_->integration() == expected, "term '", t.name(), "' integrates over ",
          expected == Integration::Cells ? "cells" : "faces", " but region '", geometry_->region(), "' is a ",
          geometry_->integration() == Integration::Cells ? "cell" : "face", " region");
  for (int e = 0; e < geometry_->num_elements(); ++e)
    for (int f = 0; f < int(spaces_.size()); ++f)
      require(spaces_[f]->has_cell(geometry_->cell(e)), "term '", t.name(), "': field '", t.fields()[f].name,
              "' is not defined on cell ", geometry_->cell(e), " of region '", geometry_->region(), "'");

  // Shape tables for each field, in the cell or on each local face.
  const int dim = mesh.dim();
  const int n_faces = num_faces(mesh.cell_shape());
  tables_.resize(spaces_.size());
  for (int f = 0; f < int(spaces_.size()); ++f) {
    const ReferenceElement& element = spaces_[f]->element();
    tables_[f].resize(n_faces + 1);
    for (int lf = -1; lf < n_faces; ++lf) {
      if ((expected == Integration::Cells) != (lf == -1)) continue;
      ShapeTable& table = tables_[f][lf + 1];
      if (lf < 0) {
        for (int i = 0; i < element.num_dofs(); ++i) table.local_dofs.push_back(i);
      } else {
        const auto on_face = element.face_dofs(lf);
        table.local_dofs.assign(on_face.begin(), on_face.end());
      }
      const int n = static_cast<int>(table.local_dofs.size());
      std::vector<double> all_N(element.num_dofs()), all_dN(element.num_dofs() * dim);
      for (const auto& xi : geometry_->reference_points(lf)) {
        element.values(xi.data(), all_N.data());
        element.gradients(xi.data(), all_dN.data());
        for (int i = 0; i < n; ++i) {
          table.N.push_back(all_N[table.local_dofs[i]]);
          if (lf < 0)
            for (int d = 0; d < dim; ++d) table.dN.push_back(all_dN[table.local_dofs[i] * dim + d]);
        }
      }
    }
  }
  build_blocks(cache);
}

const RegionGeometry& TermAssembly::geometry() const {
  if (!geometry_) geometry_ = cache_->geometry(region_, degree_);
  return *geometry_;
}

void TermAssembly::release_geometry() {
  if (!cache_ || released_) return;
  geometry_.reset();
  released_ = true;
}

const TermAssembly::ShapeTable& TermAssembly::table(int field, int local_face) const {
  return tables_[field][local_face + 1];
}

// The dofs in the order of the block patterns' elements (assembly/block_pattern.hpp), whose function it is.
void TermAssembly::element_dofs(int field, int element, std::vector<int>& dofs) const {
  pc::element_dofs(*spaces_[field], geometry(), element, dofs);
}

void TermAssembly::build_blocks(TermAssemblyCache* cache) {
  patterns_.clear();
  block_values_.clear();
  for (const Coupling& c : term_->couplings()) {
    const FESpace& test = *spaces_[c.test];
    const FESpace& trial = *spaces_[c.trial];
    patterns_.push_back(cache ? cache->pattern(geometry_, test, trial)
                              : std::make_shared<const BlockPattern>(make_block_pattern(*geometry_, test, trial)));
    block_values_.emplace_back(patterns_.back()->inner.size(), 0.0);
  }
}

CsrView TermAssembly::block(int k) const {
  const BlockPattern& p = *patterns_.at(size_t(k));
  return CsrView(p.rows, p.cols, Eigen::Index(p.inner.size()), p.outer.data(), p.inner.data(),
                 block_values_[size_t(k)].data());
}

void TermAssembly::assemble(std::span<const Eigen::VectorXd* const> values, double time,
                            std::span<Eigen::VectorXd* const> residuals, bool tangent) {
  check_arguments(values, residuals);
  bool want_residual = false;
  for (auto* r : residuals) want_residual = want_residual || r != nullptr;
  if (tangent)
    for (std::vector<double>& b : block_values_) std::fill(b.begin(), b.end(), 0.0);
  if (!want_residual && !tangent) return;
  run_element_loop(geometry(), values, time, residuals, want_residual, tangent);
}

// One value vector per field and one residual (or null) per test field, each of its space's size.
void TermAssembly::check_arguments(std::span<const Eigen::VectorXd* const> values,
                                   std::span<Eigen::VectorXd* const> residuals) const {
  const Term& term = *term_;
  const int n_fields = static_cast<int>(spaces_.size());
  const int n_tests = static_cast<int>(term.tests().size());
  require(int(values.size()) == n_fields, "term '", term.name(), "': ", values.size(), " value vectors for ", n_fields,
          " fields");
  require(int(residuals.size()) == n_tests, "term '", term.name(), "': ", residuals.size(), " residual vectors for ",
          n_tests, " test fields");
  for (int f = 0; f < n_fields; ++f)
    require(values[f] != nullptr && values[f]->size() == spaces_[f]->num_dofs(), "term '", term.name(),
            "': the values of field '", term.fields()[f].name, "' have ", values[f] ? values[f]->size() : 0,
            " entries, its space has ", spaces_[f]->num_dofs(), " dofs");
  for (int t = 0; t < n_tests; ++t)
    require(residuals[t] == nullptr || residuals[t]->size() == spaces_[term.tests()[t]]->num_dofs(), "term '",
            term.name(), "': residual of '", term.fields()[term.tests()[t]].name, "' has the wrong size");
}

// Sizes a workspace for this term (a kept one has the sizes already: the resizes do nothing).
void TermAssembly::prepare(Workspace& w, const RegionGeometry& geo, double time) const {
  const int nq = geo.num_points();
  w.data.dim = geo.mesh().dim();
  w.data.num_points = nq;
  w.data.time = time;
  w.data.weights.resize(nq);
  w.data.points.resize(nq);
  if (geo.integration() != Integration::Cells) w.data.normals.resize(nq);
  w.data.fields.resize(spaces_.size());
  w.local.residual.resize(term_->tests().size());
  w.local.tangent.resize(term_->couplings().size());
  w.dofs.resize(spaces_.size());
}

// Element e's quadrature data and its fields' dofs, values and (on cells) physical gradients at its points.
void TermAssembly::interpolate(int e, const RegionGeometry& geo, std::span<const Eigen::VectorXd* const> values,
                               Workspace& w) const {
  const int dim = geo.mesh().dim();
  const int nq = geo.num_points();
  const bool cells = geo.integration() == Integration::Cells;
  ElementData& data = w.data;
  data.cell = geo.cell(e);
  data.local_face = geo.local_face(e);
  for (int q = 0; q < nq; ++q) {
    data.weights[q] = geo.weight(e, q);
    data.points[q] = geo.point(e, q);
    if (!cells) data.normals[q] = geo.normal(e, q);
  }
  for (int f = 0; f < int(spaces_.size()); ++f) {
    const ShapeTable& t = table(f, data.local_face);
    ElementData::Field& field = data.fields[f];
    const int n = static_cast<int>(t.local_dofs.size());
    const int nc = spaces_[f]->num_components();
    field.num_shapes = n;
    field.num_components = nc;
    field.N = t.N.data();
    element_dofs(f, e, w.dofs[f]);
    field.coefficients.resize(n * nc);
    for (int a = 0; a < n * nc; ++a) field.coefficients[a] = (*values[f])[w.dofs[f][a]];
    field.value.assign(nq * nc, 0.0);
    for (int q = 0; q < nq; ++q)
      for (int i = 0; i < n; ++i)
        for (int c = 0; c < nc; ++c) field.value[q * nc + c] += t.N[q * n + i] * field.coefficients[i * nc + c];
    if (!cells) continue;
    // Physical gradients: dN = G dN_ref with G = J^{-T}.
    field.dN.resize(nq * n * dim);
    field.grad.assign(nq * nc * dim, 0.0);
    for (int q = 0; q < nq; ++q) {
      const double* G = geo.inverse_jacobian_t(e, q);
      for (int i = 0; i < n; ++i) {
        const double* ref = &t.dN[(q * n + i) * dim];
        double* phys = &field.dN[(q * n + i) * dim];
        for (int d = 0; d < dim; ++d) {
          double s = 0;
          for (int k = 0; k < dim; ++k) s += G[d * dim + k] * ref[k];
          phys[d] = s;
        }
        for (int c = 0; c < nc; ++c)
          for (int d = 0; d < dim; ++d) field.grad[(q * nc + c) * dim + d] += phys[d] * field.coefficients[i * nc + c];
      }
    }
  }
}

// The element's local residual and tangent (no shared state is written).
void TermAssembly::compute(int e, const RegionGeometry& geo, std::span<const Eigen::VectorXd* const> values,
                           bool want_residual, bool tangent, Workspace& w) const {
  const Term& term = *term_;
  interpolate(e, geo, values, w);
  for (int ti = 0; ti < int(term.tests().size()); ++ti) w.local.residual[ti].setZero(w.dofs[term.tests()[ti]].size());
  if (tangent)
    for (int k = 0; k < int(term.couplings().size()); ++k)
      w.local.tangent[k].setZero(w.dofs[term.couplings()[k].test].size(), w.dofs[term.couplings()[k].trial].size());
  term.assemble(w.data, w.local, want_residual, tangent);
}

// Adds the element's contributions into the global residuals and blocks (in element order).
void TermAssembly::scatter(const Workspace& w, std::span<Eigen::VectorXd* const> residuals, bool tangent) {
  const Term& term = *term_;
  for (int ti = 0; ti < int(term.tests().size()); ++ti) {
    if (residuals[ti] == nullptr) continue;
    const std::vector<int>& rows = w.dofs[term.tests()[ti]];
    for (int a = 0; a < int(rows.size()); ++a) (*residuals[ti])[rows[a]] += w.local.residual[ti][a];
  }
  if (!tangent) return;
  for (int k = 0; k < int(term.couplings().size()); ++k) {
    const Eigen::MatrixXd& K = w.local.tangent[k];
    const std::vector<int>& row_dofs = w.dofs[term.couplings()[k].test];
    const std::vector<int>& col_dofs = w.dofs[term.couplings()[k].trial];
    const int* outer = patterns_[k]->outer.data();
    const int* inner = patterns_[k]->inner.data();
    double* target = block_values_[k].data();
    // Each entry is in its row's pattern (the element made it): a binary search over the row's sorted
    // columns finds its slot.
    for (int r = 0; r < int(K.rows()); ++r) {
      const int* begin = inner + outer[row_dofs[r]];
      const int* end = inner + outer[row_dofs[r] + 1];
      for (int c = 0; c < int(K.cols()); ++c) target[std::lower_bound(begin, end, col_dofs[c]) - inner] += K(r, c);
    }
  }
}

// Every element of the region computed and scattered, on one thread or in chunks on several.
void TermAssembly::run_element_loop(const RegionGeometry& geo, std::span<const Eigen::VectorXd* const> values,
                                    double time, std::span<Eigen::VectorXd* const> residuals, bool want_residual,
                                    bool tangent) {
  const int n_elements = geo.num_elements();
  const int threads = n_elements >= kMinElementsForThreads ? assembly_threads() : 1;
  if (tangent) ++tangent_assemblies_;
  std::vector<Workspace> made;
  std::vector<Workspace>& workspaces = tangent_assemblies_ >= 2 ? kept_workspaces_ : made;
  workspaces.resize(threads == 1 ? 1 : std::min(kChunkElements, n_elements));
  for (Workspace& w : workspaces) prepare(w, geo, time);
  if (threads == 1) {
    Workspace& w = workspaces.front();
    for (int e = 0; e < n_elements; ++e) {
      compute(e, geo, values, want_residual, tangent, w);
      scatter(w, residuals, tangent);
    }
  } else {
    // Chunks of elements are computed in parallel, then added in element order: the sums are those of
    // the loop above, bit for bit. An exception leaves the parallel loop as the first failed element's.
    std::vector<Workspace>& chunk = workspaces;
    std::vector<std::exception_ptr> failures(chunk.size());
    for (int first = 0; first < n_elements; first += int(chunk.size())) {
      const int count = std::min(int(chunk.size()), n_elements - first);
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(static)
#endif
      for (int i = 0; i < count; ++i) {
        try {
          compute(first + i, geo, values, want_residual, tangent, chunk[i]);
        } catch (...) {
          failures[i] = std::current_exception();
        }
      }
      for (int i = 0; i < count; ++i)
        if (failures[i]) std::rethrow_exception(failures[i]);
      for (int i = 0; i < count; ++i) scatter(chunk[i], residuals, tangent);
    }
  }
  elements_assembled_ += n_elements;
}

}  // namespace pc
