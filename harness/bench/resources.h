// Where vobench's own files are (report scripts, suites, shaders): the one place that
// knows. Installed, they are in share/vobench beside the prefix libvobench.so was loaded
// from, so a moved prefix still works and the source tree may be gone; in a build tree
// they are the source tree's.
#pragma once
#include <string>

namespace vob {

// share/vobench of the installed prefix, or the source tree when not installed.
const std::string& resource_dir();
// resource_dir() + "/" + relative ("reports/report.py", "datasets/suites").
std::string resource_path(const std::string& relative);
// True when the files come from an installed prefix (then nothing is written beside them).
bool installed();
// The git description of the sources the program was built from ("" when unknown):
// installed, the one recorded by `cmake --install`; else the source tree's now.
std::string source_revision();

}  // namespace vob
