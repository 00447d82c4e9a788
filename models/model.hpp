#pragma once
// The Model: named fields, named constants and a stack of bricks, assembled into one monolithic system
// on the free dofs of its unknowns (GetFEM's model object).
//
// Fields are unknowns (solved for), data fields (history, given fields) and affine fields
// `name = factor * base + sum c_i history_i` of an unknown, whose factor and coefficients the time scheme
// sets (u = k v + u_prev, a = v / k - v_prev / k). A brick's tangent with respect to an affine field is added into the
// base unknown's columns times the factor, so a new step size never re-runs an element loop.
//
// Caching: a linear brick's tangent blocks are assembled once per change of the constants it reads; its
// residual is sum_k K_k x_k + R0, a mat-vec, where R0 (the residual with the coupled fields at zero) is
// refreshed when a data field it reads or, for time-dependent bricks, the time changes. The sum of the
// linear blocks with the scheme's factors is kept, so each Newton iteration only re-assembles the
// nonlinear bricks (for the paper, those on the contact boundary).
//
// The system is what Newton solves (models/solvers/nonlinear_problem.hpp): its free values are the
// unknowns' free dofs, one block per unknown.
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "assembly/dof_layout.hpp"
#include "assembly/fe_space.hpp"
#include "assembly/parameters.hpp"
#include "assembly/system_matrix.hpp"
#include "assembly/term_assembly.hpp"
#include "bricks/brick.hpp"
#include "models/residual_scaling.hpp"
#include "models/solvers/nonlinear_problem.hpp"

namespace pc {

enum class FieldKind { Unknown, Data, Affine };

class Model : public DataView, public NonlinearProblem {
 public:
  explicit Model(std::shared_ptr<const Mesh> mesh);
  ~Model() override;
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  const Mesh& mesh() const { return *mesh_; }
  std::shared_ptr<const Mesh> mesh_ptr() const { return mesh_; }

  // ---- fields -----------------------------------------------------------------------------------
  void add_unknown(const std::string& name, std::shared_ptr<const FESpace> space);
  // Initial values default to zero.
  void add_data_field(const std::string& name, std::shared_ptr<const FESpace> space, Eigen::VectorXd values = {});
  // name = factor * base + sum_i c_i * history_i, with base an unknown and history data fields of the
  // same space (e.g. u = k v + u_prev). Factor 1 and coefficients 0 until set_affine.
  void add_affine_field(const std::string& name, const std::string& base, std::vector<std::string> history = {});
  void set_affine(const std::string& name, double factor, std::vector<double> history_coefficients);
  double affine_factor(const std::string& name) const;
  // An affine field's history coefficients, in the order of its history fields (empty for other fields).
  std::vector<double> affine_coefficients(const std::string& name) const;
  // An affine field's history fields, in order (empty for other fields).
  std::vector<std::string> affine_history(const std::string& name) const;
  const std::string& affine_base(const std::string& name) const;  // the unknown an affine field is of

  bool has_field(const std::string& name) const { return fields_.count(name) > 0; }
  FieldKind field_kind(const std::string& name) const;
  const FESpace& space(const std::string& name) const;
  std::shared_ptr<const FESpace> space_ptr(const std::string& name) const;
  // Current values (an affine field's are computed on the fly).
  const Eigen::VectorXd& values(const std::string& name) const;
  // Sets an unknown's or a data field's values (a data field's change refreshes what reads it).
  void set_values(const std::string& name, const Eigen::VectorXd& values);
  std::vector<std::string> unknowns() const { return unknown_names_; }
  // Whether a brick brought this unknown (Brick::own_unknowns, e.g. a Lagrange multiplier on a region).
  bool is_brick_unknown(const std::string& name) const { return restricted_.count(name) > 0; }
  // An unknown's Dirichlet-constrained (eliminated) dofs, sorted; known from finalize() on.
  std::vector<int> constrained_dofs(const std::string& unknown) const;
  std::vector<std::string> field_names() const;

