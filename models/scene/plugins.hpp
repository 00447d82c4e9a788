#pragma once
// Plugins: shared libraries of a user's laws (and bricks) that a scene names, built with
// piezocontact_add_plugin() against the installed package. Loading one checks that it is a piezocontact
// plugin and that it was built against this version of the library, and only then runs its
// registrations, so its laws join the registries and are read, checked and listed like the built-in ones.
#include <string>
#include <vector>

namespace pc {

// Loads the plugin at `path` (once: a path loaded before is not loaded again). Throws pc::Error naming the
// file when it is missing, is not a shared library, is not a piezocontact plugin, was built against
// another version, or registers a name that is taken.
void load_plugin(const std::string& path);
// The canonical paths of the plugins loaded so far, in loading order.
const std::vector<std::string>& loaded_plugins();

}  // namespace pc
