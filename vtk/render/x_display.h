// Whether an X server can be opened (VTK's X render window aborts the process when none
// can): kept apart because Xlib's macros (Bool, Status, ...) clash with vobench's names.
#pragma once
#include <string>

namespace vob {
// "" when $DISPLAY opens, else "'VALUE'" (the display that did not open).
std::string x_display_problem();
}  // namespace vob