  // ---- constants --------------------------------------------------------------------------------
  void set_constant(const std::string& name, Eigen::MatrixXd value);
  void set_constant(const std::string& name, double value);
  // Scalar constants by name, e.g. a law's parameters: set_constants(law_values(LinearDampedResponse{1e12})).
  void set_constants(const ParameterValues& values);
  bool has_constant(const std::string& name) const { return constants_.count(name) > 0; }
  const Eigen::MatrixXd& constant(const std::string& name) const override;

  // ---- bricks -----------------------------------------------------------------------------------
  // Checks that every field, datum and region the brick names exists and that it differentiates
  // only unknowns and affine fields. Returns the brick's index.
  // A constant belongs to the first brick that reads it (a law's parameters to its brick): a brick that
  // finds one set to a new value since its owner read it would change the owner's parameter too (a
  // foundation law or a plugin brick declaring c_nu), and is refused naming both bricks. Reading it as it
  // stands (a friction brick reads its normal brick's c_nu), the owner itself, or setting it again to the
  // value it has are accepted.
  int add_brick(std::shared_ptr<Brick> brick);
  const std::vector<std::shared_ptr<Brick>>& bricks() const { return bricks_; }
  // Binds every term to its region (pattern, geometry), applies the Dirichlet bricks and refuses a
  // field that no brick uses.
  void finalize();
  bool finalized() const { return finalized_; }

  // ---- time -------------------------------------------------------------------------------------
  double time() const { return time_; }
  void set_time(double t) { time_ = t; }
  // Writes the Dirichlet values at the current time into the unknowns' constrained dofs, and gives the
  // dofs of each uniform-value region their group's value (that of its first dof).
  void apply_dirichlet();

