// The entry point of an orderer plugin: a shared library loaded with
// `vobench --plugin PATH.so SUBCOMMAND ...` defines this one C function, which registers its
// orderers with vob::register_orderer (harness/bench/registry.h). The plugin links
// libvobench.so (vobench::vobench from find_package(vobench); vobench_add_plugin builds
// one), so it fills the same registry the program reads. Errors are thrown as
// vob::InputError (e.g. a name already taken): the program prints one line and exits 2.
#pragma once

#include "harness/bench/registry.h"
#include "harness/scene/input_error.h"

#define VOBENCH_PLUGIN_ENTRY_POINT "vobench_register_orderers"
#define VOBENCH_PLUGIN_VERSION "vobench_plugin_version"

extern "C" void vobench_register_orderers(void);
// Optional (vobench_add_plugin defines it): the vobench version the plugin was built
// against; a plugin of another major.minor is refused before its entry point is called.
extern "C" const char* vobench_plugin_version(void);
// libvobench.so's own version ("0.15.0").
extern "C" const char* vobench_library_version(void);
