#include "models/model.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <set>
#include <span>
#include <utility>

#include "assembly/cell_partition.hpp"
#include "assembly/error.hpp"
#include "assembly/processes.hpp"
#include "models/linear_brick_cache.hpp"

namespace pc {

struct Model::Field {
  FieldKind kind = FieldKind::Data;
  std::shared_ptr<const FESpace> space;
  mutable Eigen::VectorXd values;  // an affine field's are computed on access, when what they read changed
  std::uint64_t version = 0;       // when the values (unknowns, data) or the map (affine fields) last changed
  std::string base;                // affine fields
  double factor = 1;
  std::vector<std::string> history;
  std::vector<double> coefficients;
  // Affine fields: the versions of the map, the base and each history field that `values` was computed
  // from. Each residual reads u and a several times (every term and mat-vec that couples them), and each
  // read was a pass over the dofs.
  mutable std::vector<std::uint64_t> computed_from;
};

// A brick term bound to the mesh, with the model's meaning of each of its couplings.
struct Model::BoundTerm {
  std::unique_ptr<TermAssembly> assembly;
  std::vector<std::string> field_names;     // per term field
  std::vector<std::string> test_unknowns;   // per test
  std::vector<std::string> trial_fields;    // per coupling
  std::vector<std::string> trial_unknowns;  // per coupling: the unknown whose columns it fills
  std::vector<std::string> uncoupled_data;  // data fields read but not differentiated (R0 depends on them)
};

struct Model::BrickState {
  std::vector<BoundTerm> terms;
  std::map<std::string, std::uint64_t> constant_versions;  // as last read by update()
  std::int64_t retired_elements = 0;                       // element loops of replaced assemblies
  LinearBrickCache cache;                                  // linear bricks
  std::set<std::string> tested;                            // the unknowns the terms test, as bound
};

struct Model::System {
  DofLayout layout;
  std::unique_ptr<SystemMatrix> matrix;
  std::vector<std::vector<std::vector<int>>> handles;  // [brick][term][coupling]
  // `matrix` holds the sum of the linear blocks with the scheme's factors (linear_jacobian()). The
  // Jacobian, that sum plus the nonlinear blocks, is formed only when it is asked for: the condensed
  // solves need no more than its nonlinear rows (nonlinear_part()), and a second matrix of the whole
  // pattern was the largest allocation of the model's own at a run's peak.
  CsrMatrix jacobian;
  bool jacobian_current = false;                   // jacobian is that of the last assemble(true)
  std::uint64_t linear_stamp = ~std::uint64_t(0);  // linear_version_ the sum was made with
  std::vector<double> linear_factors;              // affine factors of the last assemble(true), the sum's
  std::uint64_t linear_sum = 0;                    // Model::linear_sums_ when it was last made
  std::vector<int> nonlinear_dofs;                 // free dofs that nonlinear blocks touch, sorted
  // Where each nonlinear dof's row starts in nonlinear_part()'s values (-1 for other rows), and their
  // number.
  std::vector<long> nonlinear_row_start;
  long nonlinear_slots = 0;
};

// Distributed, an element loop that throws on one process must not leave the others waiting in the
// sums that follow it: each loop's failure is kept, the processes agree on it before the brick's sums,
// and all of them throw (the failing one its own error, the others its message).
struct Model::ElementLoops {
  std::exception_ptr failure;

  template <class Run> void run(Run&& loop) {
    if (!processes::distributed()) return loop();
    if (failure) return;
    try {
      loop();
    } catch (...) {
      failure = std::current_exception();
    }
  }
  void agree_on_failure(const Brick& brick) const {
    processes::agree_on_failure(failure, "brick '" + brick.name() + "'");
  }
};

namespace {

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out.empty() ? "none" : out;
}

// An unknown's free numbering in the layout (-1 on an eliminated dof).
std::span<const int> global_of(const DofLayout& l, const std::string& unknown) {
  return l.global_indices(l.field_index(unknown));
}

}  // namespace

Model::Model(std::shared_ptr<const Mesh> mesh) : mesh_(std::move(mesh)) {
  require(mesh_ != nullptr, "Model: no mesh");
  assembly_cache_ = std::make_unique<TermAssemblyCache>(*mesh_);
}

Model::~Model() = default;

Model::Field& Model::field(const std::string& name) {
  return const_cast<Field&>(static_cast<const Model*>(this)->field(name));
}

const Model::Field& Model::field(const std::string& name) const {
  const auto it = fields_.find(name);
  if (it == fields_.end()) fail("Model: unknown field '", name, "' (the model has: ", join(field_names()), ")");
  return *it->second;
}

std::vector<std::string> Model::field_names() const {
  std::vector<std::string> names;
  for (const auto& [name, f] : fields_) names.push_back(name);
  return names;
}

void Model::add_unknown(const std::string& name, std::shared_ptr<const FESpace> space) {
  require(!finalized_, "Model: add_unknown('", name, "') after finalize()");
  require(!has_field(name), "Model: field '", name, "' exists already");
  require(space && &space->mesh() == mesh_.get(), "Model: the space of '", name, "' is not on the model's mesh");
  auto f = std::make_unique<Field>();
  f->kind = FieldKind::Unknown;
  f->values = Eigen::VectorXd::Zero(space->num_dofs());
  f->version = ++clock_;
  f->space = std::move(space);
  fields_[name] = std::move(f);
  unknown_names_.push_back(name);
}

void Model::add_data_field(const std::string& name, std::shared_ptr<const FESpace> space, Eigen::VectorXd values) {
  require(!finalized_, "Model: add_data_field('", name, "') after finalize()");
  require(!has_field(name), "Model: field '", name, "' exists already");
  require(space && &space->mesh() == mesh_.get(), "Model: the space of '", name, "' is not on the model's mesh");
  if (values.size() == 0) values = Eigen::VectorXd::Zero(space->num_dofs());
  require(values.size() == space->num_dofs(), "Model: data field '", name, "' has ", values.size(),
          " values, its space has ", space->num_dofs(), " dofs");
  require(values.allFinite(), "Model: data field '", name, "' has non-finite values");
  auto f = std::make_unique<Field>();
  f->kind = FieldKind::Data;
  f->space = std::move(space);
  f->values = std::move(values);
  f->version = ++clock_;
  fields_[name] = std::move(f);
}

