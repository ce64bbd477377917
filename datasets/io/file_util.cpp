#include "datasets/io/file_util.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <vector>

#include "harness/scene/input_error.h"

namespace vob {

void write_atomically(const std::string& path,
                      const std::function<void(const std::string& tmp)>& write) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  std::error_code ec;
  if (target.has_parent_path()) {
    fs::create_directories(target.parent_path(), ec);
    if (ec) throw InputError(path, "folder", "cannot be created: " + ec.message());
  }
  std::string pattern = path + ".tmp-" + std::string(6, 'X');  // mkstemp template
  std::vector<char> buf(pattern.begin(), pattern.end());
  buf.push_back('\0');
  const int fd = mkstemp(buf.data());
  if (fd < 0) throw InputError(path, "file", std::string("cannot be written: ") + std::strerror(errno));
  // mkstemp creates 0600; a written mesh gets the mode the umask allows, like any file.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  close(fd);
  const std::string tmp(buf.data());
  try {
    write(tmp);
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    fs::remove(tmp, ec);
    throw InputError(path, "file", "cannot be renamed into place: " + why);
  }
}

void require_readable_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto st = fs::status(path, ec);
  if (ec || !fs::exists(st)) throw InputError(path, "file", "does not exist");
  if (!fs::is_regular_file(st)) throw InputError(path, "file", "is not a regular file");
  if (access(path.c_str(), R_OK) != 0)
    throw InputError(path, "file", std::string("cannot be read: ") + std::strerror(errno));
}

std::string file_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

void require_file_start(const std::string& path, std::initializer_list<const char*> starts, bool after_blanks,
                        const std::string& format, const std::string& expected) {
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  const size_t at = after_blanks ? std::min(head.find_first_not_of(" \t\r\n"), head.size()) : 0;
  for (const char* s : starts)
    if (head.compare(at, std::strlen(s), s) == 0) return;
  const std::string why = "is not a " + format + " file: ";
  if (head.empty()) throw InputError(path, "file", why + "it is empty");
  if (at == head.size()) throw InputError(path, "file", why + "its first " + std::to_string(at) + " bytes are blank");
  const std::string line = head.substr(at, std::min(head.find('\n', at), head.size()) - at);
  if (line.find_first_not_of(" \t\r") == std::string::npos)
    throw InputError(path, "file", why + "it starts with a blank line, not " + expected);
  throw InputError(path, "file", why + "it starts with '" + line.substr(0, 16) + (line.size() > 16 ? "...'" : "'") +
                                     ", not " + expected);
}

}  // namespace vob
