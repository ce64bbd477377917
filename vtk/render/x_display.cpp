#include "vtk/render/x_display.h"

#include <cstdlib>

#include <X11/Xlib.h>

namespace vob {

std::string x_display_problem() {
  Display* d = XOpenDisplay(nullptr);
  if (d) {
    XCloseDisplay(d);
    return "";
  }
  const char* name = std::getenv("DISPLAY");
  std::string quoted = "'";
  quoted += name ? name : "";
  return quoted + "'";
}

}  // namespace vob
