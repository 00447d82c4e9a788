#pragma once
// The registry of whole bricks that a scene can add ("bricks": [{"type": NAME, "region": ..., parameters}]),
// for physics beyond the paper's recipe, from the library or from a plugin. An entry declares its
// parameters like a law; the recipe writes their values into the model's constants (by the parameter
// names) and the factory makes the brick over the region, which reads them in update():
//
//   PC_REGISTER_BRICK("surface_damping", "k v . w on a face region", {{"k", "Pa s/m", "damping", std::nullopt,
//                     pc::Range::at_least(0)}}, [](const std::string& region) { return make_brick(region); })
#include <functional>
#include <memory>
#include <string>

#include "assembly/registry.hpp"
#include "bricks/brick.hpp"

namespace pc {

using BrickFactory = std::function<std::shared_ptr<Brick>(const std::string& region)>;
Registry<BrickFactory>& brick_registry();

}  // namespace pc

// PC_REGISTER_BRICK(name, doc, parameters, factory)
#define PC_REGISTER_BRICK(...) PC_REGISTER(pc::brick_registry(), {__VA_ARGS__})
