# Public headers that moved since 0.1.0 keep their old path in the installed package: a forwarding header
# that includes the new one and says, once per translation unit, where it went (a #pragma message is a
# note, not a warning, so a consumer's -Werror still compiles). Old path = new path, both under the include
# root; tests/consumer/old_includes/ compiles code written against the old paths.
set(piezocontact_moved_headers
  models/boundary_table.hpp=models/output/boundary_table.hpp
  models/condensed_solve.hpp=models/solvers/condensed_solve.hpp
  models/csv_log.hpp=models/output/csv_log.hpp
  models/json.hpp=models/scene/json.hpp
  models/newton.hpp=models/solvers/newton.hpp
  models/piezo_contact_recipe.hpp=models/piezo/piezo_contact_recipe.hpp
  models/piezo_fields.hpp=models/output/piezo_fields.hpp
  models/result_series.hpp=models/output/result_series.hpp
  models/scene.hpp=models/scene/scene.hpp
  models/scene_runner.hpp=models/scene/scene_runner.hpp)

foreach(move ${piezocontact_moved_headers})
  string(REPLACE "=" ";" paths "${move}")
  list(GET paths 0 old)
  list(GET paths 1 new)
  if(EXISTS "${PROJECT_SOURCE_DIR}/${old}" OR NOT EXISTS "${PROJECT_SOURCE_DIR}/${new}")
    message(FATAL_ERROR "ForwardingHeaders.cmake: ${old} -> ${new} is stale (the old path exists or the new one does not)")
  endif()
  set(forwarding "${PROJECT_BINARY_DIR}/forwarding/${old}")
  file(CONFIGURE OUTPUT "${forwarding}" CONTENT
"#pragma once
// Forwarding header: ${old} moved to ${new} in piezocontact 0.2.0. Include the new path.
#pragma message(\"piezocontact: ${old} moved to ${new} in 0.2.0; include the new path\")
#include \"${new}\"
")
  get_filename_component(old_dir "${old}" DIRECTORY)
  install(FILES "${forwarding}" DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/piezocontact/${old_dir})
endforeach()
