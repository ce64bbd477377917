# Every dependency is a Debian 12 package; a missing one stops configuration with a message
# naming the package (bash scripts/setup installs them all).
macro(vob_require found what package)
  if(NOT ${found})
    message(FATAL_ERROR "vobench: ${what} not found. Install the Debian package '${package}' "
                        "(or run: bash scripts/setup).")
  endif()
endmacro()

find_package(VTK 9.1 QUIET COMPONENTS CommonCore CommonDataModel IOXML IOLegacy IOImage RenderingCore
             IOExodus IOGeometry IOPLY IOParallelXML FiltersParallel)
vob_require(VTK_FOUND "VTK 9.1 (CommonCore, CommonDataModel, IOXML, IOLegacy, IOImage, RenderingCore, IOExodus, IOGeometry, IOPLY, IOParallelXML, FiltersParallel)" libvtk9-dev)

# gmsh's SDK (.msh files) has no CMake package: its header and library.
find_path(GMSH_INCLUDE_DIR gmsh.h)
find_library(GMSH_LIBRARY gmsh)
vob_require(GMSH_LIBRARY "the gmsh SDK (gmsh.h, libgmsh)" libgmsh-dev)
vob_require(GMSH_INCLUDE_DIR "the gmsh SDK (gmsh.h, libgmsh)" libgmsh-dev)

find_package(ZLIB QUIET)
vob_require(ZLIB_FOUND "zlib" zlib1g-dev)

find_package(CGAL QUIET)
vob_require(CGAL_FOUND "CGAL" libcgal-dev)

find_package(embree 3 QUIET)
vob_require(embree_FOUND "Embree 3" libembree-dev)

find_package(TBB QUIET)
vob_require(TBB_FOUND "TBB" libtbb-dev)

find_package(nlohmann_json 3 QUIET)
vob_require(nlohmann_json_FOUND "nlohmann-json" nlohmann-json3-dev)

find_package(CLI11 QUIET)
vob_require(CLI11_FOUND "CLI11" libcli11-dev)

find_package(GTest QUIET)
vob_require(GTest_FOUND "GoogleTest" libgtest-dev)

find_package(benchmark QUIET)
vob_require(benchmark_FOUND "Google Benchmark" libbenchmark-dev)

find_package(PkgConfig QUIET)
vob_require(PkgConfig_FOUND "pkg-config" pkg-config)
pkg_check_modules(OSMESA QUIET IMPORTED_TARGET osmesa)
vob_require(OSMESA_FOUND "OSMesa (pkg-config osmesa)" libosmesa6-dev)
# vobench opens libOSMesa by its soname when it first needs a GL context (harness/gl).
find_library(VOB_OSMESA_LIBRARY NAMES OSMesa HINTS ${OSMESA_LIBRARY_DIRS})
execute_process(COMMAND ${CMAKE_OBJDUMP} -p ${VOB_OSMESA_LIBRARY} OUTPUT_VARIABLE _vob_osmesa_dyn ERROR_QUIET)
string(REGEX MATCH "SONAME +([^ \n]+)" _vob_osmesa_match "${_vob_osmesa_dyn}")
set(VOB_OSMESA_SONAME "${CMAKE_MATCH_1}")
vob_require(VOB_OSMESA_SONAME "the soname of libOSMesa (objdump -p ${VOB_OSMESA_LIBRARY})" libosmesa6-dev)

find_program(TETGEN_EXECUTABLE tetgen)
vob_require(TETGEN_EXECUTABLE "the tetgen program" tetgen)

set(VOB_PYTHON /usr/bin/python3 CACHE FILEPATH "Debian python3 that sees python3-matplotlib")
set(VOB_CGAL_DATA /usr/share/doc/libcgal-dev/data.tar.gz CACHE FILEPATH "libcgal-demo data archive")
if(NOT EXISTS ${VOB_CGAL_DATA})
  message(FATAL_ERROR "vobench: ${VOB_CGAL_DATA} not found. Install the Debian package 'libcgal-demo'.")
endif()
