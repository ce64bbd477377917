#include "datasets/io/gmsh_reader.h"

#include <dlfcn.h>

#include <filesystem>
#include <mutex>

#include "datasets/io/msh_prescan.h"
#include "harness/scene/input_error.h"

namespace vob {
namespace {

using ReadFn = void (*)(const std::string&, CellMesh&, std::string*);

// The module beside the library holding this code (libvobench.so, wherever it was
// installed or moved), loaded once and kept.
ReadFn load_module(const std::string& path) {
  static std::mutex mutex;
  static ReadFn fn = nullptr;
  std::lock_guard<std::mutex> lock(mutex);
  if (fn) return fn;
  Dl_info info{};
  std::string module = VOBENCH_GMSH_MODULE;
  if (dladdr(reinterpret_cast<const void*>(&load_module), &info) != 0 && info.dli_fname)
    module = (std::filesystem::path(info.dli_fname).parent_path() / VOBENCH_GMSH_MODULE).string();
  // DEEPBIND: the module's tree (gmsh, OpenCASCADE, ...) looks its symbols up in itself
  // first; searched after the ~100 libraries already loaded, its ~140k relocations took
  // 60 ms more than the whole read did with the SDK linked in. AddressSanitizer refuses it.
#if defined(__SANITIZE_ADDRESS__)
  const int flags = RTLD_LAZY | RTLD_LOCAL;
#else
  const int flags = RTLD_LAZY | RTLD_LOCAL | RTLD_DEEPBIND;
#endif
  void* lib = dlopen(module.c_str(), flags);
  if (!lib) {
    const char* why = dlerror();
    throw InputError(path, "file", "the gmsh reader " + module + " cannot be loaded (" +
                                       (why ? why : "unknown") + ")");
  }
  void* entry = dlsym(lib, VOBENCH_GMSH_READ_ENTRY);
  if (!entry) throw InputError(path, "file", "the gmsh reader " + module + " has no entry point " VOBENCH_GMSH_READ_ENTRY);
  fn = reinterpret_cast<ReadFn>(entry);
  return fn;
}

}  // namespace

CellMesh read_gmsh(const std::string& path, std::string* note) {
  prescan_msh(path);
  CellMesh mesh;
  load_module(path)(path, mesh, note);
  return mesh;
}

}  // namespace vob
