#include <sstream>

#include "harness/bench/reporters.h"

namespace vob {

void ConsoleReporter::dataset(size_t index, size_t count, const std::string& label, const Scene& scene,
                              double seconds) const {
  say("dataset " + std::to_string(index + 1) + "/" + std::to_string(count) + " " + label + ": " +
      std::to_string(scene.num_primitives()) + " " + scene_kind_name(scene.kind()) + " (" +
      std::to_string(seconds).substr(0, 5) + " s)");
}

void ConsoleReporter::record(const Record& rec, bool written) const {
  std::ostringstream line;
  if (!rec.probe.empty())
    line << "  " << rec.key.substr(rec.key.find('|') + 1) << ": ";
  else
    line << "  " << rec.algorithm << " on " << rec.dataset << " view " << rec.view_index << " " << rec.w
         << "x" << rec.h << " t" << rec.threads << ": ";
  if (!written) {
    line << "another run wrote this record meanwhile; kept theirs";
  } else if (!rec.probe.empty()) {
    line << rec.seconds << " s";
  } else {
    line << rec.total.value("median", 0.0) * 1e3 << " ms/frame";
    if (!rec.input_fault.is_null())
      line << ", input fault: " << rec.input_fault.value("overlapping_pairs", 0) << " overlapping cell pairs";
    else if (!rec.oracle.is_null())
      line << ", " << rec.oracle.value("violating_pixels", 0) << " violating pixels";
  }
  say(line.str());
}

}  // namespace vob
