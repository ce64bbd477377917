#include "harness/cli/plugin_loader.h"

#include <dlfcn.h>

#include <cstring>
#include <filesystem>
#include <map>

#include "harness/bench/plugin.h"
#include "harness/bench/registry.h"
#include "harness/scene/input_error.h"

namespace vob {
namespace {
std::map<std::string, std::string>& plugin_orderers() {  // orderer name -> plugin path
  static std::map<std::string, std::string> m;
  return m;
}
std::string major_minor(const std::string& version) {
  const size_t dot = version.find('.');
  return dot == std::string::npos ? version : version.substr(0, version.find('.', dot + 1));
}
}  // namespace

void load_plugin(const std::string& path) {
  namespace fs = std::filesystem;
  const std::string what = "'" + path + "'";
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError("--plugin", what, "no such file");
  if (fs::is_directory(path, ec)) throw InputError("--plugin", what, "is a folder, not a shared library");
  // A name without '/' would be looked up in the library path, not in the current folder.
  const std::string file = path.find('/') == std::string::npos ? "./" + path : path;
  // Never closed: the registered orderers' code lives in it. RTLD_NOW reports missing
  // symbols here rather than in the middle of a run.
  void* lib = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!lib) {
    const char* why = dlerror();
    throw InputError("--plugin", what, std::string("cannot be loaded as a shared library (") +
                                           (why ? why : "unknown reason") + ")");
  }
  if (void* v = dlsym(lib, VOBENCH_PLUGIN_VERSION)) {
    const std::string built = reinterpret_cast<const char* (*)()>(v)(), ours = vobench_library_version();
    if (major_minor(built) != major_minor(ours))
      throw InputError("--plugin", what, "was built for vobench " + built + ", this is " + ours +
                                             " (rebuild it against this installation)");
  }
  void* entry = dlsym(lib, VOBENCH_PLUGIN_ENTRY_POINT);
  if (!entry)
    throw InputError("--plugin", what,
                     "has no entry point " VOBENCH_PLUGIN_ENTRY_POINT
                     " (extern \"C\", harness/bench/plugin.h; vobench_add_plugin builds one)");
  const size_t before = orderer_registry().size();
  try {
    reinterpret_cast<void (*)()>(entry)();
  } catch (const std::exception& e) {
    throw InputError("--plugin", what, e.what());
  }
  if (orderer_registry().size() == before)
    throw InputError("--plugin", what, VOBENCH_PLUGIN_ENTRY_POINT " registered no orderer");
  for (size_t i = before; i < orderer_registry().size(); ++i)
    plugin_orderers()[orderer_registry()[i].name] = path;
}

std::string plugin_of(const std::string& orderer) {
  const auto it = plugin_orderers().find(orderer);
  return it == plugin_orderers().end() ? "" : it->second;
}

std::vector<char*> load_plugin_options(int argc, char** argv) {
  std::vector<char*> rest(argv, argv + argc);
  size_t i = 1;
  while (i < rest.size()) {
    const std::string a = rest[i];
    if (a == "--plugin") {
      if (i + 1 >= rest.size()) throw InputError("--plugin", "option", "needs the path of a shared library");
      load_plugin(rest[i + 1]);
      rest.erase(rest.begin() + i, rest.begin() + i + 2);
    } else if (a.rfind("--plugin=", 0) == 0) {
      load_plugin(a.substr(9));
      rest.erase(rest.begin() + i);
    } else {
      break;
    }
  }
  for (size_t j = i; j < rest.size(); ++j)
    if (std::strcmp(rest[j], "--plugin") == 0 || std::strncmp(rest[j], "--plugin=", 9) == 0)
      throw InputError("--plugin", "option",
                       "goes before the subcommand (vobench --plugin PATH.so SUBCOMMAND ...)");
  return rest;
}

}  // namespace vob
