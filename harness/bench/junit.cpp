#include "harness/bench/junit.h"

#include <cstdio>

#include "harness/bench/atomic_file.h"

namespace vob {

namespace {
std::string escaped(const std::string& s) {
  std::string out;
  for (unsigned char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        if (c >= 0x20 || c == '\t') out += static_cast<char>(c);  // XML 1.0 has no other control bytes
    }
  }
  return out;
}
std::string seconds_text(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6f", s);
  return b;
}
}  // namespace

std::string junit_xml(const std::string& suite_name, const std::vector<JunitCase>& cases) {
  int failures = 0;
  double total = 0;
  for (const auto& c : cases) {
    failures += c.failed ? 1 : 0;
    total += c.seconds;
  }
  const std::string counts = " tests=\"" + std::to_string(cases.size()) + "\" failures=\"" +
                             std::to_string(failures) + "\" errors=\"0\" time=\"" + seconds_text(total) + "\"";
  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  x += "<testsuites name=\"" + escaped(suite_name) + "\"" + counts + ">\n";
  x += "  <testsuite name=\"" + escaped(suite_name) + "\"" + counts + " skipped=\"0\">\n";
  for (const auto& c : cases) {
    x += "    <testcase classname=\"" + escaped(c.classname) + "\" name=\"" + escaped(c.name) + "\" time=\"" +
         seconds_text(c.seconds) + "\">\n";
    if (c.failed)
      x += "      <failure message=\"" + escaped(c.message) + "\" type=\"violation\">" + escaped(c.message) +
           "</failure>\n";
    x += "      <system-out>" + escaped(c.message) + "</system-out>\n";
    x += "    </testcase>\n";
  }
  x += "  </testsuite>\n</testsuites>\n";
  return x;
}

void write_junit(const std::string& path, const std::string& suite_name, const std::vector<JunitCase>& cases) {
  write_file_atomically(path, junit_xml(suite_name, cases));
}

}  // namespace vob
