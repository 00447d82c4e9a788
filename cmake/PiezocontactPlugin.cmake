# piezocontact_add_plugin(<target> <source>...)
#   A shared library of laws and bricks that a scene names ("plugins": ["path/to/lib<target>.so"]): built
#   against piezocontact, its PC_REGISTER... lines are run by the loader after it has checked the version
#   the plugin was built against.
set(_piezocontact_plugin_entry "${CMAKE_CURRENT_LIST_DIR}/piezocontact_plugin_entry.cpp")
function(piezocontact_add_plugin target)
  add_library(${target} MODULE ${ARGN} ${_piezocontact_plugin_entry})
  target_link_libraries(${target} PRIVATE piezocontact::piezocontact)
  target_compile_definitions(${target} PRIVATE PIEZOCONTACT_PLUGIN)
  # Only the two entry points are exported: a plugin's own symbols never clash with another's.
  set_target_properties(${target} PROPERTIES CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON PREFIX "lib")
endfunction()
