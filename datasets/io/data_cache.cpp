#include "datasets/io/data_cache.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "datasets/io/file_util.h"
#include "datasets/io/subprocess.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace fs = std::filesystem;

std::string cache_dir() {
  std::string base;
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x)
    base = x;
  else if (const char* h = std::getenv("HOME"); h && *h)
    base = std::string(h) + "/.cache";
  else
    throw InputError("cache", "folder", "neither XDG_CACHE_HOME nor HOME is set");
  const std::string dir = base + "/vobench";
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError(dir, "cache folder", "cannot be created: " + ec.message());
  return dir;
}

std::string cgal_data_file(const std::string& member) {
  const std::string archive = VOB_CGAL_DATA;
  const std::string path = cache_dir() + "/cgal/" + member;
  std::error_code ec;
  if (fs::is_regular_file(path, ec) && fs::file_size(path, ec) > 0) return path;
  if (!fs::is_regular_file(archive, ec))
    throw InputError(archive, "archive", "not found (install the Debian package libcgal-demo)");
  write_atomically(path, [&](const std::string& tmp) {
    const std::string err = tmp + ".err";
    const ProcessResult r = run_process({"/bin/tar", "xzf", archive, "-O", member}, "", tmp, err, 300);
    const std::string why = last_line_of(err);
    fs::remove(err, ec);
    if (r.timed_out) throw InputError(archive, member, "extraction timed out");
    if (!r.exited || r.exit_code != 0 || fs::file_size(tmp, ec) == 0)
      throw InputError(archive, member, "cannot be extracted" + (why.empty() ? "" : ": " + why));
  });
  return path;
}

std::string stable_hash(const std::string& text) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

}  // namespace vob
