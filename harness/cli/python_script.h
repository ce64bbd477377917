// The one way vobench starts Python: Debian's python3 (VOB_PYTHON, which sees
// python3-matplotlib) on a script under reports/, with the caller's environment.
#pragma once
#include <string>
#include <vector>

namespace vob {

// Runs reports/SCRIPT with `args` and waits; returns its exit status (2 when it died of a
// signal). InputError when python3 cannot be started.
int run_python_script(const std::string& script, const std::vector<std::string>& args);

}  // namespace vob
