#pragma once
// What a friction or foundation brick reads of the normal brick it is paired with: the contact pressure
// p_nu as a function of the normal component r of the field the normal law reads (v.n, or u.n for a
// compliance law). The normal law is given once, to the normal brick; a Coulomb friction brick or a
// pressure-activated foundation brick holds that brick and evaluates its law, whatever law it is.
//
// The law is reached through a virtual call with its value and slope; at(), templated on the scalar,
// rebuilds p_nu by the chain rule, so kernels keep exact first derivatives with Dual (all that Newton's
// tangent needs) and the pairing needs no template over every normal law.
#include <string>
#include <vector>

#include "assembly/dual.hpp"
#include "assembly/error.hpp"
#include "bricks/brick.hpp"
#include "bricks/contact_kinematics.hpp"

namespace pc {

class NormalPressure {
 public:
  virtual ~NormalPressure() = default;
  // p_nu(r) and, into slope, dp_nu/dr (right-sided at a kink, like the laws themselves).
  virtual double pressure(double r, double* slope) const = 0;
  // Whether the law reads the displacement u (normal compliance) rather than the velocity v.
  virtual bool reads_displacement() const = 0;
  // The model constants the law reads: a brick that reads p_nu depends on them too.
  virtual std::vector<std::string> law_data() const = 0;
  // The face region the pressure acts on; a brick paired with it must integrate over the same one.
  virtual const std::string& region() const = 0;
  // The foundation's motion the law reads the body's relative to (null: at rest).
  virtual const FoundationMotion* motion() const = 0;
  // The model field the law reads.
  const std::string& argument_field(const ContactFields& names) const {
    return reads_displacement() ? names.displacement : names.velocity;
  }

  // p_nu at a point and time t from the argument's value there and the outward unit normal, relative
  // to the foundation's motion.
  template <class S> S at(const S* argument, const double* normal, int dim, double t) const {
    const auto relative = relative_to_foundation(argument, motion(), reads_displacement(), t, dim);
    const S r = normal_part(relative.data(), normal, dim);
    double slope = 0;
    const double p = pressure(value_of(r), &slope);
    return chain_rule(r, p, slope);
  }
};

// A normal contact brick: a brick that is also the NormalPressure of its surface (NormalResponseBrick<Law>
// for any law); what the normal-law registry makes, so that friction and foundation bricks can pair with it.
class NormalContactBrick : public Brick, public NormalPressure {};

// A brick that reads p_nu depends on the normal law's constants as well as on its own law's.
inline std::vector<std::string> paired_data(std::vector<std::string> law_data, const NormalPressure* normal) {
  if (normal)
    for (const std::string& name : normal->law_data()) law_data.push_back(name);
  return law_data;
}

// A law that reads the contact pressure needs the normal brick of its surface, and only such a law takes one.
inline void require_pairing(bool reads_pressure, const NormalPressure* normal, const std::string& brick,
                            const std::string& region) {
  require(reads_pressure == (normal != nullptr), "brick '", brick, "': ",
          reads_pressure ? "the law reads the contact pressure: pair it with the normal brick of its surface"
                         : "the law reads no contact pressure: it takes no normal brick");
  require(!normal || normal->region() == region, "brick '", brick, "' is paired with the normal brick of region '",
          normal ? normal->region() : "", "': the pressure it reads must act on its own region '", region, "'");
}

}  // namespace pc
