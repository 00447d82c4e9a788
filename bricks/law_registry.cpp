#include "bricks/law_registry.hpp"

#include "bricks/brick_registry.hpp"

namespace pc {

Registry<NormalLawFactory>& normal_law_registry() {
  static Registry<NormalLawFactory> registry("normal law", "contact.law_normal");
  return registry;
}

Registry<PairedLawFactory>& friction_law_registry() {
  static Registry<PairedLawFactory> registry("friction law", "contact.law_tangential");
  return registry;
}

Registry<PairedLawFactory>& foundation_law_registry() {
  static Registry<PairedLawFactory> registry("foundation law", "foundation.<name>.type");
  return registry;
}

Registry<BrickFactory>& brick_registry() {
  static Registry<BrickFactory> registry("brick", "bricks[].type");
  return registry;
}

Registry<PairedLawFactory>::Entry no_brick_entry(std::string name, std::string doc) {
  return {std::move(name), std::move(doc), {}, [](const ContactSurface&, const std::shared_ptr<const NormalPressure>&) {
            return std::shared_ptr<Brick>();
          }};
}

}  // namespace pc
