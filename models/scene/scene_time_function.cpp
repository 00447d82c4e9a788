#include "models/scene/scene_time_function.hpp"

#include <utility>
#include <vector>

#include "assembly/error.hpp"

namespace pc {

TimeFunction time_function_from_json(const Json& value) {
  if (value.is_number()) return TimeFunction::constant(value.as_number());
  require(value.is_object(), "scene: '", value.path(),
          "' must be a number or a time function "
          "{\"type\": \"constant\" | \"ramp\" | \"sine\" | \"table\", ...}, got ",
          value.dump(0));
  const std::string type = value.at("type").as_string();
  // The factories' own messages name the argument; the scene's prefix names where it is.
  auto made = [&](auto&& make) {
    try {
      return make();
    } catch (const Error& e) {
      fail("scene: '", value.path(), "': ", e.what());
    }
  };
  if (type == "constant") {
    require_known_keys(value, {"type", "value"});
    return TimeFunction::constant(value.at("value").as_number());
  }
  if (type == "ramp") {
    require_known_keys(value, {"type", "value", "duration"});
    const double target = value.at("value").as_number();
    const double duration = value.at("duration").as_positive();
    return made([&] { return TimeFunction::ramp(target, duration); });
  }
  if (type == "sine") {
    require_known_keys(value, {"type", "amplitude", "frequency", "phase", "offset"});
    const double amplitude = value.at("amplitude").as_number();
    const double frequency = value.at("frequency").as_positive();
    const double phase = value.contains("phase") ? value.at("phase").as_number() : 0.0;
    const double offset = value.contains("offset") ? value.at("offset").as_number() : 0.0;
    return made([&] { return TimeFunction::sine(amplitude, frequency, phase, offset); });
  }
  if (type == "table") {
    require_known_keys(value, {"type", "points"});
    std::vector<std::pair<double, double>> points;
    for (const Json& point : value.at("points").as_array()) {
      const std::vector<double> p = point.as_vector(2);
      points.push_back({p[0], p[1]});
    }
    return made([&] { return TimeFunction::table(std::move(points)); });
  }
  fail("scene: '", value.path(), ".type' must be constant, ramp, sine or table, got '", type, "'");
}

}  // namespace pc
