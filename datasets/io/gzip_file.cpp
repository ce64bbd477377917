#include "datasets/io/gzip_file.h"

#include <zlib.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "harness/scene/input_error.h"

namespace vob {

std::string gunzip_file(const std::string& path, size_t limit) {
  {
    std::ifstream in(path, std::ios::binary);
    unsigned char magic[2] = {0, 0};
    in.read(reinterpret_cast<char*>(magic), 2);
    if (in.gcount() != 2 || magic[0] != 0x1f || magic[1] != 0x8b)
      throw InputError(path, "file", "is not gzip-compressed (no 1f 8b magic bytes)");
  }
  gzFile f = gzopen(path.c_str(), "rb");
  if (!f) throw InputError(path, "file", std::string("cannot be opened: ") + std::strerror(errno));
  std::string out;
  char buf[1 << 16];
  for (;;) {
    const int n = gzread(f, buf, sizeof buf);
    if (n < 0) {
      int code = 0;
      const std::string why = gzerror(f, &code);
      gzclose(f);
      throw InputError(path, "gzip stream", "zlib: " + why + " at byte " + std::to_string(out.size()) + " of the inflated data");
    }
    if (n == 0) break;
    out.append(buf, size_t(n));
    if (out.size() > limit && limit < kMaxGunzipBytes) {  // enough: the caller needs no more
      out.resize(limit + 1);
      gzclose(f);
      return out;
    }
    if (out.size() > kMaxGunzipBytes) {
      gzclose(f);
      throw InputError(path, "gzip stream", "inflates to more than 16 GiB");
    }
  }
  // gzread returns 0 at a cut stream too; gzclose_r then reports the error (Z_BUF_ERROR).
  const int rc = gzclose(f);
  if (rc != Z_OK)
    throw InputError(path, "gzip stream", rc == Z_BUF_ERROR ? "file ends inside the compressed data"
                                                           : "zlib error " + std::to_string(rc));
  return out;
}

}  // namespace vob
