#include "models/piezo/piezo_contact_recipe.hpp"

#include "assembly/error.hpp"
#include "bricks/brick_registry.hpp"
#include "bricks/dirichlet_brick.hpp"
#include "bricks/elasticity_brick.hpp"
#include "bricks/inertia_brick.hpp"
#include "bricks/law_registry.hpp"
#include "bricks/permittivity_brick.hpp"
#include "bricks/piezoelectric_brick.hpp"
#include "bricks/viscosity_brick.hpp"

namespace pc {
namespace {

// The entry a choice names, its parameters checked and written into the model's constants.
template <class Factory>
const typename Registry<Factory>::Entry& choose(Model& model, const Registry<Factory>& registry, const Choice& choice) {
  const auto& entry = registry.at(choice.name, registry.key());
  model.set_constants(
      checked_values(entry.parameters, choice.parameters, message(registry.key(), " '", choice.name, "'")));
  return entry;
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
    for (const Electrode& electrode : spec.electrodes) add_electrode(m, electrode);
    if (spec.volume_charge)
      m.add_brick(std::make_shared<VolumeChargeBrick>(spec.volume_charge, LoadTime::Varying, spec.body));
    for (const SurfaceLoad& q : spec.surface_charges)
      m.add_brick(std::make_shared<SurfaceChargeBrick>(q.load, q.time, q.region));
  }

  require(electric || spec.electrodes.empty(),
          "electrodes: a purely mechanical body (no piezo_E, permittivity_beta) "
          "has no potential to drive");
  if (!spec.contact.empty()) {
    require(spec.mesh->has_region(spec.contact) && spec.mesh->region_kind(spec.contact) == RegionKind::Faces,
            "regions.contact: '", spec.contact, "' is not a face region of the mesh");
    ContactSurface surface{spec.contact, {}, {}};
    if (spec.foundation_motion && spec.foundation_motion->moves()) surface.fields.motion = spec.foundation_motion;
    const auto normal = choose(m, normal_law_registry(), spec.normal).create(surface);
    built.contact_bricks.push_back(m.add_brick(normal));
    if (auto friction = choose(m, friction_law_registry(), spec.friction).create(surface, normal))
      built.contact_bricks.push_back(m.add_brick(friction));
    m.keep_brick_residuals(built.contact_bricks);
    if (electric)
      if (auto foundation = choose(m, foundation_law_registry(), spec.foundation).create(surface, normal))
        m.add_brick(foundation);
    built.normal = normal;
    built.contact_argument = normal->argument_field(surface.fields);
    built.contact_nodes = contact_nodes(m.space("v"), spec.contact);
    const std::string argument = built.contact_argument;
    const double threshold = spec.slip_threshold;
    auto status = [normal, nodes = built.contact_nodes, argument, threshold](const Model& model) {
      return contact_status(*normal, model.space("v"), nodes, model.values(argument), model.values("v"), threshold,
                            model.time());
    };
    m.add_diagnostic("contact_nodes_in_compression",
                     [=](const Model& model) { return double(status(model).in_contact); });
    m.add_diagnostic("contact_nodes_in_slip", [=](const Model& model) { return double(status(model).sliding); });
  } else {
    require(!spec.foundation_motion || !spec.foundation_motion->moves(),
            "foundation motion: it needs a contact region (regions.contact)");
    require(spec.foundation.name == "insulated", "foundation '", spec.foundation.name,
            "' needs a contact region (regions.contact)");
  }
  for (const RegisteredBrick& b : spec.bricks) m.add_brick(choose(m, brick_registry(), b.brick).create(b.region));
  if (spec.extra_bricks) spec.extra_bricks(m);
  m.finalize();
  return built;
}

}  // namespace pc
