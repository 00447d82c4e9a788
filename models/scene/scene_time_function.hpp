#pragma once
// A time function (assembly/time_function.hpp) in a scene: a number is a constant, an object names its kind
//   {"type": "constant", "value": 5}
//   {"type": "ramp", "value": 100, "duration": 1e-3}
//   {"type": "sine", "amplitude": 100, "frequency": 25e3, "phase": 1.5708, "offset": 0}   (phase in radians)
//   {"type": "table", "points": [[0, 0], [1e-3, 100], [2e-3, 100]]}
// Every problem is reported with the value's path.
#include "assembly/time_function.hpp"
#include "models/scene/json.hpp"

namespace pc {

TimeFunction time_function_from_json(const Json& value);

}  // namespace pc
