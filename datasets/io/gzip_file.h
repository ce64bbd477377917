// gzip files inflated whole with zlib. A file that is not gzip (zlib would pass it through
// unchanged), a corrupt stream or a truncated one is one InputError line.
#pragma once
#include <string>

namespace vob {

inline constexpr size_t kMaxGunzipBytes = size_t(1) << 34;  // 16 GiB: a bomb is refused

std::string gunzip_file(const std::string& path);

}  // namespace vob
