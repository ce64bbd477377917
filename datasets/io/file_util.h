// Small file helpers shared by the readers and writers. Files are never left half-written:
// `write` fills a temporary file beside `path`, which is then renamed over it (rename is
// atomic within a file system).
#pragma once
#include <functional>
#include <initializer_list>
#include <string>

namespace vob {

// Creates missing parent folders. InputError naming the path when the folder or file
// cannot be written; the temporary file is removed if `write` throws.
void write_atomically(const std::string& path, const std::function<void(const std::string& tmp)>& write);

// InputError naming the path unless it is an existing, readable regular file.
void require_readable_file(const std::string& path);

// Lower-case extension with the dot (".vtu"), or "" when there is none.
std::string file_extension(const std::string& path);

// Unless the file starts with one of `starts` (after blank bytes when `after_blanks`),
// InputError "is not a FORMAT file: it starts with '...', not EXPECTED" (or "it is
// empty"). Only the first 4 KiB are read: a reader's library may read a whole file of
// anything else before failing (gmsh parsed 4 GB of NUL bytes as a script for a minute).
void require_file_start(const std::string& path, std::initializer_list<const char*> starts, bool after_blanks,
                        const std::string& format, const std::string& expected);

}  // namespace vob
