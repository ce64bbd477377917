// `vobench --plugin PATH.so SUBCOMMAND ...`: orderers from shared libraries built outside
// the tree (harness/bench/plugin.h, vobench_add_plugin in the CMake package).
#pragma once
#include <string>
#include <vector>

namespace vob {

// Loads the library at `path` and calls its entry point; InputError naming the path when the
// file is missing, is not a shared library, has no entry point, or registers nothing.
void load_plugin(const std::string& path);
// Loads every leading "--plugin PATH" / "--plugin=PATH" (before the subcommand) and returns
// argv without them. InputError for a --plugin without a path or after the subcommand.
std::vector<char*> load_plugin_options(int argc, char** argv);
// The path of the plugin that registered `orderer` ("" for the built-in ones).
std::string plugin_of(const std::string& orderer);

}  // namespace vob
