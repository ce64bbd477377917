# vobench_add_plugin(NAME [SOURCES] src...): a shared library of orderers for
# `vobench --plugin $<TARGET_FILE:NAME> SUBCOMMAND ...`. The sources define
# extern "C" void vobench_register_orderers(void) (#include "harness/bench/plugin.h").
# Linked against libvobench.so, so the orderers land in the program's own registry.
# Comes with find_package(vobench); vobench's own tree includes it too (harness/cli).
function(vobench_add_plugin name)
  cmake_parse_arguments(P "" "" "SOURCES" ${ARGN})
  set(sources ${P_SOURCES} ${P_UNPARSED_ARGUMENTS})
  if(NOT sources)
    message(FATAL_ERROR "vobench_add_plugin(${name}): no SOURCES")
  endif()
  # The vobench version the plugin is built for: vobench --plugin refuses a plugin from
  # another major.minor (the C++ interface may have changed) instead of crashing in it.
  set(stamp ${CMAKE_CURRENT_BINARY_DIR}/${name}_vobench_version.cpp)
  file(CONFIGURE OUTPUT ${stamp} CONTENT
       "extern \"C\" const char* vobench_plugin_version() { return \"${vobench_VERSION}\"; }\n")
  add_library(${name} MODULE ${sources} ${stamp})
  target_link_libraries(${name} PRIVATE vobench::vobench)
  # Undefined symbols fail the link here, not the dlopen in vobench.
  target_link_options(${name} PRIVATE "LINKER:--no-undefined")
endfunction()