  // ---- the system -------------------------------------------------------------------------------
  // Unknowns excluded from the system keep their values (e.g. v while the initial potential is found).
  void set_frozen(const std::vector<std::string>& unknowns);
  const DofLayout& layout() const;
  // Assembles the residual on the free dofs and, if asked, the tangent: the linear bricks' sum and the
  // nonlinear bricks' blocks, of which jacobian() forms the Jacobian when it is first asked for (the
  // condensed solves never ask: nonlinear_part() is all they read).
  void assemble(bool tangent) override;
  const Eigen::VectorXd& residual() const override { return residual_; }
  const CsrMatrix& jacobian() const override;
  void nonlinear_part(std::vector<double>& values) override;
  // The nonlinear bricks alone, residual and tangent, at the current values (the linear bricks' data, the
  // constants and the scheme's factors as at the last assemble(true)): the contact boundary's element
  // loops, nothing of size the whole system but a scatter. residual(), the field and kept brick residuals
  // and the scales stay those of the last assemble(). False when distributed (each process holds a share).
  bool assemble_nonlinear_rows(Eigen::VectorXd& rows) override;
  // The Jacobian's share of assembly: the linear bricks' tangent element loops (once per change of their
  // data, in whichever assemble() needs them first: their residual is a mat-vec with them), their sum with
  // the scheme's factors, and the Jacobian formed from it with the nonlinear blocks. The nonlinear
  // bricks' element loops compute residual and tangent in one pass and count as the residual's.
  double jacobian_assembly_seconds() const override { return jacobian_seconds_; }
  // The sum of the linear bricks' blocks with the current factors (the Jacobian without the nonlinear
  // bricks), with the Jacobian's pattern; its version changes only when that sum was recomputed (a new
  // step size, a changed datum), so a factorisation of it can be kept across Newton iterations and steps.
  const CsrMatrix& linear_jacobian() override;
  std::uint64_t linear_jacobian_version() override;
  // The free dofs (global numbering) whose rows or columns the nonlinear bricks fill: J - linear_jacobian()
  // vanishes outside these rows and columns (for the paper, the contact boundary's dofs).
  const std::vector<int>& nonlinear_dofs() override;
  // The residual's derivative along a change of data fields (e.g. the time scheme's history u_prev, v_prev:
  // `change` maps each to its direction), on the free dofs as residual(): dR/dd . change. It is the
  // linear bricks' blocks times the change of the affine fields they are coupled to (an affine field moves
  // by sum_i c_i change_i over its history), with no element loop, and exact (a linear brick's residual is
  // linear in its fields) where a difference of residuals is off by its step. False, `out` untouched, when
  // the blocks do not give it: a nonlinear brick reads a changed field (a datum or an affine field of one),
  // a linear brick reads one without being coupled to it (its R0 moves), its blocks are not those of its
  // current constants, or the model is distributed. A difference of residuals does then.
  bool residual_derivative(const std::map<std::string, Eigen::VectorXd>& change, Eigen::VectorXd& out) const;
  // Residual of one unknown in its field numbering (all dofs, constrained ones included): reactions.
  const Eigen::VectorXd& field_residual(const std::string& unknown) const;
  // Keeps these bricks' own residuals at every assembly from now on, so that what one brick does can be
  // read (the force a contact brick exerts, the power it absorbs). brick_residual() is the kept brick's
  // contribution to field_residual(unknown) at the last assembly: zeros for an unknown it does not test.
  void keep_brick_residuals(const std::vector<int>& bricks);
  const Eigen::VectorXd& brick_residual(int brick, const std::string& unknown) const;
  // The unknowns, in the layout's order.
  std::vector<ProblemBlock> blocks() const override;
  // What assemble(false) leaves behind (the residual, its per-field and kept-brick pieces, its scales),
  // kept so that a caller who assembles at perturbed values (a finite difference) can put the last
  // assembly's back without assembling again. Valid only while the values it was assembled at stand.
  // The kept bricks' residuals are moved into the snapshot, not copied (there is one per kept brick and
  // unknown, the largest part of it): until restore_residual(), assemblies keep none, and
  // brick_residual() refuses.
  struct ResidualSnapshot {
    Eigen::VectorXd residual;
    std::map<std::string, Eigen::VectorXd> field_residuals;
    std::map<int, std::map<std::string, Eigen::VectorXd>> kept_residuals;
    std::map<std::string, double> residual_scales, round_off_scales;
  };
  ResidualSnapshot take_residual_snapshot();
  void restore_residual(ResidualSnapshot snapshot);
  // Per unknown, the norm (on free dofs) of the largest single brick contribution to the last residual:
  // the scale of the forces that balance, Newton's reference.
  std::vector<double> residual_scales() const override;
  // Per unknown, the same with each linear piece K x measured by the norm of |K| |x| (rows
  // sum_j |K_ij| |x_j|) instead of K x: the size of the products before they cancel, which sets the
  // residual's round-off floor (nonlinear bricks and the R0 pieces are measured by their net size).
  std::vector<double> round_off_scales() const override;
  // Unknowns on free dofs, and their update x <- x + step.
  Eigen::VectorXd free_values() const override;
  void set_free_values(const Eigen::VectorXd& x) override;
  void add_to_free_values(const Eigen::VectorXd& step) override;

  // Distributed over several processes (assembly/processes.hpp): one flag per mesh cell, set on the cells
  // whose elements this process assembles (METIS's partition, made by finalize()); empty on one process.
  // Residuals and reactions are the whole model's on every process; the Jacobian is this process's share
  // of the sum that MUMPS factorises.
  const std::vector<char>& owned_cells() const { return owned_cells_; }

  // Drops every cache, so that the next assemble() re-runs every element loop (to compare with cached
  // assembly, or after changing something the model cannot see).
  void invalidate_caches();

  // ---- introspection (tests, reports) ------------------------------------------------------------
  // Element loops run so far by each brick's terms: lets tests see what a cache avoided.
  std::int64_t elements_assembled(int brick) const;
  // Named diagnostics evaluated after each solve (e.g. contact points in compression).
  void add_diagnostic(const std::string& name, std::function<double(const Model&)> evaluate);
  std::map<std::string, double> diagnostics() const override;

 private:
  struct Field;
  struct BoundTerm;
  struct BrickState;
  struct System;
  struct ElementLoops;
  // The brick that declared a constant it reads (the first to read it), and the constant's version then.
  struct ParameterOwner {
    std::string brick;
    std::uint64_t version = 0;
  };

