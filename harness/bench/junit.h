// JUnit XML for CI systems (GitLab, Jenkins, GitHub test reporters): one <testsuite> of
// test cases, a failing case carrying its message. `vobench check --junit FILE` writes one
// case per view with the oracle's counts in the message.
#pragma once
#include <string>
#include <vector>

namespace vob {

struct JunitCase {
  std::string name;       // "view 3"
  std::string classname;  // "vobench.check.centroid"
  double seconds = 0;
  bool failed = false;
  std::string message;    // one line: the counts (the failure's message when failed)
};

// The document; text is escaped for XML (and control bytes dropped).
std::string junit_xml(const std::string& suite_name, const std::vector<JunitCase>& cases);
// Written atomically; InputError naming the path when it cannot be written.
void write_junit(const std::string& path, const std::string& suite_name, const std::vector<JunitCase>& cases);

}  // namespace vob
