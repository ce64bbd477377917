// A netCDF classic header (CDF-1, CDF-2 "64-bit offset", CDF-5) walked against the file's
// size before the netCDF library opens it: libnetcdf 4.9 takes the header's element counts
// on trust, and a mutated variable count (738 million in a 470 kB Exodus file) made it
// crash building its name table (SIGSEGV in NC_hashmapadd). Checks, from the format's
// specification: the list tags, every count and name length against the bytes left, name
// lengths within NC_MAX_NAME, attribute types of the file's version, variables' dimension
// ids. netCDF-4 (HDF5) files are not walked. One InputError naming file, part, reason.
#pragma once
#include <string>

namespace vob {

void prescan_netcdf_classic(const std::string& path);

}  // namespace vob