  Field& field(const std::string& name);
  const Field& field(const std::string& name) const;
  void check_brick(const Brick& brick) const;
  void claim_parameters(const Brick& brick, const std::map<std::string, std::uint64_t>& versions);
  void collect_uniform_values();  // the uniform-value regions' dofs, merged into disjoint groups
  void bind_brick(int index);
  System& system();
  void refresh_brick(int index);
  void refresh_linear_sum(System& s);
  // add(handle, block, factor) for each block of the linear bricks, or of the others.
  template <class Add> void for_each_block(const System& s, bool linear, Add&& add) const;
  void require_factors_of_last_tangent(const System& s, const char* what) const;
  // The phases of assemble() (and, for a nonlinear brick's element loops, of assemble_nonlinear_rows()).
  std::map<std::string, Eigen::VectorXd> start_assembly();
  void size_kept_residuals();
  std::vector<const Eigen::VectorXd*> term_values(const BoundTerm& bt) const;
  std::set<std::string> run_nonlinear_loops(int index, std::map<std::string, Eigen::VectorXd>& into, bool tangent,
                                            ElementLoops& loops);
  void add_nonlinear_brick(int index, const System& s, std::map<std::string, Eigen::VectorXd>& brick_residual,
                           bool tangent, ElementLoops& loops);
  void assemble_linear_tangent(int index, ElementLoops& loops);
  void refresh_r0(int index, ElementLoops& loops);
  void add_linear_pieces(int index, const System& s, std::map<std::string, Eigen::VectorXd>& brick_residual);
  void add_brick_share(const System& s, const std::string& u, int index, Eigen::VectorXd& share);
  void refresh_tangent(System& s);
  std::vector<double> affine_factors() const;

  std::shared_ptr<const Mesh> mesh_;
  // The geometry and block patterns the bricks' terms share (one copy for all body terms).
  std::unique_ptr<TermAssemblyCache> assembly_cache_;
  std::map<std::string, std::unique_ptr<Field>> fields_;
  std::vector<std::string> unknown_names_;
  std::map<std::string, std::pair<Eigen::MatrixXd, std::uint64_t>> constants_;
  std::vector<std::shared_ptr<Brick>> bricks_;
  std::vector<std::unique_ptr<BrickState>> brick_states_;
  std::map<std::string, std::vector<int>> constrained_;  // per unknown: Dirichlet dofs
  std::vector<DirichletCondition> dirichlet_;
  std::map<std::string, std::vector<std::vector<int>>> tied_;  // per unknown: groups of one value
  std::map<std::string, BrickUnknown> restricted_;             // bricks' own unknowns, by name
  std::vector<std::string> frozen_;
  std::vector<char> owned_cells_;
  std::map<std::vector<std::string>, std::unique_ptr<System>> systems_;
  std::vector<std::pair<std::string, std::function<double(const Model&)>>> diagnostics_;
  std::map<std::string, Eigen::VectorXd> field_residuals_;
  std::map<int, std::map<std::string, Eigen::VectorXd>> kept_residuals_;  // per kept brick, per unknown
  std::map<std::string, Eigen::VectorXd> zero_residuals_;   // a kept brick's for an unknown it does not test
  bool kept_residuals_in_snapshot_ = false;                 // take_residual_snapshot() holds them
  ResidualScaling scaling_;                                 // of the last assembly
  std::map<std::string, ParameterOwner> parameter_owners_;  // per constant a brick reads
  // Per unknown, the nonlinear bricks' residual at the last assemble(true) or assemble_nonlinear_rows(), and
  // the values' version (clock_) and time it is of.
  std::map<std::string, Eigen::VectorXd> nonlinear_scratch_;
  std::pair<std::uint64_t, double> nonlinear_rows_at_{~std::uint64_t(0), 0.0};
  Eigen::VectorXd residual_;
  std::uint64_t clock_ = 0;           // version source for constants and data fields
  std::uint64_t linear_version_ = 1;  // changes when a linear brick's blocks change
  std::uint64_t linear_sums_ = 0;     // counts recomputations of the linear sum
  double time_ = 0;
  mutable double jacobian_seconds_ = 0;  // jacobian() forms the Jacobian on demand
  bool finalized_ = false;
};

}  // namespace pc
