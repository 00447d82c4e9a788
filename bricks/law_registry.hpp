#pragma once
// The registries of contact laws that a scene can name: normal laws (contact.law_normal), friction laws
// (contact.law_tangential) and foundation laws (foundation.<name>.type). Each entry carries the law's
// declared parameters and a factory that makes its brick over a contact surface, reading the parameters
// from the model's constants. A new law that scenes can name is one file:
//
//   struct MyResponse { double c_nu = 0; static constexpr auto parameters() { ... } template <class S> ... };
//   PC_REGISTER_NORMAL_LAW(MyResponse, "my_response", "p_nu = ...")
//
// ("none" friction and the "insulated" foundation are entries whose factory makes no brick.)
#include <functional>
#include <memory>
#include <string>

#include "assembly/registry.hpp"
#include "bricks/bound_law.hpp"
#include "bricks/conductive_foundation_brick.hpp"
#include "bricks/friction_brick.hpp"
#include "bricks/normal_response_brick.hpp"

namespace pc {

// Where a contact law's brick acts and what it reads.
struct ContactSurface {
  std::string region = "contact";
  ContactFields fields;
  ParameterNames names;
};

using NormalLawFactory = std::function<std::shared_ptr<NormalContactBrick>(const ContactSurface&)>;
// `normal` is the surface's normal brick; a factory whose law reads no pressure ignores it. May return
// null: the law adds no brick.
using PairedLawFactory =
    std::function<std::shared_ptr<Brick>(const ContactSurface&, const std::shared_ptr<const NormalPressure>& normal)>;

Registry<NormalLawFactory>& normal_law_registry();
Registry<PairedLawFactory>& friction_law_registry();
Registry<PairedLawFactory>& foundation_law_registry();

template <class Law> Registry<NormalLawFactory>::Entry normal_law_entry(std::string name, std::string doc) {
  return {std::move(name), std::move(doc), parameter_declarations<Law>(), [](const ContactSurface& s) {
            return std::make_shared<NormalResponseBrick<Law>>(s.region, s.fields, s.names);
          }};
}

// Friction (FrictionBrick) or foundation (ConductiveFoundationBrick) entry of a law.
template <template <class> class PairedBrick, class Law>
Registry<PairedLawFactory>::Entry paired_law_entry(std::string name, std::string doc) {
  return {std::move(name), std::move(doc), parameter_declarations<Law>(),
          [](const ContactSurface& s, const std::shared_ptr<const NormalPressure>& normal) -> std::shared_ptr<Brick> {
            return std::make_shared<PairedBrick<Law>>(s.region, law_uses_normal_pressure<Law> ? normal : nullptr,
                                                      s.fields, s.names);
          }};
}

// An entry that adds no brick ("none" friction, the "insulated" foundation).
Registry<PairedLawFactory>::Entry no_brick_entry(std::string name, std::string doc);

}  // namespace pc

#define PC_REGISTER_NORMAL_LAW(Law, name, doc) \
  PC_REGISTER(pc::normal_law_registry(), pc::normal_law_entry<Law>(name, doc))
#define PC_REGISTER_FRICTION_LAW(Law, name, doc) \
  PC_REGISTER(pc::friction_law_registry(), pc::paired_law_entry<pc::FrictionBrick, Law>(name, doc))
#define PC_REGISTER_FOUNDATION_LAW(Law, name, doc) \
  PC_REGISTER(pc::foundation_law_registry(), pc::paired_law_entry<pc::ConductiveFoundationBrick, Law>(name, doc))
