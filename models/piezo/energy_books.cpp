#include "models/piezo/energy_books.hpp"

#include <algorithm>
#include <cmath>

#include "assembly/error.hpp"
#include "bricks/boundary_dashpot_brick.hpp"
#include "bricks/dirichlet_brick.hpp"
#include "bricks/elasticity_brick.hpp"
#include "bricks/inertia_brick.hpp"
#include "bricks/permittivity_brick.hpp"
#include "bricks/piezoelectric_brick.hpp"
#include "bricks/source_bricks.hpp"
#include "bricks/uniform_value_brick.hpp"
#include "bricks/viscosity_brick.hpp"

namespace pc {
namespace {

// Sum of a * b over the dofs that the layout leaves free (free = true) or constrains (free = false).
double dot_on(const DofLayout& layout, const std::string& field, const Eigen::VectorXd& a, const Eigen::VectorXd& b,
              bool free) {
  const auto global = layout.global_indices(layout.field_index(field));
  double sum = 0;
  for (int d = 0; d < int(global.size()); ++d)
    if ((global[d] >= 0) == free) sum += a[d] * b[d];
  return sum;
}

}  // namespace

double EnergyBalance::scale() const {
  return std::max({std::abs(kinetic), std::abs(elastic), std::abs(electric), std::abs(numerical_dissipation),
                   std::abs(viscous_dissipation), std::abs(contact_dissipation), std::abs(coupling), std::abs(other),
                   std::abs(external_work), std::abs(boundary_work)});
}

EnergyBooks::EnergyBooks(PiezoContactModel& built, double initial_kinetic)
    : electric_(built.electric), initial_kinetic_(initial_kinetic) {
  Model& m = *built.model;
  std::vector<int> all;
  for (int b = 0; b < int(m.bricks().size()); ++b) {
    const Brick* brick = m.bricks()[b].get();
    Kind kind = Kind::Other;
    if (std::count(built.contact_bricks.begin(), built.contact_bricks.end(), b))
      kind = Kind::Contact;
    else if (dynamic_cast<const InertiaBrick*>(brick))
      kind = Kind::Inertia;
    else if (dynamic_cast<const ElasticityBrick*>(brick))
      kind = Kind::Elasticity;
    else if (dynamic_cast<const PermittivityBrick*>(brick))
      kind = Kind::Permittivity;
    else if (dynamic_cast<const PiezoelectricCouplingBrick*>(brick))
      kind = Kind::Coupling;
    else if (dynamic_cast<const ViscosityBrick*>(brick) || dynamic_cast<const BoundaryDashpotBrick*>(brick))
      kind = Kind::Dissipative;
    else if (dynamic_cast<const SourceBrick*>(brick))
      kind = Kind::External;
    else if (dynamic_cast<const DirichletBrick*>(brick) || dynamic_cast<const UniformValueBrick*>(brick))
      kind = Kind::None;
    kinds_.push_back(kind);
    bool tests_phi = false;
    for (const BrickTerm& bt : brick->terms())
      for (int t : bt.term->tests()) tests_phi = tests_phi || bt.term->fields()[size_t(t)].name == "phi";
    tests_phi_.push_back(tests_phi);
    all.push_back(b);
  }
  phi_residuals_.assign(kinds_.size(), Eigen::VectorXd());
  m.keep_brick_residuals(all);
}

void EnergyBooks::start(const Model& m) {
  time_ = m.time();
  v_ = m.values("v");
  u_ = m.values("u");
  phi_ = electric_ ? m.values("phi") : Eigen::VectorXd();
  totals_ = {};
  totals_.kinetic = initial_kinetic_;
  phi_residuals_.assign(kinds_.size(), Eigen::VectorXd());
  bool assembled = true;
  try {
    m.field_residual("v");
  } catch (const Error&) {
    assembled = false;
  }
  if (!assembled) {
    require(u_.cwiseAbs().maxCoeff() == 0 && !electric_,
            "energy books: the initial state has a displacement or a "
            "potential but the model has not been assembled at it (start the books after the initial solve)");
  } else {
    for (size_t b = 0; b < kinds_.size(); ++b) {
      if (kinds_[b] == Kind::Elasticity) totals_.elastic += 0.5 * u_.dot(m.brick_residual(int(b), "v"));
      if (electric_ && tests_phi_[b]) {
        phi_residuals_[b] = m.brick_residual(int(b), "phi");
        if (kinds_[b] == Kind::Permittivity) totals_.electric += 0.5 * phi_.dot(phi_residuals_[b]);
      }
    }
    if (electric_) phi_total_ = m.field_residual("phi");
  }
  if (electric_ && phi_total_.size() == 0) phi_total_ = Eigen::VectorXd::Zero(phi_.size());
  for (size_t b = 0; b < phi_residuals_.size(); ++b)
    if (electric_ && tests_phi_[b] && phi_residuals_[b].size() == 0)
      phi_residuals_[b] = Eigen::VectorXd::Zero(phi_.size());
  initial_stored_ = totals_.stored();
}

const EnergyBalance& EnergyBooks::record(const Model& m) {
  require(v_.size() > 0, "energy books: record() before start()");
  const double k = m.time() - time_;
  const Eigen::VectorXd& v = m.values("v");
  const Eigen::VectorXd& u = m.values("u");
  const Eigen::VectorXd dv = v - v_;
  double elastic = 0, electric = 0, elastic_power = 0, electric_power = 0;
  EnergyBalance& t = totals_;
  for (size_t b = 0; b < kinds_.size(); ++b) {
    if (kinds_[b] == Kind::None) continue;
    const Eigen::VectorXd& rv = m.brick_residual(int(b), "v");
    const double power_v = k * v.dot(rv);
    double power_phi = 0;
    if (electric_ && tests_phi_[b]) {  // a brick that does not test phi has no potential rows: no power
      const Eigen::VectorXd& rphi = m.brick_residual(int(b), "phi");
      power_phi = m.values("phi").dot(rphi - phi_residuals_[b]);
      if (kinds_[b] == Kind::Permittivity) electric += 0.5 * m.values("phi").dot(rphi);
      phi_residuals_[b] = rphi;
    }
    switch (kinds_[b]) {
      case Kind::Inertia: {
        // R = M dv / k: 1/2 dv.M dv = k/2 dv.R, and the rest of k v.R is the kinetic energy's change.
        const double numerical = 0.5 * k * dv.dot(rv);
        t.numerical_dissipation += numerical;
        t.kinetic += power_v - numerical;
        break;
      }
      case Kind::Elasticity:
        elastic += 0.5 * u.dot(rv);
        elastic_power += power_v;
        break;
      case Kind::Permittivity: electric_power += power_phi + power_v; break;
      case Kind::Coupling: t.coupling += power_v + power_phi; break;
      case Kind::Dissipative: t.viscous_dissipation += power_v + power_phi; break;
      case Kind::Contact: t.contact_dissipation += power_v + power_phi; break;
      case Kind::External: t.external_work -= power_v + power_phi; break;
      case Kind::Other: t.other += power_v + power_phi; break;
      case Kind::None: break;
    }
  }
  // What the stored energies did not take of their bricks' power is the scheme's numerical dissipation.
  t.numerical_dissipation += elastic_power - (elastic - t.elastic) + electric_power - (electric - t.electric);
  t.elastic = elastic;
  t.electric = electric;
  // The reactions' work: the constrained dofs' share of the whole residual's.
  const DofLayout& layout = m.layout();
  t.boundary_work += k * dot_on(layout, "v", v, m.field_residual("v"), false);
  if (electric_) {
    const Eigen::VectorXd& total = m.field_residual("phi");
    t.boundary_work += dot_on(layout, "phi", m.values("phi"), total - phi_total_, false);
    phi_total_ = total;
    phi_ = m.values("phi");
  }
  t.balance = t.stored() - initial_stored_ + t.numerical_dissipation + t.viscous_dissipation + t.contact_dissipation +
              t.coupling + t.other - t.external_work - t.boundary_work;
  time_ = m.time();
  v_ = v;
  u_ = u;
  return t;
}

std::vector<std::string> EnergyBooks::columns() {
  return {"E_kinetic",  "E_elastic", "E_electric", "W_numerical", "W_viscous", "W_contact",
          "W_coupling", "W_other",   "W_external", "W_boundary",  "E_balance"};
}

std::vector<double> EnergyBooks::row() const {
  const EnergyBalance& t = totals_;
  return {t.kinetic,
          t.elastic,
          t.electric,
          t.numerical_dissipation,
          t.viscous_dissipation,
          t.contact_dissipation,
          t.coupling,
          t.other,
          t.external_work,
          t.boundary_work,
          t.balance};
}

std::map<std::string, Eigen::VectorXd> EnergyBooks::state() const {
  std::map<std::string, Eigen::VectorXd> s;
  const std::vector<double> r = row();
  Eigen::VectorXd scalars(r.size() + 3);
  for (size_t i = 0; i < r.size(); ++i) scalars[Eigen::Index(i)] = r[i];
  scalars[Eigen::Index(r.size())] = time_;
  scalars[Eigen::Index(r.size() + 1)] = initial_stored_;
  scalars[Eigen::Index(r.size() + 2)] = initial_kinetic_;
  s["energy.scalars"] = scalars;
  s["energy.v"] = v_;
  s["energy.u"] = u_;
  if (electric_) {
    s["energy.phi"] = phi_;
    s["energy.phi_total"] = phi_total_;
    for (size_t b = 0; b < phi_residuals_.size(); ++b)
      if (tests_phi_[b]) s["energy.phi_residual." + std::to_string(b)] = phi_residuals_[b];
  }
  return s;
}

void EnergyBooks::restore(const std::map<std::string, Eigen::VectorXd>& s) {
  auto at = [&](const std::string& key) -> const Eigen::VectorXd& {
    const auto it = s.find(key);
    require(it != s.end(), "energy books: the saved state has no '", key, "'");
    return it->second;
  };
  const Eigen::VectorXd& scalars = at("energy.scalars");
  require(scalars.size() == Eigen::Index(columns().size() + 3), "energy books: the saved state has ", scalars.size(),
          " numbers, expected ", columns().size() + 3);
  EnergyBalance& t = totals_;
  double* fields[] = {&t.kinetic,
                      &t.elastic,
                      &t.electric,
                      &t.numerical_dissipation,
                      &t.viscous_dissipation,
                      &t.contact_dissipation,
                      &t.coupling,
                      &t.other,
                      &t.external_work,
                      &t.boundary_work,
                      &t.balance};
  for (size_t i = 0; i < std::size(fields); ++i) *fields[i] = scalars[Eigen::Index(i)];
  time_ = scalars[Eigen::Index(std::size(fields))];
  initial_stored_ = scalars[Eigen::Index(std::size(fields) + 1)];
  initial_kinetic_ = scalars[Eigen::Index(std::size(fields) + 2)];
  v_ = at("energy.v");
  u_ = at("energy.u");
  if (electric_) {
    phi_ = at("energy.phi");
    phi_total_ = at("energy.phi_total");
    for (size_t b = 0; b < phi_residuals_.size(); ++b)
      if (tests_phi_[b]) phi_residuals_[b] = at("energy.phi_residual." + std::to_string(b));
  }
}

}  // namespace pc
