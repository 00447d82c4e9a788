#pragma once
// Scene keys read through the registries: an object names a registered entry (contact.law_normal,
// foundation.<name>.type, time.scheme) and holds that entry's declared parameters as its own keys. The
// reader takes the allowed keys and the defaults from the declarations, so a law registered anywhere,
// a plugin's included, is read, checked and refused like a built-in one.
#include <string>
#include <vector>

#include "assembly/parameters.hpp"
#include "assembly/registry.hpp"
#include "models/scene/json.hpp"

namespace pc {

// An entry a scene object chose, with the label messages give it ("law_normal 'linear_damped'").
struct ChosenEntry {
  std::string label;
  const std::vector<ParameterDeclaration>* parameters;
};

// The chosen entry's parameters from the object's keys: each checked against its range (the message names
// the key's path and the value), the defaults of those left out, a missing required one refused.
ParameterValues read_parameters(const Json& object, const ChosenEntry& entry);

// Every key of the object must be one of `fixed` or a parameter of a chosen entry. A refused key that
// some other registered entry declares is named with it ("'contact.mu' is read by law_tangential coulomb,
// not by the chosen ..."). `others` lists, for that hint, the (label prefix, registry names, declarations).
struct RegisteredParameters {
  std::string label;  // "law_tangential"
  std::vector<std::pair<std::string, const std::vector<ParameterDeclaration>*>> entries;
};
void require_read_keys(const Json& object, const std::vector<std::string>& fixed,
                       const std::vector<ChosenEntry>& chosen, const std::vector<RegisteredParameters>& others);

template <class Factory>
RegisteredParameters registered_parameters(const std::string& label, const Registry<Factory>& registry) {
  RegisteredParameters out{label, {}};
  for (const auto& entry : registry.entries()) out.entries.push_back({entry.name, &entry.parameters});
  return out;
}

// The entry of the registry that object.<key> names (or `fallback` when the key is absent and the fallback
// is not empty); an unknown name is refused with the path and the registered names.
template <class Factory>
const typename Registry<Factory>::Entry& chosen_entry(const Json& object, const std::string& key,
                                                      const Registry<Factory>& registry,
                                                      const std::string& fallback = "") {
  const auto named = object.find(key);
  if (!named && !fallback.empty()) return registry.at(fallback, "scene: '" + object.path() + "." + key + "'");
  const Json& name = object.at(key);
  return registry.at(name.as_string(), "scene: '" + name.path() + "'");
}

}  // namespace pc
