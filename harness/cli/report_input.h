// The results files given to `vobench report` are checked here before reports/report.py
// sees them, so a bad file gets one line naming the file, the line and the field (Python
// would print a traceback): every line must parse (within the JSON depth bound) and be a
// record with the fields the report reads, of the right types.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace vob {

// InputError(path, "line N", reason) for the first bad record; also when no file holds a
// record, unless `plans_suffice` and a file holds a plan line (a results folder whose run
// stopped before its first record still gets its pages: every planned job missing).
void check_report_inputs(const std::vector<std::string>& paths, bool plans_suffice = false);

// The reason a record cannot be reported ("field 'total.median' must be a number"), or
// empty when it can.
std::string report_record_problem(const nlohmann::json& record);

}  // namespace vob