void Model::add_affine_field(const std::string& name, const std::string& base, std::vector<std::string> history) {
  require(!finalized_, "Model: add_affine_field('", name, "') after finalize()");
  require(!has_field(name), "Model: field '", name, "' exists already");
  const Field& b = field(base);
  require(b.kind == FieldKind::Unknown, "Model: affine field '", name, "' must be based on an unknown; '", base,
          "' is not one");
  for (const std::string& h : history) {
    const Field& hf = field(h);
    require(hf.kind == FieldKind::Data && hf.space == b.space, "Model: history '", h, "' of affine field '", name,
            "' must be a data field on the space of '", base, "'");
  }
  auto f = std::make_unique<Field>();
  f->kind = FieldKind::Affine;
  f->space = b.space;
  f->base = base;
  f->history = std::move(history);
  f->coefficients.assign(f->history.size(), 0.0);
  f->version = ++clock_;
  fields_[name] = std::move(f);
}

void Model::set_affine(const std::string& name, double factor, std::vector<double> history_coefficients) {
  Field& f = field(name);
  require(f.kind == FieldKind::Affine, "Model: '", name, "' is not an affine field");
  require(history_coefficients.size() == f.history.size(), "Model: affine field '", name, "' has ", f.history.size(),
          " history fields, got ", history_coefficients.size(), " coefficients");
  require(std::isfinite(factor), "Model: affine factor of '", name, "' is not finite: ", factor);
  f.factor = factor;
  f.coefficients = std::move(history_coefficients);
  f.version = ++clock_;
}

double Model::affine_factor(const std::string& name) const {
  const Field& f = field(name);
  return f.kind == FieldKind::Affine ? f.factor : 1.0;
}

std::vector<double> Model::affine_coefficients(const std::string& name) const {
  const Field& f = field(name);
  return f.kind == FieldKind::Affine ? f.coefficients : std::vector<double>{};
}

std::vector<std::string> Model::affine_history(const std::string& name) const {
  const Field& f = field(name);
  return f.kind == FieldKind::Affine ? f.history : std::vector<std::string>{};
}

const std::string& Model::affine_base(const std::string& name) const {
  const Field& f = field(name);
  require(f.kind == FieldKind::Affine, "Model: '", name, "' is not an affine field");
  return f.base;
}

FieldKind Model::field_kind(const std::string& name) const { return field(name).kind; }
const FESpace& Model::space(const std::string& name) const { return *field(name).space; }
std::shared_ptr<const FESpace> Model::space_ptr(const std::string& name) const { return field(name).space; }

const Eigen::VectorXd& Model::values(const std::string& name) const {
  const Field& f = field(name);
  if (f.kind != FieldKind::Affine) return f.values;
  const Field& base = field(f.base);
  bool current = f.computed_from.size() == f.history.size() + 2 && f.computed_from[0] == f.version &&
                 f.computed_from[1] == base.version;
  for (size_t i = 0; current && i < f.history.size(); ++i)
    current = f.computed_from[i + 2] == field(f.history[i]).version;
  if (current) return f.values;
  f.values = f.factor * base.values;
  f.computed_from = {f.version, base.version};
  for (size_t i = 0; i < f.history.size(); ++i) {
    const Field& h = field(f.history[i]);
    if (f.coefficients[i] != 0) f.values += f.coefficients[i] * h.values;
    f.computed_from.push_back(h.version);
  }
  return f.values;
}

void Model::set_values(const std::string& name, const Eigen::VectorXd& values) {
  Field& f = field(name);
  require(f.kind != FieldKind::Affine, "Model: affine field '", name, "' is computed, it cannot be set");
  require(values.size() == f.space->num_dofs(), "Model: '", name, "' has ", f.space->num_dofs(), " dofs, got ",
          values.size(), " values");
  require(values.allFinite(), "Model: non-finite values given for '", name, "'");
  f.values = values;
  f.version = ++clock_;
}

void Model::set_constant(const std::string& name, Eigen::MatrixXd value) {
  require(value.size() > 0, "Model: constant '", name, "' is empty");
  require(value.allFinite(), "Model: constant '", name, "' has non-finite entries");
  // An unchanged value invalidates nothing.
  const auto it = constants_.find(name);
  if (it != constants_.end() && it->second.first.rows() == value.rows() && it->second.first.cols() == value.cols() &&
      it->second.first == value)
    return;
  constants_[name] = {std::move(value), ++clock_};
}

void Model::set_constant(const std::string& name, double value) {
  require(std::isfinite(value), "Model: constant '", name, "' is not finite: ", value);
  set_constant(name, Eigen::MatrixXd::Constant(1, 1, value));
}

void Model::set_constants(const ParameterValues& values) {
  for (const auto& [name, value] : values) set_constant(name, value);
}

const Eigen::MatrixXd& Model::constant(const std::string& name) const {
  const auto it = constants_.find(name);
  if (it == constants_.end()) {
    std::vector<std::string> known;
    for (const auto& [n, v] : constants_) known.push_back(n);
    fail("Model: unknown constant '", name, "' (the model has: ", join(known), ")");
  }
  return it->second.first;
}

void Model::check_brick(const Brick& brick) const {
  const std::string who = "brick '" + brick.name() + "'";
  for (const BrickTerm& bt : brick.terms()) {
    const Term& term = *bt.term;
    require(mesh_->has_region(bt.region), who, ": unknown region '", bt.region,
            "' (the mesh has: ", join(mesh_->region_names()), ")");
    const bool cells = mesh_->region_kind(bt.region) == RegionKind::Cells;
    require(cells == (term.integration() == Integration::Cells), who, ": term '", term.name(), "' integrates over ",
            cells ? "faces" : "cells", " but region '", bt.region, "' is a ", cells ? "cell" : "face", " region");
    for (const FieldUse& use : term.fields())
      require(has_field(use.name), who, ": unknown field '", use.name, "' (the model has: ", join(field_names()), ")");
    for (int t : term.tests())
      require(field_kind(term.fields()[t].name) == FieldKind::Unknown, who, ": tests field '", term.fields()[t].name,
              "', which is not an unknown");
    for (const Coupling& c : term.couplings())
      require(field_kind(term.fields()[c.trial].name) != FieldKind::Data, who, ": differentiates data field '",
              term.fields()[c.trial].name, "'; only unknowns and affine fields have tangents");
  }
  for (const DirichletCondition& d : brick.dirichlet_conditions()) {
    require(has_field(d.unknown) && field_kind(d.unknown) == FieldKind::Unknown, who, ": Dirichlet condition on '",
            d.unknown, "', which is not an unknown");
    require(mesh_->has_region(d.region), who, ": unknown region '", d.region,
            "' (the mesh has: ", join(mesh_->region_names()), ")");
    for (int c : d.components)
      require(c >= 0 && c < space(d.unknown).num_components(), who, ": component ", c, " of '", d.unknown,
              "' does not exist");
  }
  for (const UniformValueCondition& d : brick.uniform_value_conditions()) {
    require(has_field(d.unknown) && field_kind(d.unknown) == FieldKind::Unknown, who, ": uniform value of '", d.unknown,
            "', which is not an unknown");
    require(mesh_->has_region(d.region), who, ": unknown region '", d.region,
            "' (the mesh has: ", join(mesh_->region_names()), ")");
    require(d.component >= 0 && d.component < space(d.unknown).num_components(), who, ": component ", d.component,
            " of '", d.unknown, "' does not exist");
  }
}

