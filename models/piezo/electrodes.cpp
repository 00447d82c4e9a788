#include "models/piezo/electrodes.hpp"

#include <memory>

#include "assembly/error.hpp"
#include "bricks/dirichlet_brick.hpp"
#include "bricks/source_bricks.hpp"
#include "bricks/uniform_value_brick.hpp"

namespace pc {

Electrode floating_electrode(std::string name, std::string region, TimeFunction charge) {
  Electrode e;
  e.name = std::move(name);
  e.region = std::move(region);
  e.circuit = ElectrodeCircuit::Floating;
  e.charge = std::move(charge);
  return e;
}

void add_electrode(Model& model, const Electrode& electrode, const std::string& potential) {
  require(!electrode.name.empty(), "electrode on region '", electrode.region, "': it needs a name");
  require(model.mesh().has_region(electrode.region) && model.mesh().region_kind(electrode.region) == RegionKind::Faces,
          "electrode '", electrode.name, "': '", electrode.region, "' is not a face region of the mesh");
  if (electrode.circuit == ElectrodeCircuit::Driven) {
    const TimeFunction voltage = electrode.voltage;
    model.add_brick(std::make_shared<DirichletBrick>(
        potential, electrode.region, std::vector<int>{},
        [voltage](const double*, double t, double* out) { out[0] = voltage.value(t); }, voltage.varies()));
    return;
  }
  model.add_brick(std::make_shared<UniformValueBrick>(potential, electrode.region));
  const TimeFunction charge = electrode.charge;
  if (!charge.varies() && charge.value(0) == 0) return;  // an open circuit: the summed residual is the condition
  const double area = model.mesh().region_measure(electrode.region);
  require(area > 0, "electrode '", electrode.name, "': region '", electrode.region, "' has no area");
  // Q = -integral D . n over the electrode, and the surface charge brick's q_b is D . n.
  model.add_brick(std::make_shared<SurfaceChargeBrick>(
      [charge, area](const double*, double t, double* out) { out[0] = -charge.value(t) / area; },
      charge.varies() ? LoadTime::Varying : LoadTime::Constant, electrode.region, potential));
}

double electrode_potential(const Model& model, const std::string& region, const std::string& potential) {
  const std::vector<int> dofs = model.space(potential).dofs_on(region);
  require(!dofs.empty(), "electrode_potential: region '", region, "' has no dof of '", potential, "'");
  return model.values(potential)[dofs.front()];
}

double electrode_charge(const Model& model, const std::string& region, const std::string& potential) {
  const Eigen::VectorXd& reaction = model.field_residual(potential);
  double charge = 0;
  for (int dof : model.space(potential).dofs_on(region)) charge += reaction[dof];
  return charge;
}

ElectrodeMeter::ElectrodeMeter(std::vector<Electrode> electrodes, std::string potential)
    : electrodes_(std::move(electrodes)), potential_(std::move(potential)) {}

std::vector<ElectrodeReading> ElectrodeMeter::read(const Model& model) {
  const double t = model.time();
  std::vector<ElectrodeReading> readings;
  std::vector<double> charges;
  for (size_t i = 0; i < electrodes_.size(); ++i) {
    ElectrodeReading r;
    const Electrode& e = electrodes_[i];
    if (e.circuit == ElectrodeCircuit::Driven) {
      r.voltage = e.voltage.value(t);
      r.charge = electrode_charge(model, e.region, potential_);
    } else {
      r.voltage = electrode_potential(model, e.region, potential_);
      r.charge = e.charge.value(t);
    }
    if (has_previous_ && t > previous_time_) r.current = (r.charge - previous_charge_[i]) / (t - previous_time_);
    charges.push_back(r.charge);
    readings.push_back(r);
  }
  previous_charge_ = std::move(charges);
  previous_time_ = t;
  has_previous_ = true;
  return readings;
}

std::vector<std::string> ElectrodeMeter::columns() const {
  std::vector<std::string> names;
  for (const Electrode& e : electrodes_)
    for (const char* quantity : {"V_", "Q_", "I_"}) names.push_back(quantity + e.name);
  return names;
}

std::map<std::string, double> ElectrodeMeter::state() const {
  std::map<std::string, double> state;
  if (!has_previous_) return state;
  state["electrodes.time"] = previous_time_;
  for (size_t i = 0; i < electrodes_.size(); ++i) state["electrodes.Q_" + electrodes_[i].name] = previous_charge_[i];
  return state;
}

void ElectrodeMeter::restore(const std::map<std::string, double>& state) {
  has_previous_ = state.count("electrodes.time") > 0;
  if (!has_previous_) return;
  previous_time_ = state.at("electrodes.time");
  previous_charge_.clear();
  for (const Electrode& e : electrodes_) {
    const auto it = state.find("electrodes.Q_" + e.name);
    require(it != state.end(), "electrodes: the saved state has no charge of electrode '", e.name, "'");
    previous_charge_.push_back(it->second);
  }
}

}  // namespace pc
