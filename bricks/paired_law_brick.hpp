#pragma once
// What friction and foundation bricks share: a law over a contact region whose parameters come from the
// model (bound_law.hpp) and, for a law that reads the contact pressure, the normal brick of the same
// region it is paired with. A derived brick builds its one term in its constructor.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "bricks/bound_law.hpp"
#include "bricks/brick.hpp"
#include "bricks/laws/law_traits.hpp"
#include "bricks/normal_pressure.hpp"

namespace pc {

template <class Law> class PairedLawBrick : public Brick {
 public:
  // The law's constants and, for a law reading the pressure, the normal law's: a new c_nu changes it too.
  std::vector<std::string> data() const override { return paired_data(law_.data(), normal_.get()); }
  void update(const DataView& data) override { law_.update(data, name()); }
  std::vector<BrickTerm> terms() const override { return {{term_, region_}}; }
  bool linear() const override { return law_affine<Law>; }
  // A pressure read relative to a moving foundation changes with the time.
  bool time_dependent() const override { return normal_ && foundation_moves(normal_->motion()); }
  const Law& law() const { return *law_; }
  const std::string& region() const { return region_; }

 protected:
  PairedLawBrick(BoundLaw<Law> law, std::string region, std::shared_ptr<const NormalPressure> normal)
      : region_(std::move(region)), law_(std::move(law)), normal_(std::move(normal)) {}
  // Called by the derived constructor, once name() can be called.
  void require_pairing_of(const std::string& brick) const {
    require_pairing(law_uses_normal_pressure<Law>, normal_.get(), brick, region_);
  }
  // For a brick that reads the foundation's motion (friction): it must be its paired normal brick's.
  void require_motion_of_pairing(const std::string& brick, const FoundationMotion* motion) const {
    require(!normal_ || normal_->motion() == motion, "brick '", brick,
            "': its foundation motion is not the one of the normal brick it is paired with (give both bricks the "
            "same ContactFields::motion)");
  }

  std::string region_;
  BoundLaw<Law> law_;
  std::shared_ptr<const NormalPressure> normal_;
  std::shared_ptr<const Term> term_;
};

}  // namespace pc
