// Every header path of 0.1.0 that moved, included as 0.1.0's users wrote it, with a name from each in use.
#include "models/boundary_table.hpp"
#include "models/condensed_solve.hpp"
#include "models/csv_log.hpp"
#include "models/json.hpp"
#include "models/newton.hpp"
#include "models/piezo_contact_recipe.hpp"
#include "models/piezo_fields.hpp"
#include "models/result_series.hpp"
#include "models/scene.hpp"
#include "models/scene_runner.hpp"

int main() {
  const pc::Json json = pc::parse_json("{\"a\": 1}", "old_includes");
  pc::NewtonOptions options;
  return json.find("a").has_value() && options.max_iterations > 0 ? 0 : 1;
}
