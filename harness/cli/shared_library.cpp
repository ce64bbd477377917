// libvobench.so: every vobench static library, whole (harness/cli/CMakeLists.txt). The
// program, plugins loaded with --plugin and the Python module link this one library, so
// they share one orderer registry. This file gives the library its own symbol: the
// version a plugin can check against.
extern "C" const char* vobench_library_version() { return VOB_LIBRARY_VERSION; }
