#pragma once
// Prescribed loads (paper eq. (18), (19)), entering the residual R = internal - external:
//   body force     f0  on cells, tests w:   - f0 . w
//   traction       f_N on faces, tests w:   - f_N . w
//   volume charge  q0  on cells, tests psi: - q0 psi
//   surface charge q_b on faces, tests psi: + q_b psi
// The surface charge enters with a plus: integrating div D = q0 by parts against psi gives
//   int D . grad psi = int_boundary (D . nu) psi - int q0 psi,
// and with D = E eps(u) - beta grad phi and D . nu = q_b the electric residual is
//   int beta grad phi . grad psi - int E eps(u) . grad psi - int q0 psi + int q_b psi.
// (Eq. (19) of the paper writes + q_b on the right-hand side, which is inconsistent with its eq. (4), (8).)
//
// Loads are functions of the point and the time; a load whose time dependence is declared Constant is
// assembled once. The residual does not depend on the unknowns: the bricks are linear with no tangent.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bricks/brick.hpp"

namespace pc {

// Writes the load's components at the physical point x and time t into out (room for 3 values).
using Load = std::function<void(const double* x, double t, double* out)>;
enum class LoadTime { Constant, Varying };

// The common part of the four source bricks: one term testing `field` with the load.
class SourceBrick : public Brick {
 public:
  std::string name() const override { return name_; }
  std::vector<BrickTerm> terms() const override { return {{term_, region_}}; }
  bool linear() const override { return true; }
  bool symmetric() const override { return true; }  // no tangent blocks, so none that is not symmetric
  bool time_dependent() const override { return time_ == LoadTime::Varying; }

 protected:
  // sign -1 subtracts the load from the residual (an external force), +1 adds it.
  SourceBrick(const std::string& kind, Integration integration, double sign, Load load, LoadTime time,
              std::string region, const std::string& field);

 private:
  std::string name_, region_;
  LoadTime time_;
  std::shared_ptr<const Term> term_;
};

class BodyForceBrick : public SourceBrick {
 public:
  BodyForceBrick(Load f0, LoadTime time, std::string region = "all", const std::string& velocity = "v");
  explicit BodyForceBrick(std::vector<double> f0, std::string region = "all", const std::string& velocity = "v");
};

class TractionBrick : public SourceBrick {
 public:
  TractionBrick(Load f_N, LoadTime time, std::string region, const std::string& velocity = "v");
  TractionBrick(std::vector<double> f_N, std::string region, const std::string& velocity = "v");
};

class VolumeChargeBrick : public SourceBrick {
 public:
  VolumeChargeBrick(Load q0, LoadTime time, std::string region = "all", const std::string& potential = "phi");
  explicit VolumeChargeBrick(double q0, std::string region = "all", const std::string& potential = "phi");
};

class SurfaceChargeBrick : public SourceBrick {
 public:
  SurfaceChargeBrick(Load q_b, LoadTime time, std::string region, const std::string& potential = "phi");
  SurfaceChargeBrick(double q_b, std::string region, const std::string& potential = "phi");
};

}  // namespace pc
