// The on-disk cache for real data: members extracted from the libcgal-demo archive and
// TetGen meshes. Everything in it is written atomically and only once; a second process
// racing for the same entry finds it complete or builds its own copy and renames it over.
#pragma once
#include <string>

namespace vob {

// $XDG_CACHE_HOME/vobench, else $HOME/.cache/vobench (created on first use).
std::string cache_dir();

// The path of `member` (e.g. "data/meshes/elephant.off") of the libcgal-demo data archive
// (VOB_CGAL_DATA), extracted with `tar xzf ARCHIVE -O member` on first use.
std::string cgal_data_file(const std::string& member);

// A short stable hex hash (FNV-1a 64) for cache keys.
std::string stable_hash(const std::string& text);

}  // namespace vob
