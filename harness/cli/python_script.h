// The one way vobench starts Python: Debian's python3 (VOB_PYTHON, which sees
// python3-matplotlib) on a script under reports/, with the caller's environment.
#pragma once
#include <string>
#include <vector>

namespace vob {

// Runs reports/SCRIPT with `args` and waits; returns its exit status (2 when it died of a
// signal). InputError when python3 cannot be started.
int run_python_script(const std::string& script, const std::vector<std::string>& args);

// Where `--format gbench` writes Google Benchmark's JSON of a results file (reports/gbench.py):
// "DIR/results.jsonl" -> "DIR/results.gbench.json".
std::string gbench_path(const std::string& results);

}  // namespace vob
