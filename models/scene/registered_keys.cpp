#include "models/scene/registered_keys.hpp"

#include <algorithm>

#include "assembly/error.hpp"

namespace pc {

ParameterValues read_parameters(const Json& object, const ChosenEntry& entry) {
  ParameterValues values;
  for (const ParameterDeclaration& d : *entry.parameters) {
    const auto value = object.find(d.name);
    if (!value) {
      require(!d.required(), "scene: '", object.path(), ".", d.name, "' is required by ", entry.label, " (", d.doc,
              ", ", d.unit, ")");
      values[d.name] = *d.default_value;
      continue;
    }
    values[d.name] = value->as_number(d.range, d.unit);
  }
  return values;
}

void require_read_keys(const Json& object, const std::vector<std::string>& fixed,
                       const std::vector<ChosenEntry>& chosen, const std::vector<RegisteredParameters>& others) {
  std::vector<std::string> allowed = fixed;
  for (const ChosenEntry& entry : chosen)
    for (const ParameterDeclaration& d : *entry.parameters) allowed.push_back(d.name);
  for (const std::string& key : object.keys()) {
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string readers;
    for (const RegisteredParameters& group : others)
      for (const auto& [name, parameters] : group.entries)
        if (find_parameter(*parameters, key)) readers += (readers.empty() ? "" : ", ") + group.label + " " + name;
    std::string chosen_labels;
    for (const ChosenEntry& entry : chosen) chosen_labels += (chosen_labels.empty() ? "" : " and ") + entry.label;
    if (!readers.empty())
      fail("scene: '", object.path(), ".", key, "' is read by ", readers, ", not by the chosen ",
           chosen_labels.empty() ? "entries" : chosen_labels);
    require_known_keys(object, allowed);  // names the unknown key and lists the known ones
  }
}

}  // namespace pc