std::vector<int> Model::constrained_dofs(const std::string& unknown) const {
  require(finalized_, "Model: constrained_dofs('", unknown, "') before finalize()");
  const auto it = constrained_.find(unknown);
  return it == constrained_.end() ? std::vector<int>{} : it->second;
}

int Model::add_brick(std::shared_ptr<Brick> brick) {
  require(brick != nullptr, "Model: add_brick(nullptr)");
  require(!finalized_, "Model: add_brick('", brick->name(), "') after finalize()");
  brick->update(*this);
  for (const BrickUnknown& own : brick->own_unknowns()) {
    require(has_field(own.like), "brick '", brick->name(), "': its unknown '", own.name, "' takes the space of '",
            own.like, "', which the model does not have");
    require(mesh_->has_region(own.region), "brick '", brick->name(), "': its unknown '", own.name,
            "' lives on region '", own.region, "', which the mesh does not have (it has: ", join(mesh_->region_names()),
            ")");
    require(!has_field(own.name), "brick '", brick->name(), "' brings the unknown '", own.name,
            "', but the model has a field of that name already (one such brick per model)");
    add_unknown(own.name, space_ptr(own.like));
    restricted_[own.name] = own;
  }
  check_brick(*brick);
  auto state = std::make_unique<BrickState>();
  for (const std::string& name : brick->data()) {
    const auto it = constants_.find(name);
    require(it != constants_.end(), "Model: brick '", brick->name(), "' reads the constant '", name,
            "', which the model does not have (set it before adding the brick)");
    state->constant_versions[name] = it->second.second;
  }
  claim_parameters(*brick, state->constant_versions);
  bricks_.push_back(std::move(brick));
  brick_states_.push_back(std::move(state));
  return static_cast<int>(bricks_.size()) - 1;
}

// A constant a brick reads is owned by the first brick to read it (a law's parameters by the law's brick).
// Another brick reading it as its owner read it is no declaration (a friction brick reads its normal
// brick's c_nu); one that finds it set to a new value since declares it anew, which would change the
// owner's parameter behind its back: a second owner is refused, naming both. A value set again unchanged
// changes nothing, and counts as no new declaration.
void Model::claim_parameters(const Brick& brick, const std::map<std::string, std::uint64_t>& versions) {
  for (const auto& [name, version] : versions) {
    const auto owner = parameter_owners_.find(name);
    if (owner != parameter_owners_.end() && owner->second.brick != brick.name() && owner->second.version != version)
      fail("Model: parameter '", name, "' is declared by brick '", owner->second.brick, "' and by brick '",
           brick.name(), "': the second would change the first's value (give one of them a name of its own)");
  }
  for (const auto& [name, version] : versions) {
    auto [owner, inserted] = parameter_owners_.try_emplace(name, ParameterOwner{brick.name(), version});
    if (owner->second.brick == brick.name()) owner->second.version = version;
  }
}

void Model::bind_brick(int index) {
  const Brick& brick = *bricks_[index];
  BrickState& state = *brick_states_[index];
  // New terms may test other unknowns: the kept residuals start again from zero.
  if (const auto kept = kept_residuals_.find(index); kept != kept_residuals_.end())
    for (auto& [u, r] : kept->second) r.setZero();
  for (const BoundTerm& bt : state.terms) state.retired_elements += bt.assembly->elements_assembled();
  std::vector<BoundTerm> bound;
  for (const BrickTerm& bt : brick.terms()) {
    BoundTerm b;
    std::vector<const FESpace*> spaces;
    for (const FieldUse& use : bt.term->fields()) {
      b.field_names.push_back(use.name);
      spaces.push_back(&space(use.name));
    }
    for (int t : bt.term->tests()) b.test_unknowns.push_back(b.field_names[t]);
    std::set<std::string> coupled;
    for (const Coupling& c : bt.term->couplings()) {
      const std::string& trial = b.field_names[c.trial];
      b.trial_fields.push_back(trial);
      b.trial_unknowns.push_back(field_kind(trial) == FieldKind::Affine ? field(trial).base : trial);
      coupled.insert(trial);
    }
    for (const std::string& name : b.field_names)
      if (!coupled.count(name) && field_kind(name) == FieldKind::Data) b.uncoupled_data.push_back(name);
    b.assembly = std::make_unique<TermAssembly>(bt.term, bt.region, spaces, *assembly_cache_);
    // A rebuilt term must keep its pattern: the system matrix was declared with it.
    if (bound.size() < state.terms.size()) {
      const BoundTerm& old = state.terms[bound.size()];
      for (size_t k = 0; k < b.trial_fields.size(); ++k)
        require(old.assembly->block(int(k)).nonZeros() == b.assembly->block(int(k)).nonZeros(), "brick '", brick.name(),
                "' changed the sparsity of its terms in update()");
    }
    bound.push_back(std::move(b));
  }
  require(state.terms.empty() || state.terms.size() == bound.size(), "brick '", brick.name(),
          "' changed its number of terms in update()");
  state.terms = std::move(bound);
  state.tested.clear();
  for (const BoundTerm& bt : state.terms) state.tested.insert(bt.test_unknowns.begin(), bt.test_unknowns.end());
  state.cache.invalidate();
}

