#include "models/piezo/piezo_contact_recipe.hpp"

#include "assembly/error.hpp"
#include "bricks/conductive_foundation_brick.hpp"
#include "bricks/contact_status.hpp"
#include "bricks/dirichlet_brick.hpp"
#include "bricks/elasticity_brick.hpp"
#include "bricks/friction_brick.hpp"
#include "bricks/inertia_brick.hpp"
#include "bricks/laws/foundation_laws.hpp"
#include "bricks/laws/friction_laws.hpp"
#include "bricks/laws/normal_laws.hpp"
#include "bricks/normal_response_brick.hpp"
#include "bricks/permittivity_brick.hpp"
#include "bricks/piezoelectric_brick.hpp"
#include "bricks/viscosity_brick.hpp"

namespace pc {
namespace {

// Calls f with the normal law the spec names (the bricks are templates over laws).
template <class F>
void with_normal_law(const NormalLawSpec& s, F&& f) {
  if (s.type == "linear_damped") return f(LinearDampedResponse{s.c_nu});
  if (s.type == "power_damped") return f(PowerDampedResponse{s.c_nu, s.m});
  if (s.type == "normal_compliance") return f(NormalCompliance{s.c_nu, s.m, s.gap});
  fail("contact.law_normal: unknown law '", s.type, "' (known: linear_damped, power_damped, normal_compliance)");
}

template <class Normal>
void add_friction(Model& model, const FrictionLawSpec& s, const Normal& normal, const std::string& region) {
  if (s.type == "none") return;
  if (s.type == "viscous") {
    model.add_brick(std::make_shared<FrictionBrick<ViscousFriction>>(ViscousFriction{s.c_tau}, region));
  } else if (s.type == "coulomb") {
    model.add_brick(std::make_shared<FrictionBrick<RegularizedCoulomb, Normal>>(RegularizedCoulomb{s.mu, s.eps}, normal,
                                                                                region));
  } else if (s.type == "tresca") {
    model.add_brick(std::make_shared<FrictionBrick<RegularizedTresca>>(RegularizedTresca{s.g, s.eps}, region));
  } else {
    fail("contact.law_tangential: unknown law '", s.type, "' (known: none, viscous, coulomb, tresca)");
  }
}

template <class Normal>
void add_foundation(Model& model, const FoundationSpec& s, const Normal& normal, const std::string& region) {
  if (s.type == "insulated") return;
  if (s.type == "conductive") {
    model.add_brick(
        std::make_shared<ConductiveFoundationBrick<LinearConductance>>(LinearConductance{s.k_e, s.phi_f}, region));
  } else if (s.type == "pressure_activated") {
    using Law = PressureActivatedConductance<Normal>;
    model.add_brick(std::make_shared<ConductiveFoundationBrick<Law>>(Law{s.k_e, s.phi_f, s.p_ref, normal}, region));
  } else {
    fail("foundation: unknown type '", s.type, "' (known: insulated, conductive, pressure_activated)");
  }
}

}  // namespace

PiezoContactModel build_piezo_contact_model(const PiezoContactSpec& spec) {
  require(spec.mesh != nullptr, "recipe: no mesh");
  require(spec.order == 1 || spec.order == 2, "mesh.order must be 1 or 2, got ", spec.order);
  require(std::isfinite(spec.rho) && spec.rho >= 0, "material.rho must be finite and >= 0 (0: quasi-static), got ",
          spec.rho);
  require(spec.B.size() > 0, "material.elasticity_B is required");
  const bool electric = spec.E.size() > 0 || spec.beta.size() > 0;
  require(!electric || (spec.E.size() > 0 && spec.beta.size() > 0),
          "material: piezo_E and permittivity_beta go together (give both, or neither for a mechanical model)");
  const bool viscous = spec.A.size() > 0 && spec.A.norm() > 0;
  const bool inertia = spec.rho > 0;

  PiezoContactModel built;
  built.electric = electric;
  built.model = std::make_unique<Model>(spec.mesh);
  Model& m = *built.model;
  const int dim = spec.mesh->dim();
  m.add_unknown("v", std::make_shared<const FESpace>(spec.mesh, spec.order, dim));
  if (electric) m.add_unknown("phi", std::make_shared<const FESpace>(spec.mesh, spec.order, 1));
  built.scheme = make_time_scheme(spec.scheme);
  built.scheme->attach(m, inertia);

  m.set_constant("B", spec.B);
  m.add_brick(std::make_shared<ElasticityBrick>(spec.body));
  if (viscous) {
    m.set_constant("A", spec.A);
    m.add_brick(std::make_shared<ViscosityBrick>(spec.body));
  }
  if (inertia) {
    m.set_constant("rho", spec.rho);
    m.add_brick(std::make_shared<InertiaBrick>(spec.body));
  }
  if (electric) {
    m.set_constant("E", spec.E);
    m.set_constant("beta", spec.beta);
    m.add_brick(std::make_shared<PiezoelectricCouplingBrick>(spec.body));
    m.add_brick(std::make_shared<PermittivityBrick>(spec.body));
  }
  for (const std::string& region : spec.clamped)
    m.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("v", region)));
  for (const SurfaceLoad& t : spec.tractions) m.add_brick(std::make_shared<TractionBrick>(t.load, t.time, t.region));
  if (spec.body_force) m.add_brick(std::make_shared<BodyForceBrick>(spec.body_force, LoadTime::Varying, spec.body));
  if (electric) {
    for (const std::string& region : spec.grounded)
      m.add_brick(std::make_shared<DirichletBrick>(DirichletBrick::clamp("phi", region)));
    if (spec.volume_charge)
      m.add_brick(std::make_shared<VolumeChargeBrick>(spec.volume_charge, LoadTime::Varying, spec.body));
    for (const SurfaceLoad& q : spec.surface_charges)
      m.add_brick(std::make_shared<SurfaceChargeBrick>(q.load, q.time, q.region));
  }

  if (!spec.contact.empty()) {
    require(spec.mesh->has_region(spec.contact) && spec.mesh->region_kind(spec.contact) == RegionKind::Faces,
            "regions.contact: '", spec.contact, "' is not a face region of the mesh");
    const FaceRef first = spec.mesh->face_region(spec.contact).front();
    built.contact_normal = spec.mesh->face_normal(first);
    with_normal_law(spec.normal, [&](auto law) {
      using Law = decltype(law);
      m.add_brick(std::make_shared<NormalResponseBrick<Law>>(law, spec.contact));
      add_friction(m, spec.friction, law, spec.contact);
      if (electric) add_foundation(m, spec.foundation, law, spec.contact);
      built.contact_argument = law_uses_displacement<Law> ? "u" : "v";
      built.contact_pressure = [law](const double* argument, const double* normal, int d) {
        return contact_pressure(law, argument, normal, d);
      };
      const std::array<double, 3> normal = built.contact_normal;
      const std::string argument = built.contact_argument, region = spec.contact;
      const double threshold = spec.slip_threshold;
      m.add_diagnostic("contact_nodes_in_compression", [=](const Model& model) {
        return double(contact_status(law, model.space("v"), region, model.values(argument), model.values("v"),
                                     normal, threshold).in_contact);
      });
      m.add_diagnostic("contact_nodes_in_slip", [=](const Model& model) {
        return double(contact_status(law, model.space("v"), region, model.values(argument), model.values("v"),
                                     normal, threshold).sliding);
      });
    });
  } else {
    require(spec.foundation.type == "insulated", "foundation '", spec.foundation.type,
            "' needs a contact region (regions.contact)");
  }
  if (spec.extra_bricks) spec.extra_bricks(m);
  m.finalize();
  return built;
}

}  // namespace pc
