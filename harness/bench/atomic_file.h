// Orders, tables and reports are never left half-written: write to a fresh temporary file in
// the same folder, flush it to disk, then rename it over the target. The file gets the mode
// the umask allows (0666 & ~umask), like any file a user's program creates.
#pragma once
#include <string>

namespace vob {
// Creates missing parent folders. Throws InputError naming the path and the reason on
// failure, and leaves no temporary file behind.
void write_file_atomically(const std::string& path, const std::string& content);

// Throws InputError (one line) unless `folder` exists as a writable folder or could be
// created: the nearest existing ancestor must be a folder we may write into. Used to
// refuse an output location before any work is done.
void require_writable_folder(const std::string& folder);
}
