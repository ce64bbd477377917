// gzip files inflated whole with zlib. A file that is not gzip (zlib would pass it through
// unchanged), a corrupt stream or a truncated one is one InputError line naming the member
// and the compressed byte. Concatenated members are one stream (as gzip reads them); bytes
// after the last member that do not start another are refused.
#pragma once
#include <string>

namespace vob {

inline constexpr size_t kMaxGunzipBytes = size_t(1) << 34;  // 16 GiB: a bomb is refused

// The inflated bytes; with `limit`, at most limit + 1 of them (the rest is not inflated: one
// more byte than a caller needs tells it the stream holds more, without holding it all).
std::string gunzip_file(const std::string& path, size_t limit = kMaxGunzipBytes);

}  // namespace vob