void Model::finalize() {
  require(!finalized_, "Model: finalize() called twice");
  require(!unknown_names_.empty(), "Model: no unknown field");
  // Every field must be read by some brick (directly, or as the base or history of a field that is).
  std::set<std::string> used;
  for (const auto& brick : bricks_)
    for (const BrickTerm& bt : brick->terms())
      for (const FieldUse& use : bt.term->fields()) used.insert(use.name);
  for (const auto& [name, f] : fields_)
    if (f->kind == FieldKind::Affine && used.count(name)) {
      used.insert(f->base);
      used.insert(f->history.begin(), f->history.end());
    }
  for (const auto& [name, f] : fields_)
    require(used.count(name) > 0, "Model: field '", name,
            "' is used by no brick; remove it or add the brick that needs it");

  // Distributed: this process's terms hold the elements of its cells only (the partition is the same on
  // every process), and assemble() sums the processes' residuals.
  if (processes::distributed()) {
    owned_cells_ = cells_of_part(partition_cells(*mesh_, processes::count()), processes::rank());
    assembly_cache_->set_owned_cells(owned_cells_);
  }
  // The cache holds geometries and patterns weakly: the terms' blocks hold theirs, and a brick bound again
  // later shares them.
  for (int b = 0; b < int(bricks_.size()); ++b) bind_brick(b);
  for (const auto& brick : bricks_)
    for (const DirichletCondition& d : brick->dirichlet_conditions()) {
      const FESpace& s = space(d.unknown);
      std::vector<int>& dofs = constrained_[d.unknown];
      for (int scalar : s.scalar_dofs_on(d.region))
        for (int c = 0; c < s.num_components(); ++c)
          if (d.components.empty() || std::count(d.components.begin(), d.components.end(), c))
            dofs.push_back(s.dof(scalar, c));
      dirichlet_.push_back(d);
    }
  // A brick's own unknown lives on its region: the dofs off it are eliminated, at 0, and so are those
  // where its `like` field is prescribed (a multiplier of a clamped dof has nothing to act on: its force
  // is the clamp's reaction, and its column would be empty).
  for (const auto& [name, own] : restricted_) {
    const FESpace& s = space(name);
    std::vector<char> on(s.num_dofs(), 0);
    for (int d : s.dofs_on(own.region)) on[d] = 1;
    if (constrained_.count(own.like))
      for (int d : constrained_.at(own.like)) on[d] = 0;
    std::vector<int>& dofs = constrained_[name];
    for (int d = 0; d < s.num_dofs(); ++d)
      if (!on[d]) dofs.push_back(d);
  }
  for (auto& [name, dofs] : constrained_) {
    std::sort(dofs.begin(), dofs.end());
    dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
  }
  collect_uniform_values();
  finalized_ = true;
  apply_dirichlet();
}

void Model::collect_uniform_values() {
  // Regions of one value that share a dof are one group (two electrodes touching at a corner are one
  // conductor): the groups are merged by union-find over the dofs.
  for (const auto& brick : bricks_)
    for (const UniformValueCondition& d : brick->uniform_value_conditions()) {
      const FESpace& s = space(d.unknown);
      const std::vector<int>& constrained = constrained_[d.unknown];
      std::vector<int> dofs;
      for (int scalar : s.scalar_dofs_on(d.region)) {
        const int dof = s.dof(scalar, d.component);
        require(!std::binary_search(constrained.begin(), constrained.end(), dof), "brick '", brick->name(),
                "': region '", d.region, "' shares dofs of '", d.unknown,
                "' with a Dirichlet condition (a uniform value cannot be prescribed too)");
        dofs.push_back(dof);
      }
      tied_[d.unknown].push_back(std::move(dofs));
    }
  for (auto& [name, groups] : tied_) {
    std::map<int, int> parent;
    const auto root = [&](int d) {
      while (parent.at(d) != d) d = parent[d] = parent.at(parent.at(d));
      return d;
    };
    for (const std::vector<int>& group : groups)
      for (int d : group) parent.emplace(d, d);
    for (const std::vector<int>& group : groups)
      for (int d : group) parent[root(d)] = root(group.front());
    std::map<int, std::vector<int>> merged;
    for (const auto& [d, p] : parent) merged[root(d)].push_back(d);
    groups.clear();
    for (auto& [r, group] : merged) groups.push_back(std::move(group));
  }
}

void Model::apply_dirichlet() {
  require(finalized_, "Model: apply_dirichlet() before finalize()");
  for (const DirichletCondition& d : dirichlet_) {
    Field& f = field(d.unknown);
    f.version = ++clock_;  // first: a value refused below leaves the others changed
    const FESpace& s = *f.space;
    double value[3];
    for (int scalar : s.scalar_dofs_on(d.region)) {
      d.value(s.scalar_dof_point(scalar).data(), time_, value);
      for (int c = 0; c < s.num_components(); ++c) {
        if (!d.components.empty() && !std::count(d.components.begin(), d.components.end(), c)) continue;
        require(std::isfinite(value[c]), "Dirichlet value of '", d.unknown, "' on '", d.region,
                "' is not finite at t = ", time_);
        f.values[s.dof(scalar, c)] = value[c];
      }
    }
  }
  for (const auto& [name, groups] : tied_) {
    Field& f = field(name);
    f.version = ++clock_;
    for (const std::vector<int>& group : groups)
      for (int d : group) f.values[d] = f.values[group.front()];
  }
}

void Model::set_frozen(const std::vector<std::string>& unknowns) {
  for (const std::string& u : unknowns)
    require(has_field(u) && field_kind(u) == FieldKind::Unknown, "Model: cannot freeze '", u, "': not an unknown");
  frozen_ = unknowns;
  std::sort(frozen_.begin(), frozen_.end());
}

