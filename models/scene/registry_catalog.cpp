#include "models/scene/registry_catalog.hpp"

#include "assembly/error.hpp"
#include "assembly/linear_solver.hpp"
#include "bricks/brick_registry.hpp"
#include "bricks/law_registry.hpp"
#include "bricks/piezo_materials.hpp"
#include "models/solvers/condensed_solve.hpp"
#include "models/time_scheme.hpp"

namespace pc {
namespace {

template <class Factory> CatalogSection section(const Registry<Factory>& registry, std::string where) {
  CatalogSection s{registry.kind(), registry.key(), std::move(where), {}};
  for (const auto& e : registry.entries()) s.entries.push_back({e.name, e.doc, e.parameters});
  return s;
}

std::string describe_parameter(const ParameterDeclaration& p) {
  std::string text = message(p.name, " [", p.unit, "] ");
  text += p.required() ? "required" : message("default ", *p.default_value);
  if (p.range.describe() != "finite") text += ", " + p.range.describe();
  return text + ": " + p.doc;
}

// Markdown table cells: a '|' (as in |p_nu|) would end the cell.
std::string table_cell(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

}  // namespace

std::vector<CatalogSection> registry_catalog() {
  return {section(piezo_material_registry(), "material"), section(normal_law_registry(), "contact"),
          section(friction_law_registry(), "contact"),    section(foundation_law_registry(), "foundation.<name>"),
          section(brick_registry(), "bricks[]"),          section(time_scheme_registry(), "time"),
          section(linear_solver_registry(), "solver"),    section(condensation_registry(), "solver")};
}

std::string catalog_list(const std::vector<CatalogSection>& catalog) {
  std::string text;
  for (const CatalogSection& s : catalog) {
    text += s.kind + "s (" + s.key + "):";
    for (const CatalogEntry& e : s.entries) text += " " + e.name;
    text += "\n";
  }
  return text;
}

std::string catalog_describe(const std::vector<CatalogSection>& catalog, const std::string& name) {
  std::string text;
  for (const CatalogSection& s : catalog)
    for (const CatalogEntry& e : s.entries) {
      if (!name.empty() && e.name != name) continue;
      text += message(s.key, " = \"", e.name, "\" (", s.kind, "): ", e.doc, "\n");
      for (const ParameterDeclaration& p : e.parameters) text += "    " + s.where + "." + describe_parameter(p) + "\n";
    }
  return text;
}

std::string catalog_markdown(const std::vector<CatalogSection>& catalog) {
  std::string text;
  for (const CatalogSection& s : catalog) {
    std::string kind = s.kind;
    kind[0] = char(std::toupper(static_cast<unsigned char>(kind[0])));
    text += message("\n#### ", kind, "s: `", s.key, "`\n\n| name | what it is | parameters (in `", s.where,
                    "`) |\n|---|---|---|\n");
    for (const CatalogEntry& e : s.entries) {
      std::string parameters;
      for (const ParameterDeclaration& p : e.parameters)
        parameters += (parameters.empty() ? "" : "; ") + describe_parameter(p);
      text += message("| `", e.name, "` | ", table_cell(e.doc), " | ",
                      table_cell(parameters.empty() ? "none" : parameters), " |\n");
    }
  }
  return text;
}

}  // namespace pc
