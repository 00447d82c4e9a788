#pragma once
// Every registry a scene reads, for the runner's `list` and `describe` and for the tables of
// docs/scenes.md, which are this catalog's Markdown (a test fails when they differ).
#include <string>
#include <vector>

#include "assembly/parameters.hpp"

namespace pc {

struct CatalogEntry {
  std::string name;
  std::string doc;
  std::vector<ParameterDeclaration> parameters;
};

struct CatalogSection {
  std::string kind;   // "normal law"
  std::string key;    // the scene key that names an entry: "contact.law_normal"
  std::string where;  // where the entry's parameters go in a scene: "contact"
  std::vector<CatalogEntry> entries;
};

// The registries as they stand (plugins loaded so far included), in scene order.
std::vector<CatalogSection> registry_catalog();

// `piezocontact list`: one line per kind with its names.
std::string catalog_list(const std::vector<CatalogSection>& catalog);
// `piezocontact describe [NAME]`: every entry (or those called NAME) with its parameters; empty when no
// entry has that name.
std::string catalog_describe(const std::vector<CatalogSection>& catalog, const std::string& name = "");
// The Markdown tables of docs/scenes.md.
std::string catalog_markdown(const std::vector<CatalogSection>& catalog);

}  // namespace pc