Model::System& Model::system() {
  require(finalized_, "Model: assemble() before finalize()");
  auto& slot = systems_[frozen_];
  if (slot) return *slot;
  slot = std::make_unique<System>();
  System& s = *slot;
  for (const std::string& u : unknown_names_) {
    std::vector<int> constrained;
    if (std::count(frozen_.begin(), frozen_.end(), u)) {
      constrained.resize(space(u).num_dofs());
      for (int d = 0; d < int(constrained.size()); ++d) constrained[d] = d;
    } else if (constrained_.count(u)) {
      constrained = constrained_.at(u);
    }
    const bool tied = !std::count(frozen_.begin(), frozen_.end(), u) && tied_.count(u);
    s.layout.add_field(u, space(u).num_dofs(), constrained, tied ? tied_.at(u) : std::vector<std::vector<int>>{});
  }
  s.matrix = std::make_unique<SystemMatrix>(s.layout);
  s.handles.resize(bricks_.size());
  for (int b = 0; b < int(bricks_.size()); ++b) {
    for (const BoundTerm& bt : brick_states_[b]->terms) {
      std::vector<int> handles;
      for (size_t k = 0; k < bt.trial_fields.size(); ++k) {
        const Coupling& c = bt.assembly->term().couplings()[k];
        handles.push_back(s.matrix->declare(s.layout.field_index(bt.field_names[c.test]),
                                            s.layout.field_index(bt.trial_unknowns[k]), bt.assembly->block(int(k))));
      }
      s.handles[b].push_back(std::move(handles));
    }
  }
  s.matrix->finalize();
  // The dofs the nonlinear bricks touch: only their rows and columns of the Jacobian change inside a step.
  std::set<int> touched;
  for (int b = 0; b < int(bricks_.size()); ++b) {
    if (bricks_[b]->linear()) continue;
    for (const BoundTerm& bt : brick_states_[b]->terms)
      for (size_t k = 0; k < bt.trial_fields.size(); ++k) {
        const CsrView block = bt.assembly->block(int(k));
        const auto rows =
            s.layout.global_indices(s.layout.field_index(bt.field_names[bt.assembly->term().couplings()[k].test]));
        const auto cols = s.layout.global_indices(s.layout.field_index(bt.trial_unknowns[k]));
        for (int r = 0; r < block.rows(); ++r)
          for (CsrView::InnerIterator it(block, r); it; ++it) {
            if (rows[r] >= 0) touched.insert(rows[r]);
            if (cols[it.col()] >= 0) touched.insert(cols[it.col()]);
          }
      }
  }
  s.nonlinear_dofs.assign(touched.begin(), touched.end());
  s.nonlinear_row_start.assign(s.layout.size(), -1);
  const int* outer = s.matrix->matrix().outerIndexPtr();
  for (int row : s.nonlinear_dofs) {
    s.nonlinear_row_start[row] = s.nonlinear_slots;
    s.nonlinear_slots += outer[row + 1] - outer[row];
  }
  return s;
}

const DofLayout& Model::layout() const {
  const auto it = systems_.find(frozen_);
  require(it != systems_.end(), "Model: layout() before the first assemble()");
  return it->second->layout;
}

