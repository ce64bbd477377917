#include "harness/bench/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "harness/scene/input_error.h"

namespace vob {

namespace {
std::string reason(int err) { return std::strerror(err); }

// O_EXCL with mode 0666 lets the kernel apply the umask (mkstemp would force 0600); the
// name carries the pid and a per-process counter so that threads and processes never share
// a temporary file.
int create_temporary(const std::string& path, std::string& tmp) {
  static std::atomic<unsigned> counter{0};
  for (;;) {
    tmp = path + ".tmp." + std::to_string(getpid()) + "." + std::to_string(counter++);
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
}

bool write_all(int fd, const std::string& content) {
  size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += size_t(n);
  }
  return true;
}
}  // namespace

void write_file_atomically(const std::string& path, const std::string& content) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  if (target.has_parent_path()) {
    std::error_code ec;
    fs::create_directories(target.parent_path(), ec);
    if (ec) throw InputError(path, "folder", "cannot be created: " + ec.message());
  }
  std::string tmp;
  const int fd = create_temporary(path, tmp);
  if (fd < 0) throw InputError(path, "file", "cannot be written: " + reason(errno));
  const bool ok = write_all(fd, content) && ::fsync(fd) == 0;
  const int write_errno = errno;
  ::close(fd);
  if (!ok || std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = ok ? errno : write_errno;
    std::remove(tmp.c_str());
    throw InputError(path, "file", "cannot be written: " + reason(err));
  }
}

void require_writable_folder(const std::string& folder) {
  namespace fs = std::filesystem;
  fs::path p = fs::absolute(folder.empty() ? "." : folder);
  std::error_code ec;
  while (!fs::exists(p, ec) && p.has_parent_path() && p != p.parent_path()) p = p.parent_path();
  if (!fs::is_directory(p, ec))
    throw InputError(folder, "folder", "cannot be created: " + p.string() + " is not a folder");
  if (::access(p.c_str(), W_OK | X_OK) != 0)
    throw InputError(folder, "folder", "cannot be written: " + p.string() + ": " + reason(errno));
}

}  // namespace vob
