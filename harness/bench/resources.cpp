#include "harness/bench/resources.h"

#include <dlfcn.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace vob {
namespace {

namespace fs = std::filesystem;

// share/vobench relative to the file holding this code (libvobench.so when installed):
// dladdr names the library actually loaded, wherever the prefix was moved.
std::string installed_dir() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&installed_dir), &info) == 0 || !info.dli_fname)
    return "";
  std::error_code ec;
  const fs::path lib = fs::canonical(info.dli_fname, ec);
  if (ec) return "";
  const fs::path share = (lib.parent_path() / VOB_LIB_TO_DATA).lexically_normal();
  // The suites folder marks an installed tree (a build tree's library has no share/vobench).
  return fs::is_directory(share / "datasets" / "suites", ec) ? share.string() : "";
}

struct Where {
  std::string dir;
  bool installed;
};

const Where& where() {
  static const Where w = [] {
    const std::string dir = installed_dir();
    return dir.empty() ? Where{VOB_SOURCE_DIR, false} : Where{dir, true};
  }();
  return w;
}

std::string first_line_of_command(const std::string& cmd) {
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return "";
  char buf[128] = "";
  const bool got = fgets(buf, sizeof buf, p) != nullptr;
  pclose(p);
  std::string s = got ? buf : "";
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
  return s;
}

}  // namespace

const std::string& resource_dir() { return where().dir; }

std::string resource_path(const std::string& relative) { return where().dir + "/" + relative; }

bool installed() { return where().installed; }

std::string source_revision() {
  if (installed()) {
    std::ifstream in(resource_path("source-revision"));
    std::string s;
    std::getline(in, s);
    return s;
  }
  // The sha of the source tree now (not at configure time), with "+dirty" for local edits.
  return first_line_of_command(std::string("git -C '") + VOB_SOURCE_DIR +
                               "' describe --always --dirty=+dirty 2>/dev/null");
}

}  // namespace vob
