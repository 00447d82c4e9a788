#pragma once
// A registry: the things of one kind that a scene can name (normal laws, linear solvers, time schemes),
// each registered once, next to its code, with its parameters and one line of documentation:
//
//   PC_REGISTER(linear_solver_registry(), {"umfpack", "SuiteSparse UMFPACK, AMD ordering", {},
//                                          [] { return std::make_unique<UmfpackSolver>(); }});
//
// A kind's registry is a function-local static of one function defined in a .cpp (so that one instance
// exists however many shared libraries include this header). Registration runs when the library or
// program that holds it is loaded. In a plugin (compiled with PIEZOCONTACT_PLUGIN, which
// piezocontact_add_plugin() sets) it is deferred instead: the loader first checks the plugin's version,
// then runs its registrations (models/scene/plugins.hpp), so a plugin built against another version never
// touches the registries.
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "assembly/error.hpp"
#include "assembly/parameters.hpp"
#include "assembly/suggestions.hpp"

namespace pc {

template <class Factory> class Registry {
 public:
  struct Entry {
    std::string name;
    std::string doc;
    std::vector<ParameterDeclaration> parameters;
    Factory create;
  };

  // kind: what an entry is, in messages ("normal law"); key: the scene key that names one
  // ("contact.law_normal"), for the documentation.
  Registry(std::string kind, std::string key) : kind_(std::move(kind)), key_(std::move(key)) {}
  Registry(const Registry&) = delete;
  Registry& operator=(const Registry&) = delete;

  const std::string& kind() const { return kind_; }
  const std::string& key() const { return key_; }

  // Throws when the name is taken: two entries may not answer to one name.
  void add(Entry entry) {
    require(!entry.name.empty(), kind_, " registry: an entry needs a name");
    require(find(entry.name) == nullptr, kind_, " registry: '", entry.name, "' is registered twice");
    entries_.push_back(std::move(entry));
    std::sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) { return a.name < b.name; });
  }
  const Entry* find(const std::string& name) const {
    for (const Entry& e : entries_)
      if (e.name == name) return &e;
    return nullptr;
  }
  // Throws "<where>: unknown <kind> 'name' (known: a, b, c)", and "; did you mean 'b'?" when one is close.
  const Entry& at(const std::string& name, const std::string& where) const {
    if (const Entry* e = find(name)) return *e;
    fail(where, ": unknown ", kind_, " '", name, "' (known: ", names_text(), ")", did_you_mean(name, names()));
  }
  // Sorted by name.
  const std::vector<Entry>& entries() const { return entries_; }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const Entry& e : entries_) out.push_back(e.name);
    return out;
  }
  std::string names_text() const {
    std::string text;
    for (const Entry& e : entries_) text += (text.empty() ? "" : ", ") + e.name;
    return text;
  }

 private:
  std::string kind_, key_;
  std::vector<Entry> entries_;
};

}  // namespace pc

#ifdef PIEZOCONTACT_PLUGIN
#include <functional>
namespace pc::plugin_detail {
// The registrations of this plugin, run by its entry point once the loader has checked its version.
// Hidden: every plugin has its own list.
__attribute__((visibility("hidden"))) inline std::vector<std::function<void()>>& pending_registrations() {
  static std::vector<std::function<void()>> pending;
  return pending;
}
}  // namespace pc::plugin_detail
#define PC_REGISTRY_RUN(action) (pc::plugin_detail::pending_registrations().push_back([] { action; }), true)
#else
#define PC_REGISTRY_RUN(action) (action, true)
#endif

#define PC_REGISTRY_CONCAT_INNER(a, b) a##b
#define PC_REGISTRY_CONCAT(a, b) PC_REGISTRY_CONCAT_INNER(a, b)
// Adds an entry to a registry when the library or program that holds this line is loaded (a plugin's:
// when the loader has accepted it).
#define PC_REGISTER(registry, ...)                                                                         \
  namespace {                                                                                              \
  [[maybe_unused]] const bool PC_REGISTRY_CONCAT(pc_registered_,                                           \
                                                 __LINE__) = PC_REGISTRY_RUN((registry).add(__VA_ARGS__)); \
  }