const CsrMatrix& Model::jacobian() const {
  const auto it = systems_.find(frozen_);
  require(it != systems_.end() && it->second->linear_sum > 0, "Model: jacobian() before assemble(true)");
  System& s = *it->second;  // the Jacobian is formed on first demand: logically const
  if (!s.jacobian_current) {
    const auto start = std::chrono::steady_clock::now();
    require_factors_of_last_tangent(s, "jacobian()");
    const CsrMatrix& linear = s.matrix->matrix();
    if (s.jacobian.rows() != linear.rows() || s.jacobian.nonZeros() != linear.nonZeros())
      s.jacobian = linear;
    else
      std::copy_n(linear.valuePtr(), linear.nonZeros(), s.jacobian.valuePtr());
    for_each_block(s, /*linear=*/false, [&](int handle, const CsrView& block, double factor) {
      s.matrix->add_to(handle, block, factor, s.jacobian);
    });
    s.jacobian_current = true;
    jacobian_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return s.jacobian;
}

void Model::nonlinear_part(std::vector<double>& values) {
  const auto start = std::chrono::steady_clock::now();
  System& s = system();
  require(s.linear_sum > 0, "Model: nonlinear_part() before assemble(true)");
  require_factors_of_last_tangent(s, "nonlinear_part()");
  values.assign(size_t(s.nonlinear_slots), 0.0);
  for_each_block(s, /*linear=*/false, [&](int handle, const CsrView& block, double factor) {
    s.matrix->add_to_rows(handle, block, factor, s.nonlinear_row_start, values);
  });
  jacobian_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool Model::assemble_nonlinear_rows(Eigen::VectorXd& rows) {
  if (processes::distributed()) return false;
  System& s = system();
  require(s.linear_sum > 0, "Model: assemble_nonlinear_rows() before assemble(true)");
  require_factors_of_last_tangent(s, "assemble_nonlinear_rows()");
  // At the values and time of the last assembly with the tangent (the start of a Newton solve), its sums
  // stand. Otherwise each nonlinear brick's element loops, as in assemble(true), summed per unknown; their
  // tangent blocks are what nonlinear_part() sums.
  if (nonlinear_rows_at_ != std::pair{clock_, time_}) {
    for (const std::string& u : unknown_names_) nonlinear_scratch_.at(u).setZero();
    ElementLoops loops;  // on one process, each loop runs as it is
    for (int b = 0; b < int(bricks_.size()); ++b)
      if (!bricks_[b]->linear()) run_nonlinear_loops(b, nonlinear_scratch_, true, loops);
    s.jacobian_current = false;
    nonlinear_rows_at_ = {clock_, time_};
  }
  Eigen::VectorXd global = Eigen::VectorXd::Zero(s.layout.size());
  for (const std::string& u : unknown_names_)
    s.layout.add_to_global(s.layout.field_index(u), nonlinear_scratch_.at(u), global);
  rows = global(s.nonlinear_dofs);
  return true;
}

bool Model::residual_derivative(const std::map<std::string, Eigen::VectorXd>& change, Eigen::VectorXd& out) const {
  const auto system_of_frozen = systems_.find(frozen_);
  if (processes::distributed() || system_of_frozen == systems_.end()) return false;
  const System& s = *system_of_frozen->second;
  // How each field moves: a changed datum by its direction, an affine field by its coefficients' sum of
  // its history's.
  std::map<std::string, Eigen::VectorXd> moved;
  for (const auto& [name, direction] : change) {
    const Field& f = field(name);
    require(f.kind == FieldKind::Data, "Model: residual_derivative() along '", name, "', which is not a data field");
    require(direction.size() == f.space->num_dofs(), "Model: residual_derivative() along '", name, "' with ",
            direction.size(), " values, its space has ", f.space->num_dofs(), " dofs");
    moved[name] = direction;
  }
  for (const auto& [name, f] : fields_) {
    if (f->kind != FieldKind::Affine) continue;
    for (size_t i = 0; i < f->history.size(); ++i) {
      const auto direction = change.find(f->history[i]);
      if (direction == change.end() || f->coefficients[i] == 0) continue;
      auto [it, inserted] = moved.try_emplace(name, Eigen::VectorXd::Zero(f->space->num_dofs()));
      it->second += f->coefficients[i] * direction->second;
    }
  }
  std::map<std::string, Eigen::VectorXd> per_unknown;
  for (int b = 0; b < int(bricks_.size()); ++b) {
    const BrickState& state = *brick_states_[b];
    for (const auto& [name, seen] : state.constant_versions)
      if (constants_.at(name).second != seen) return false;
    for (const BoundTerm& bt : state.terms) {
      for (const std::string& name : bt.field_names) {
        if (!moved.count(name)) continue;
        const bool coupled = std::count(bt.trial_fields.begin(), bt.trial_fields.end(), name) > 0;
        if (!bricks_[b]->linear() || !state.cache.tangent_valid || !coupled) return false;
      }
      for (size_t k = 0; k < bt.trial_fields.size(); ++k) {
        const auto direction = moved.find(bt.trial_fields[k]);
        if (direction == moved.end()) continue;
        const std::string& u = bt.field_names[bt.assembly->term().couplings()[k].test];
        auto [it, inserted] = per_unknown.try_emplace(u, Eigen::VectorXd::Zero(space(u).num_dofs()));
        it->second += bt.assembly->block(int(k)) * direction->second;
      }
    }
  }
  out = Eigen::VectorXd::Zero(s.layout.size());
  for (const auto& [u, r] : per_unknown) s.layout.add_to_global(s.layout.field_index(u), r, out);
  return true;
}

template <class Add> void Model::for_each_block(const System& s, bool linear, Add&& add) const {
  for (int b = 0; b < int(bricks_.size()); ++b) {
    if (bricks_[b]->linear() != linear) continue;
    const BrickState& state = *brick_states_[b];
    for (size_t t = 0; t < state.terms.size(); ++t) {
      const BoundTerm& bt = state.terms[t];
      for (size_t k = 0; k < bt.trial_fields.size(); ++k)
        add(s.handles[b][t][k], bt.assembly->block(int(k)), affine_factor(bt.trial_fields[k]));
    }
  }
}

// The nonlinear blocks hold the tangent of the last assemble(true); summed with other factors (a step
// begun since) they would be no Jacobian at all.
void Model::require_factors_of_last_tangent(const System& s, const char* what) const {
  require(affine_factors() == s.linear_factors, "Model: ", what,
          " after the time scheme's factors changed since the last assemble(true)");
}

std::vector<double> Model::affine_factors() const {
  std::vector<double> factors;
  for (const auto& [name, f] : fields_)
    if (f->kind == FieldKind::Affine) factors.push_back(f->factor);
  return factors;
}

void Model::keep_brick_residuals(const std::vector<int>& bricks) {
  for (int b : bricks) {
    require(b >= 0 && b < int(bricks_.size()), "Model: brick index ", b, " out of range (", bricks_.size(), " bricks)");
    kept_residuals_[b];
  }
}

const Eigen::VectorXd& Model::brick_residual(int brick, const std::string& unknown) const {
  require(!kept_residuals_in_snapshot_, "Model: brick_residual(", brick,
          ") while a residual snapshot holds the kept residuals (restore_residual() first)");
  const auto kept = kept_residuals_.find(brick);
  require(kept != kept_residuals_.end(), "Model: the residual of brick ", brick, " is not kept (keep_brick_residuals)");
  const auto it = kept->second.find(unknown);
  require(it != kept->second.end(), "Model: no residual of brick ", brick, " for '", unknown, "' (assemble first)");
  return it->second.size() == 0 ? zero_residuals_.at(unknown) : it->second;  // empty: an untested unknown
}

const Eigen::VectorXd& Model::field_residual(const std::string& unknown) const {
  const auto it = field_residuals_.find(unknown);
  require(it != field_residuals_.end(), "Model: no residual for '", unknown, "' (assemble first)");
  return it->second;
}

// Re-reads the constants of a brick whose data changed, and re-binds its terms if update() replaced them.
void Model::refresh_brick(int index) {
  Brick& brick = *bricks_[index];
  BrickState& state = *brick_states_[index];
  bool changed = false;
  for (auto& [name, seen] : state.constant_versions) {
    const std::uint64_t now = constants_.at(name).second;
    changed = changed || now != seen;
    seen = now;
  }
  if (!changed) return;
  brick.update(*this);
  const auto terms = brick.terms();
  bool same_terms = terms.size() == state.terms.size();
  for (size_t t = 0; same_terms && t < terms.size(); ++t)
    same_terms = &state.terms[t].assembly->term() == terms[t].term.get();
  if (same_terms) {
    state.cache.invalidate();
  } else {
    bind_brick(index);
  }
}

void Model::refresh_linear_sum(System& s) {
  s.matrix->set_zero();
  for_each_block(s, /*linear=*/true,
                 [&](int handle, const CsrView& block, double factor) { s.matrix->add(handle, block, factor); });
}

void Model::assemble(bool tangent) {
  System& s = system();
  nonlinear_rows_at_ = {~std::uint64_t(0), 0.0};  // the kept rows stand again only once this assembly ends
  std::map<std::string, Eigen::VectorXd> brick_residual = start_assembly();  // one brick's, to measure it
  size_kept_residuals();
  ElementLoops loops;
  for (int b = 0; b < int(bricks_.size()); ++b) {
    refresh_brick(b);
    if (!bricks_[b]->linear()) {
      add_nonlinear_brick(b, s, brick_residual, tangent, loops);
      continue;
    }
    assemble_linear_tangent(b, loops);
    refresh_r0(b, loops);
    add_linear_pieces(b, s, brick_residual);
  }
  if (tangent) refresh_tangent(s);
  // A brick's own unknown is measured at least by the scale of its `like` field (residual_scaling.hpp).
  for (const auto& [name, own] : restricted_) scaling_.at_least_that_of(name, own.like);
  residual_ = Eigen::VectorXd::Zero(s.layout.size());
  for (const std::string& u : unknown_names_)
    s.layout.add_to_global(s.layout.field_index(u), field_residuals_.at(u), residual_);
}

// Zeroes the field residuals, the nonlinear bricks' sums and the scales; returns a zero vector per unknown.
std::map<std::string, Eigen::VectorXd> Model::start_assembly() {
  std::map<std::string, Eigen::VectorXd> zeros;
  for (const std::string& u : unknown_names_) {
    field_residuals_[u] = Eigen::VectorXd::Zero(space(u).num_dofs());
    nonlinear_scratch_[u] = Eigen::VectorXd::Zero(space(u).num_dofs());
    zeros[u] = Eigen::VectorXd::Zero(space(u).num_dofs());
  }
  scaling_.reset(unknown_names_);
  return zeros;
}

// A kept brick's residual for an unknown it tests is swapped in by add_brick_share() at every assembly. One
// it does not test (a set that changes only when its terms are bound again, which zeroes them) is held
// empty, and brick_residual() gives the unknown's one zero vector for it: the energy books keep every brick,
// and a zero vector per brick and untested unknown was 2 MB at the paper's 240 x 80.
void Model::size_kept_residuals() {
  for (auto& [b, kept] : kept_residuals_) {
    const std::set<std::string>& tested = brick_states_[b]->tested;
    for (const std::string& u : unknown_names_) {
      const Eigen::Index size = tested.count(u) ? space(u).num_dofs() : 0;
      if (Eigen::VectorXd& r = kept[u]; r.size() != size) r = Eigen::VectorXd::Zero(size);
      if (Eigen::VectorXd& zero = zero_residuals_[u]; zero.size() != space(u).num_dofs())
        zero = Eigen::VectorXd::Zero(space(u).num_dofs());
    }
  }
}

// The current values of a term's fields, in its order.
std::vector<const Eigen::VectorXd*> Model::term_values(const BoundTerm& bt) const {
  std::vector<const Eigen::VectorXd*> values;
  for (const std::string& name : bt.field_names) values.push_back(&this->values(name));
  return values;
}

// A nonlinear brick's element loops at the current values: its residual added into `into` (per unknown it
// tests, which are returned) and, if asked, its tangent blocks.
std::set<std::string> Model::run_nonlinear_loops(int index, std::map<std::string, Eigen::VectorXd>& into, bool tangent,
                                                 ElementLoops& loops) {
  std::set<std::string> touched;
  for (BoundTerm& bt : brick_states_[index]->terms) {
    const std::vector<const Eigen::VectorXd*> values = term_values(bt);
    std::vector<Eigen::VectorXd*> outputs;
    for (const std::string& u : bt.test_unknowns) {
      outputs.push_back(&into.at(u));
      touched.insert(u);
    }
    loops.run([&] { bt.assembly->assemble(values, time_, outputs, tangent); });
  }
  return touched;
}

// A nonlinear brick's contribution, summed over the processes, into the nonlinear sums and the residual.
void Model::add_nonlinear_brick(int index, const System& s, std::map<std::string, Eigen::VectorXd>& brick_residual,
                                bool tangent, ElementLoops& loops) {
  const std::set<std::string> touched = run_nonlinear_loops(index, brick_residual, tangent, loops);
  loops.agree_on_failure(*bricks_[index]);
  for (const std::string& u : touched) {
    Eigen::VectorXd& share = brick_residual.at(u);  // distributed: of this process's elements
    processes::sum({share.data(), size_t(share.size())});
    nonlinear_scratch_.at(u) += share;  // assemble_nonlinear_rows() gives these at the same values
    add_brick_share(s, u, index, share);
  }
}

// A linear brick's tangent blocks, assembled again only when its constants changed since.
void Model::assemble_linear_tangent(int index, ElementLoops& loops) {
  LinearBrickCache& cache = brick_states_[index]->cache;
  if (!cache.tangent_valid)
    for (BoundTerm& bt : brick_states_[index]->terms) {
      const std::vector<const Eigen::VectorXd*> values = term_values(bt);
      const std::vector<Eigen::VectorXd*> outputs(bt.test_unknowns.size(), nullptr);
      const auto start = std::chrono::steady_clock::now();
      loops.run([&] { bt.assembly->assemble(values, time_, outputs, true); });
      jacobian_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
  loops.agree_on_failure(*bricks_[index]);
  if (!cache.tangent_valid) {
    cache.tangent_valid = true;
    ++linear_version_;
  }
}

// A linear brick's R0, assembled again when the time (a time-dependent brick's) or a datum it reads changed.
void Model::refresh_r0(int index, ElementLoops& loops) {
  const Brick& brick = *bricks_[index];
  BrickState& state = *brick_states_[index];
  LinearBrickCache& cache = state.cache;
  if (cache.r0_current(brick.time_dependent(), time_, [&](const std::string& name) { return field(name).version; }))
    return;
  cache.clear_r0();
  for (BoundTerm& bt : state.terms) {
    std::map<std::string, Eigen::VectorXd> zeros;
    std::vector<const Eigen::VectorXd*> values;
    for (const std::string& name : bt.field_names) {
      const bool coupled = std::count(bt.trial_fields.begin(), bt.trial_fields.end(), name) > 0;
      if (!coupled) {
        values.push_back(&this->values(name));
        continue;
      }
      zeros[name] = Eigen::VectorXd::Zero(space(name).num_dofs());
      values.push_back(&zeros[name]);
    }
    std::vector<Eigen::VectorXd*> outputs;
    for (const std::string& u : bt.test_unknowns) {
      auto [it, inserted] = cache.r0.try_emplace(u, Eigen::VectorXd::Zero(space(u).num_dofs()));
      outputs.push_back(&it->second);
    }
    loops.run([&] { bt.assembly->assemble(values, time_, outputs, false); });
    for (const std::string& name : bt.uncoupled_data) cache.r0_data_versions[name] = field(name).version;
  }
  loops.agree_on_failure(brick);
  cache.finish_r0(time_);
}

// A linear brick's residual, its blocks times the fields plus R0, into the field residuals.
void Model::add_linear_pieces(int index, const System& s, std::map<std::string, Eigen::VectorXd>& brick_residual) {
  BrickState& state = *brick_states_[index];
  const LinearBrickCache& cache = state.cache;
  // Its blocks and R0 stand: the geometry is not needed until the brick's data change (then the term
  // makes it again, and keeps it).
  for (BoundTerm& bt : state.terms) bt.assembly->release_geometry();
  // The pieces K_k x_k and R0 are measured one by one: they may cancel within the brick (k_e phi
  // against k_e phi_f), and round-off is relative to each of them. A brick's share of an unknown that is
  // a single product (R0 zero, no other coupling, the brick not kept) is added straight into the field's
  // residual, measured by the product itself: the same bits as its sum through the brick's zeroed
  // vector, without that vector's three passes (most bricks' shares are one product).
  const bool kept = kept_residuals_.count(index) > 0;
  std::map<std::string, int> pieces;
  for (const auto& [u, r0] : cache.r0)
    if (kept || !cache.r0_zero.at(u)) ++pieces[u];
  for (const BoundTerm& bt : state.terms)
    for (size_t k = 0; k < bt.trial_fields.size(); ++k)
      ++pieces[bt.field_names[bt.assembly->term().couplings()[k].test]];
  std::set<std::string> touched;
  for (const auto& [u, r0] : cache.r0) {
    if (!kept && cache.r0_zero.at(u)) continue;
    scaling_.measure(u, r0, global_of(s.layout, u), 0);
    brick_residual.at(u) += r0;
    touched.insert(u);
  }
  for (const BoundTerm& bt : state.terms)
    for (size_t k = 0; k < bt.trial_fields.size(); ++k) {
      const std::string& u = bt.field_names[bt.assembly->term().couplings()[k].test];
      const CsrView K = bt.assembly->block(int(k));
      const bool alone = !kept && pieces.at(u) == 1;
      scaling_.add_measured_product(u, K, this->values(bt.trial_fields[k]), global_of(s.layout, u),
                                    alone ? field_residuals_.at(u) : brick_residual.at(u));
      if (!alone) touched.insert(u);
    }
  for (const std::string& u : touched) add_brick_share(s, u, index, brick_residual.at(u));
}

// One brick's contribution to u: measured and added to the field's residual in one pass (the residual is
// bandwidth-bound), then kept by swapping it with the kept vector, whose old values are cleared.
void Model::add_brick_share(const System& s, const std::string& u, int index, Eigen::VectorXd& share) {
  scaling_.add_measured(u, share, global_of(s.layout, u), field_residuals_.at(u));
  if (const auto kept = kept_residuals_.find(index); kept != kept_residuals_.end()) kept->second.at(u).swap(share);
  share.setZero();
}

// The linear bricks' sum with the scheme's factors, made again when a block or a factor changed; the
// Jacobian is formed from it when asked for.
void Model::refresh_tangent(System& s) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<double> factors = affine_factors();
  if (s.linear_stamp != linear_version_ || s.linear_factors != factors) {
    refresh_linear_sum(s);
    s.linear_stamp = linear_version_;
    s.linear_factors = factors;
    s.linear_sum = ++linear_sums_;
  }
  s.jacobian_current = false;  // formed by jacobian() when asked for
  nonlinear_rows_at_ = {clock_, time_};
  jacobian_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Model::ResidualSnapshot Model::take_residual_snapshot() {
  require(!kept_residuals_in_snapshot_,
          "Model: take_residual_snapshot() while another snapshot holds the kept residuals");
  kept_residuals_in_snapshot_ = true;
  return {residual_, field_residuals_, std::exchange(kept_residuals_, {}), scaling_.residual_by_unknown(),
          scaling_.round_off_by_unknown()};
}

void Model::restore_residual(ResidualSnapshot snapshot) {
  require(snapshot.residual.size() == layout().size(), "restore_residual: the snapshot has ", snapshot.residual.size(),
          " residual entries, the system ", layout().size());
  residual_ = std::move(snapshot.residual);
  field_residuals_ = std::move(snapshot.field_residuals);
  kept_residuals_ = std::move(snapshot.kept_residuals);
  kept_residuals_in_snapshot_ = false;
  scaling_.restore(std::move(snapshot.residual_scales), std::move(snapshot.round_off_scales));
}

std::vector<ProblemBlock> Model::blocks() const {
  const DofLayout& l = layout();
  std::vector<ProblemBlock> blocks;
  int begin = 0;
  for (int f = 0; f < l.num_fields(); ++f) {  // a field's free dofs are numbered consecutively
    blocks.push_back({l.field_name(f), begin, l.num_free(f)});
    begin += l.num_free(f);
  }
  return blocks;
}

std::vector<double> Model::residual_scales() const { return scaling_.residual_scales(layout()); }
std::vector<double> Model::round_off_scales() const { return scaling_.round_off_scales(layout()); }

Eigen::VectorXd Model::free_values() const {
  const DofLayout& l = layout();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(l.size());
  for (const std::string& u : unknown_names_) l.copy_to_global(l.field_index(u), field(u).values, x);
  return x;
}

void Model::set_free_values(const Eigen::VectorXd& x) {
  const DofLayout& l = layout();
  for (const std::string& u : unknown_names_) {
    const auto global = l.global_indices(l.field_index(u));
    Field& f = field(u);
    f.version = ++clock_;
    for (int d = 0; d < int(global.size()); ++d)
      if (global[d] >= 0) f.values[d] = x[global[d]];
  }
}

void Model::add_to_free_values(const Eigen::VectorXd& step) {
  const DofLayout& l = layout();
  for (const std::string& u : unknown_names_) {
    Field& f = field(u);
    f.version = ++clock_;
    l.add_from_global(l.field_index(u), step, f.values);
  }
}

const CsrMatrix& Model::linear_jacobian() {
  System& s = system();
  require(s.linear_sum > 0, "Model: linear_jacobian() before assemble(true)");
  return s.matrix->matrix();
}

std::uint64_t Model::linear_jacobian_version() { return system().linear_sum; }

const std::vector<int>& Model::nonlinear_dofs() { return system().nonlinear_dofs; }

void Model::invalidate_caches() {
  for (auto& state : brick_states_) state->cache.invalidate();
  ++linear_version_;
}

std::int64_t Model::elements_assembled(int brick) const {
  require(brick >= 0 && brick < int(bricks_.size()), "Model: brick index ", brick, " out of range");
  const BrickState& state = *brick_states_[brick];
  std::int64_t n = state.retired_elements;
  for (const BoundTerm& bt : state.terms) n += bt.assembly->elements_assembled();
  return n;
}

void Model::add_diagnostic(const std::string& name, std::function<double(const Model&)> evaluate) {
  diagnostics_.emplace_back(name, std::move(evaluate));
}

std::map<std::string, double> Model::diagnostics() const {
  std::map<std::string, double> out;
  for (const auto& [name, evaluate] : diagnostics_) out[name] = evaluate(*this);
  return out;
}

}  // namespace pc
