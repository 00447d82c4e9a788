#include "bricks/source_bricks.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "assembly/error.hpp"

namespace pc {
namespace {

// sign * load . test over cells or faces; no couplings.
class SourceTerm : public Term {
 public:
  SourceTerm(std::string name, Integration integration, const std::string& field, double sign, Load load)
      : Term(std::move(name), integration, {{field, false}}, {0}, {}), sign_(sign), load_(std::move(load)) {}

  void assemble(const ElementData& e, LocalSystem& local, bool want_residual, bool) const override {
    if (!want_residual) return;
    const ElementData::Field& field = e.fields[0];
    const int nc = field.num_components;
    for (int q = 0; q < e.num_points; ++q) {
      // NaN marks components the load did not write.
      double out[3] = {kUnset, kUnset, kUnset};
      load_(e.points[q].data(), e.time, out);
      for (int c = 0; c < nc; ++c)
        if (!std::isfinite(out[c])) report_bad_value(e, q, c, out[c]);
      const double scale = sign_ * e.weights[q];
      for (int i = 0; i < field.num_shapes; ++i) {
        const double Ni = scale * field.shape(q, i);
        for (int c = 0; c < nc; ++c) local.residual[0][i * nc + c] += Ni * out[c];
      }
    }
  }

 private:
  static constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();

  [[noreturn]] void report_bad_value(const ElementData& e, int q, int component, double value) const {
    std::ostringstream point;
    point.precision(10);
    for (int d = 0; d < e.dim; ++d) point << (d ? ", " : "(") << e.points[q][d];
    point << ")";
    fail("brick '", name(), "': the load is ", value, " in component ", component, " at x = ", point.str(),
         ", t = ", e.time, "; it must write one finite value per component of field '", fields()[0].name, "' (",
         e.fields[0].num_components, ")");
  }

  double sign_;
  Load load_;
};

Load constant_load(std::vector<double> value) {
  require(!value.empty() && value.size() <= 3, "a constant load needs 1 to 3 components, got ", value.size());
  return [value = std::move(value)](const double*, double, double* out) {
    for (size_t c = 0; c < value.size(); ++c) out[c] = value[c];
  };
}

}  // namespace

SourceBrick::SourceBrick(const std::string& kind, Integration integration, double sign, Load load, LoadTime time,
                         std::string region, const std::string& field)
    : name_(kind + " on " + region), region_(std::move(region)), time_(time) {
  require(static_cast<bool>(load), "brick '", name_, "': the load function is empty");
  term_ = std::make_shared<const SourceTerm>(name_, integration, field, sign, std::move(load));
}

BodyForceBrick::BodyForceBrick(Load f0, LoadTime time, std::string region, const std::string& velocity)
    : SourceBrick("body force", Integration::Cells, -1, std::move(f0), time, std::move(region), velocity) {}
BodyForceBrick::BodyForceBrick(std::vector<double> f0, std::string region, const std::string& velocity)
    : BodyForceBrick(constant_load(std::move(f0)), LoadTime::Constant, std::move(region), velocity) {}

TractionBrick::TractionBrick(Load f_N, LoadTime time, std::string region, const std::string& velocity)
    : SourceBrick("traction", Integration::Faces, -1, std::move(f_N), time, std::move(region), velocity) {}
TractionBrick::TractionBrick(std::vector<double> f_N, std::string region, const std::string& velocity)
    : TractionBrick(constant_load(std::move(f_N)), LoadTime::Constant, std::move(region), velocity) {}

VolumeChargeBrick::VolumeChargeBrick(Load q0, LoadTime time, std::string region, const std::string& potential)
    : SourceBrick("volume charge", Integration::Cells, -1, std::move(q0), time, std::move(region), potential) {}
VolumeChargeBrick::VolumeChargeBrick(double q0, std::string region, const std::string& potential)
    : VolumeChargeBrick(constant_load({q0}), LoadTime::Constant, std::move(region), potential) {}

SurfaceChargeBrick::SurfaceChargeBrick(Load q_b, LoadTime time, std::string region, const std::string& potential)
    : SourceBrick("surface charge", Integration::Faces, +1, std::move(q_b), time, std::move(region), potential) {}
SurfaceChargeBrick::SurfaceChargeBrick(double q_b, std::string region, const std::string& potential)
    : SurfaceChargeBrick(constant_load({q_b}), LoadTime::Constant, std::move(region), potential) {}

}  // namespace pc
