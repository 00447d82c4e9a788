#pragma once
// Electrodes on a face region, and what each reports, its voltage, charge and current:
// - driven: phi = V(t) (a Dirichlet condition with a time function); the charge is measured;
// - floating: phi takes one unknown value V over the region (UniformValueBrick) and the electrode holds
//   a given net charge Q(t), 0 for an open circuit (a sensor, an open-circuit measurement); V is measured.
//   The charge is a uniform surface charge -Q(t) / |region| on the region (SurfaceChargeBrick): since the
//   region's residuals are summed into one equation, only its total matters.
//
// The charge is the reaction of the potential condition: the electric residual summed over the
// electrode's dofs. With R_phi(psi) = -integral D . grad psi (sources aside) and the electrode's shape
// functions summing to 1 on it, that sum is -integral over the electrode of D . n, the free charge on the
// conductor side of the interface (D vanishes in the metal, n points out of the body). It is exact for the
// discrete solution: no flux is recovered from gradients. The current I = dQ/dt is the backward
// difference over the step, the scheme's own rate, so that the work of an electrode, sum V_n I_n k_n,
// is what the discrete balance of energy holds.
#include <map>
#include <string>
#include <vector>

#include "assembly/time_function.hpp"
#include "models/model.hpp"

namespace pc {

enum class ElectrodeCircuit { Driven, Floating };

struct Electrode {
  std::string name;      // of the history columns: V_<name>, Q_<name>, I_<name>
  std::string region;    // a face region of the mesh
  TimeFunction voltage;  // driven: the prescribed V(t)
  ElectrodeCircuit circuit = ElectrodeCircuit::Driven;
  TimeFunction charge = TimeFunction::constant(0);  // floating: the net charge Q(t) it holds (0: open circuit)
};

// A floating electrode on `region` holding `charge` (default: none, an open circuit).
Electrode floating_electrode(std::string name, std::string region, TimeFunction charge = TimeFunction::constant(0));

// Adds the electrode's bricks to a model not finalized yet: driven, phi = V(t) (a DirichletBrick on
// `potential`); floating, one value of phi over the region and, for a charge that is not identically 0, its
// surface charge.
void add_electrode(Model& model, const Electrode& electrode, const std::string& potential = "phi");

// The potential of a floating electrode (of its region's first dof; all of them hold it).
double electrode_potential(const Model& model, const std::string& region, const std::string& potential = "phi");

// The charge on a face region where the potential is prescribed, from the model's last residual. (On a
// floating electrode it is the residual of its one equation, 0 to Newton's tolerance: its charge is the
// given one.)
double electrode_charge(const Model& model, const std::string& region, const std::string& potential = "phi");

struct ElectrodeReading {
  double voltage = 0, charge = 0, current = 0;
};

// Reads the electrodes after each accepted state: V and Q (one given, the other measured), and I = (Q - Q_previous) /
// (t - t_previous) (0 at the first reading). Its previous readings can be saved and restored so a resumed run continues
// the current exactly.
class ElectrodeMeter {
 public:
  ElectrodeMeter(std::vector<Electrode> electrodes, std::string potential = "phi");
  const std::vector<Electrode>& electrodes() const { return electrodes_; }
  // One reading per electrode, in the order given; remembers the charges and the time for the next one.
  std::vector<ElectrodeReading> read(const Model& model);
  // The history columns V_<name>, Q_<name>, I_<name> of each electrode.
  std::vector<std::string> columns() const;
  // The state the next reading's current depends on, by name, and its restoration.
  std::map<std::string, double> state() const;
  void restore(const std::map<std::string, double>& state);

 private:
  std::vector<Electrode> electrodes_;
  std::string potential_;
  std::vector<double> previous_charge_;
  double previous_time_ = 0;
  bool has_previous_ = false;
};

}  // namespace pc
