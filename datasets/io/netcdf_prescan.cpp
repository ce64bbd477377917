#include "datasets/io/netcdf_prescan.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <vector>

#include "harness/scene/input_error.h"

namespace vob {

namespace {
constexpr uint32_t kDimension = 0x0A, kVariable = 0x0B, kAttribute = 0x0C;
constexpr uint64_t kMaxName = 256;  // NC_MAX_NAME

// Thrown when the walk reaches the end of the bytes read so far and the file has more.
struct NeedMore {};

// The record variables of a header: how many, the bytes of one record of all of them, where
// the first begins, and whether a size was clamped (a record over 4 GiB: count unknowable).
struct RecordVars {
  uint64_t vars = 0, size = 0, begin = UINT64_MAX;
  bool clamped = false;
};

class HeaderWalk {
 public:
  // `bytes`: the first bytes of a file of `file_size` bytes.
  HeaderWalk(const std::string& path, std::vector<unsigned char> bytes, uint64_t file_size)
      : path_(path), b_(std::move(bytes)), version_(b_[3]), whole_(b_.size() == file_size), file_size_(file_size) {}

  void run() {
    at_ = 4;
    RecordVars records;
    const uint64_t numrecs = big();  // NON_NEG, or STREAMING (all ones)
    const uint64_t dims = list(kDimension, "dimension list", 8);
    uint64_t record_dim = dims;  // none
    for (uint64_t i = 0; i < dims; ++i) {
      name("dimension " + std::to_string(i));
      if (big() == 0) record_dim = i;  // its length (0: the record dimension)
    }
    attributes("global attribute list");
    const uint64_t vars = list(kVariable, "variable list", 24);
    for (uint64_t i = 0; i < vars; ++i) {
      const std::string where = "variable " + std::to_string(i);
      const std::string var_name = name(where);
      const uint64_t rank = count(where + " dimension count", big(), 4);
      bool record = false;
      for (uint64_t k = 0; k < rank; ++k) {
        const uint64_t id = big();
        if (id >= dims)
          throw InputError(path_, where, "dimension id " + std::to_string(id) + " is not one of the " +
                                             std::to_string(dims) + " dimensions");
        record |= k == 0 && id == record_dim;
      }
      attributes(where + " attribute list");
      type(where);
      const uint64_t vsize = big();
      const uint64_t begin = version_ == 1 ? u32() : u64();  // 32-bit offsets in CDF-1 only
      // A fixed-size variable's data lies whole inside the file (netCDF pads a closed file
      // to it); the library reads what lies past a cut file as fill values, silently.
      if (!record && !(version_ != 5 && vsize == 0xFFFFFFFFu) && begin + vsize > file_size_)
        throw InputError(path_, where + " (" + var_name + ")",
                         "its " + std::to_string(vsize) + " bytes at offset " + std::to_string(begin) +
                             " end past the file's " + std::to_string(file_size_) + " bytes (the file is cut)");
      if (record) {
        ++records.vars;
        records.size += vsize;
        records.begin = std::min(records.begin, begin);
        records.clamped |= version_ != 5 && vsize == 0xFFFFFFFFu;  // a record over 4 GiB
      }
    }
    check_numrecs(numrecs, records);
  }

