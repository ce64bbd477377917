#include "datasets/io/gzip_file.h"

#include <zlib.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <vector>

#include "harness/scene/input_error.h"

namespace vob {

// Inflated with zlib's inflate, member by member, not gzread: gzread ignores bytes after the
// last member that do not start another (a file with junk appended read as good), and its
// messages repeat the path and name no place in the file.
std::string gunzip_file(const std::string& path, size_t limit) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "file", std::string("cannot be opened: ") + std::strerror(errno));
  std::vector<unsigned char> chunk(1 << 16);
  const auto refill = [&](z_stream& z) {
    in.read(reinterpret_cast<char*>(chunk.data()), std::streamsize(chunk.size()));
    z.next_in = chunk.data();
    z.avail_in = uInt(in.gcount());
    return z.avail_in > 0;
  };
  z_stream z{};
  if (!refill(z) || z.avail_in < 2 || z.next_in[0] != 0x1f || z.next_in[1] != 0x8b)
    throw InputError(path, "file", "is not gzip-compressed (no 1f 8b magic bytes)");
  if (inflateInit2(&z, 15 + 16) != Z_OK) throw InputError(path, "gzip stream", "zlib cannot be set up");
  struct End {
    z_stream* z;
    ~End() { inflateEnd(z); }
  } end{&z};
  uint64_t before = 0;  // compressed bytes of the chunks before the current one
  const auto at = [&] { return before + (z.next_in - chunk.data()); };  // the next compressed byte
  std::string out;
  std::vector<char> buf(1 << 16);
  int member = 1;
  for (;;) {
    if (z.avail_in == 0) {
      before += z.next_in - chunk.data();
      if (!refill(z)) throw InputError(path, "gzip member " + std::to_string(member), "file ends inside the compressed data");
    }
    z.next_out = reinterpret_cast<Bytef*>(buf.data());
    z.avail_out = uInt(buf.size());
    const int rc = inflate(&z, Z_NO_FLUSH);
    out.append(buf.data(), buf.size() - z.avail_out);
    if (out.size() > limit && limit < kMaxGunzipBytes) {  // enough: the caller needs no more
      out.resize(limit + 1);
      return out;
    }
    if (out.size() > kMaxGunzipBytes) throw InputError(path, "gzip stream", "inflates to more than 16 GiB");
    if (rc == Z_STREAM_END) {
      // Another member may follow (gzip reads concatenated members as one stream); anything
      // else after the member is refused.
      const uint64_t member_end = at();
      if (z.avail_in == 0) {
        before += z.next_in - chunk.data();
        if (!refill(z)) return out;
      }
      if (z.avail_in < 2) {  // a lone byte at the end of a chunk: look at the next one too
        const unsigned char first = z.next_in[0];
        before += z.next_in - chunk.data();
        chunk[0] = first;
        in.read(reinterpret_cast<char*>(chunk.data()) + 1, std::streamsize(chunk.size() - 1));
        z.next_in = chunk.data();
        z.avail_in = uInt(1 + in.gcount());
      }
      if (z.avail_in < 2 || z.next_in[0] != 0x1f || z.next_in[1] != 0x8b) {
        in.clear();
        in.seekg(0, std::ios::end);
        const uint64_t size = uint64_t(in.tellg());
        throw InputError(path, "gzip member " + std::to_string(member),
                         "ends at byte " + std::to_string(member_end) + " but " + std::to_string(size - member_end) +
                             " bytes follow it that are not another gzip member");
      }
      ++member;
      inflateReset(&z);
      continue;
    }
    if (rc == Z_OK || (rc == Z_BUF_ERROR && z.avail_in == 0)) continue;
    std::string why = z.msg ? z.msg : "error " + std::to_string(rc);
    if (why == "incorrect data check") why += ": the inflated data does not match the member's CRC-32";
    if (why == "incorrect length check") why += ": the inflated data does not have the member's length";
    throw InputError(path, "gzip member " + std::to_string(member),
                     "corrupt near compressed byte " + std::to_string(at()) + " (zlib: " + why + ")");
  }
}

}  // namespace vob
