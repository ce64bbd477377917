# cmake --install: everything in the component "vobench".
#   bin/vobench, lib/libvobench.so (RPATH $ORIGIN-relative: the prefix can be moved)
#   include/vobench/harness/...  the public headers (Orderer API, registry, plugin entry
#                                point, Scene, Camera, oracle) and all they include
#   share/vobench/               report scripts, suites, shaders, the source revision;
#                                harness/bench/resources.cpp finds them from libvobench.so
#   lib/cmake/vobench/           vobenchConfig.cmake: vobench::vobench, vobench::cli,
#                                vobench_add_plugin()
include(CMakePackageConfigHelpers)
set(VOB_COMPONENT vobench)
set(VOB_PACKAGE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/vobench)

# Targets. The program finds libvobench.so relative to itself.
file(RELATIVE_PATH vob_bin_to_lib ${CMAKE_INSTALL_FULL_BINDIR} ${CMAKE_INSTALL_FULL_LIBDIR})
set_target_properties(vobench PROPERTIES INSTALL_RPATH "$ORIGIN/${vob_bin_to_lib}" EXPORT_NAME cli)
install(TARGETS vobench vobench_shared EXPORT vobenchTargets
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT ${VOB_COMPONENT}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT ${VOB_COMPONENT})
install(EXPORT vobenchTargets NAMESPACE vobench:: DESTINATION ${VOB_PACKAGE_DIR}
        COMPONENT ${VOB_COMPONENT})

# Public headers: these roots and every "harness/..." header they include, found by reading
# the #include lines (a header added to the API is installed without a list to update).
set(VOB_PUBLIC_HEADERS
  harness/bench/plugin.h
  harness/bench/registry.h
  harness/bench/orderer.h
  harness/scene/scene.h
  harness/scene/input_error.h
  harness/view/camera.h
  harness/oracle/oracle.h)
set(vob_todo ${VOB_PUBLIC_HEADERS})
set(vob_headers "")
while(vob_todo)
  list(POP_FRONT vob_todo h)
  if(h IN_LIST vob_headers)
    continue()
  endif()
  if(NOT EXISTS ${CMAKE_SOURCE_DIR}/${h})
    message(FATAL_ERROR "vobench install: public header ${h} not found")
  endif()
  list(APPEND vob_headers ${h})
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/${h})
  file(STRINGS ${CMAKE_SOURCE_DIR}/${h} vob_lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
  foreach(line IN LISTS vob_lines)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*" "\\1" inc "${line}")
    list(APPEND vob_todo ${inc})
  endforeach()
endwhile()
foreach(h IN LISTS vob_headers)
  get_filename_component(dir ${h} DIRECTORY)
  install(FILES ${h} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/vobench/${dir} COMPONENT ${VOB_COMPONENT})
endforeach()

# share/vobench: what the program reads at run time (resources.cpp), and the shaders (the
# program embeds them; installed for reading and for renderers that want the same ones).
set(VOB_SHARE ${CMAKE_INSTALL_DATADIR}/vobench)
install(DIRECTORY reports/ DESTINATION ${VOB_SHARE}/reports COMPONENT ${VOB_COMPONENT}
        PATTERN out EXCLUDE PATTERN __pycache__ EXCLUDE PATTERN *.pyc EXCLUDE)
install(DIRECTORY datasets/suites/ DESTINATION ${VOB_SHARE}/datasets/suites COMPONENT ${VOB_COMPONENT})
install(DIRECTORY algorithms/ DESTINATION ${VOB_SHARE}/shaders COMPONENT ${VOB_COMPONENT}
        FILES_MATCHING PATTERN *.vert PATTERN *.frag PATTERN *.glsl)
# The records' git_sha once the sources may be gone: the revision at install time.
install(CODE "
  execute_process(COMMAND git -C \"${CMAKE_SOURCE_DIR}\" describe --always --dirty=+dirty
                  OUTPUT_VARIABLE rev ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
  file(WRITE \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${VOB_SHARE}/source-revision\" \"\${rev}\\n\")
" COMPONENT ${VOB_COMPONENT})

# The CMake package.
configure_package_config_file(cmake/vobenchConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/vobenchConfig.cmake INSTALL_DESTINATION ${VOB_PACKAGE_DIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/vobenchConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/vobenchConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/vobenchConfigVersion.cmake
              cmake/VobenchPlugin.cmake
        DESTINATION ${VOB_PACKAGE_DIR} COMPONENT ${VOB_COMPONENT})