 private:
  // The record count against the bytes the records can have: VTK's Exodus reader sizes its
  // time steps by a truncated count and the netCDF library reads them all (one changed
  // byte of a CDF-5 count crashed it in ncx_getn_double_double). Then the last record must
  // be whole: netCDF pads a file written in no-fill mode to its full size when it is closed
  // (NC3_close, to NC_calcsize), and the library reads what lies past a cut file as zeros or
  // fill values (a file cut inside its last record read a nodal variable as zeros). Up to 3
  // bytes may be missing: the size NC_calcsize gives leaves out the padding of a lone record
  // variable's odd-sized record, which the header's vsize counts.
  void check_numrecs(uint64_t numrecs, const RecordVars& r) const {
    const uint64_t streaming = version_ == 5 ? UINT64_MAX : 0xFFFFFFFFu;
    if (numrecs == streaming || r.vars == 0 || r.size == 0 || r.clamped) return;
    const uint64_t room = r.begin < file_size_ ? (file_size_ - r.begin) / r.size + 1 : 1;
    if (numrecs > room)
      throw InputError(path_, "header", "record count " + std::to_string(numrecs) + " of " + std::to_string(r.size) +
                                            "-byte records cannot fit in the file's " +
                                            std::to_string(file_size_) + " bytes");
    constexpr uint64_t kPadding = 3;
    const uint64_t end = r.begin + numrecs * r.size;  // no overflow: numrecs <= room
    if (numrecs > 0 && end > file_size_ + kPadding)
      throw InputError(path_, "record " + std::to_string(numrecs - 1),
                       "the last of " + std::to_string(numrecs) + " records of " + std::to_string(r.size) +
                           " bytes ends at byte " + std::to_string(end) + ", past the file's " +
                           std::to_string(file_size_) + " bytes (the file is cut; a closed netCDF file holds its "
                           "records whole)");
  }
  uint32_t u32() {
    need(4, "header");
    const unsigned char* p = &b_[at_];
    at_ += 4;
    return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3];
  }
  uint64_t u64() {
    const uint64_t hi = u32();
    return hi << 32 | u32();
  }
  uint64_t big() { return version_ == 5 ? u64() : u32(); }  // NON_NEG: 64-bit in CDF-5
  uint64_t left() const { return b_.size() - at_; }
  void need(uint64_t n, const std::string& where) const {
    if (n <= left()) return;
    if (!whole_) throw NeedMore{};
    throw InputError(path_, where, "the header ends past the end of the file");
  }
  // A count of items of at least `min_bytes` each, against the file's bytes left.
  uint64_t count(const std::string& where, uint64_t n, uint64_t min_bytes) const {
    const uint64_t file_left = file_size_ - at_;
    if (n > file_left / min_bytes)
      throw InputError(path_, where, std::to_string(n) + " entries cannot fit in the " + std::to_string(file_left) +
                                         " bytes left");
    return n;
  }
  // ABSENT (two zeros) or the list's tag and its count.
  uint64_t list(uint32_t tag, const std::string& where, uint64_t min_bytes) {
    const uint32_t t = u32();
    const uint64_t n = big();
    if (t == 0 && n == 0) return 0;
    if (t != tag)
      throw InputError(path_, where, "tag " + std::to_string(t) + " where " + std::to_string(tag) +
                                         " (or an absent list) belongs");
    return count(where, n, min_bytes);
  }
  std::string name(const std::string& where) {
    const uint64_t n = big();
    if (n == 0 || n > kMaxName)
      throw InputError(path_, where, "name of " + std::to_string(n) + " bytes (1 to " + std::to_string(kMaxName) + ")");
    const uint64_t padded = (n + 3) / 4 * 4;
    need(padded, where);
    std::string out;  // printable only: it goes into a message line
    for (uint64_t k = 0; k < n; ++k) {
      const unsigned char c = b_[at_ + k];
      out += c >= 32 && c < 127 ? char(c) : '?';
    }
    at_ += padded;
    return out;
  }
  uint64_t type(const std::string& where) {
    const uint32_t t = u32();
    static const int kSize[] = {0, 1, 1, 2, 4, 4, 8, 1, 2, 4, 8, 8};  // NC_BYTE .. NC_UINT64
    if (t < 1 || t > (version_ == 5 ? 11u : 6u))
      throw InputError(path_, where, "type " + std::to_string(t) + " is not a netCDF type of this format");
    return kSize[t];
  }
  void attributes(const std::string& where) {
    const uint64_t n = list(kAttribute, where, 12);
    for (uint64_t i = 0; i < n; ++i) {
      const std::string what = where + " entry " + std::to_string(i);
      name(what);
      const uint64_t size = type(what);
      const uint64_t values = count(what + " values", big(), size);
      const uint64_t padded = (values * size + 3) / 4 * 4;
      need(padded, what);
      at_ += padded;
    }
  }

  const std::string& path_;
  std::vector<unsigned char> b_;
  unsigned char version_;
  bool whole_;
  uint64_t file_size_;
  uint64_t at_ = 0;
};
}  // namespace

void prescan_netcdf_classic(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw InputError(path, "file", "cannot be opened");
  const std::streamoff size = in.tellg();
  // The header lies before the data and is a few kB in an Exodus file: read 64 kB, and more
  // only when the walk needs it (up to 64 MB, past which no Exodus header goes).
  constexpr std::streamoff kFirst = std::streamoff(64) << 10, kMost = std::streamoff(64) << 20;
  for (std::streamoff keep = std::min(size, kFirst);; keep = std::min(size, keep * 16)) {
    std::vector<unsigned char> bytes(static_cast<size_t>(keep));
    in.seekg(0);
    in.read(reinterpret_cast<char*>(bytes.data()), keep);
    if (keep < 4 || std::memcmp(bytes.data(), "CDF", 3) != 0) return;
    try {
      HeaderWalk(path, std::move(bytes), static_cast<uint64_t>(size)).run();
      return;
    } catch (const NeedMore&) {
      if (keep >= kMost)
        throw InputError(path, "header", "runs past the first " + std::to_string(keep) +
                                             " bytes (no Exodus header is that long)");
    }
  }
}

}  // namespace vob
