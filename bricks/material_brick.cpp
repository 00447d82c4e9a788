#include "bricks/material_brick.hpp"

#include "assembly/error.hpp"

namespace pc {

std::vector<BrickTerm> MaterialBrick::terms() const {
  require(term_ != nullptr, "brick '", name(), "': terms() asked before update()");
  return {{term_, region_}};
}

}  // namespace pc
