#include "datasets/gmsh/msh2_node_refs.h"

#include <algorithm>
#include <climits>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <map>
#include <vector>

#include "datasets/gmsh/msh_text.h"
#include "harness/scene/input_error.h"

namespace vob {
namespace {

// A read-only cursor over the file; every read checks the bounds (false: the scan stops
// and gmsh reports the file).
struct Cursor {
  const std::string& s;
  size_t at = 0;
  bool line(std::string_view& out) {  // the rest of the line, without its '\n'
    if (at >= s.size()) return false;
    const size_t end = s.find('\n', at);
    const size_t stop = end == std::string::npos ? s.size() : end;
    out = std::string_view(s).substr(at, stop - at);
    at = end == std::string::npos ? s.size() : end + 1;
    return true;
  }
  bool int32(int32_t& v) {
    if (at + 4 > s.size()) return false;
    std::memcpy(&v, s.data() + at, 4);
    at += 4;
    return true;
  }
  bool skip(size_t n) {
    if (at + n > s.size()) return false;
    at += n;
    return true;
  }
};

// Whole numbers of a text line, in order (false at anything else). from_chars, no copies:
// a 72 MB ASCII file has 1.3M element lines.
bool numbers(std::string_view line, std::vector<int64_t>& out) {
  out.clear();
  const char *p = line.data(), *end = p + line.size();
  for (;;) {
    while (p < end && (*p == ' ' || *p == '\t' || *p == '\r')) ++p;
    if (p == end) return true;
    int64_t v = 0;
    const auto [next, ec] = std::from_chars(p, end, v);
    if (ec != std::errc() || (next < end && *next != ' ' && *next != '\t' && *next != '\r')) return false;
    out.push_back(v);
    p = next;
  }
}

// The first whole number of a line (a node's tag; the coordinates after it are not read);
// one too large for int64_t is read as INT64_MAX (a tag check refuses it).
bool first_number(std::string_view line, int64_t& v) {
  const char *p = line.data(), *end = p + line.size();
  while (p < end && (*p == ' ' || *p == '\t')) ++p;
  const std::errc ec = std::from_chars(p, end, v).ec;
  if (ec == std::errc::result_out_of_range && p < end && *p != '-') v = INT64_MAX;
  return ec == std::errc() || v == INT64_MAX;
}

// "line N" of the byte at `at` (counted only for a message).
std::string line_of(const std::string& s, size_t at) {
  return "line " + std::to_string(std::count(s.begin(), s.begin() + std::min(at, s.size()), '\n') + 1);
}

// A node or element tag of an ASCII line gmsh would narrow (see kMaxGmshTag) is refused.
void check_tag(const std::string& path, const char* kind, int64_t tag, const std::string& s, size_t line_start) {
  if (tag <= int64_t(kMaxGmshTag)) return;
  std::string_view word(s.data() + line_start, s.size() - line_start);
  word.remove_prefix(std::min(word.find_first_not_of(" \t"), word.size()));
  word = word.substr(0, word.find_first_of(" \t\r\n"));  // the tag as written
  throw InputError(path, std::string(kind) + " " + std::string(word) + " (" + line_of(s, line_start) + ")",
                   std::string("tag ") + kGmshTagLimit);
}

}  // namespace

void check_msh2_node_refs(const std::string& path, const std::function<int(int)>& nodes_of) {
  std::string s;  // only MSH 2 files are read whole
  size_t version_at = 0;
  if (!read_msh_if_version(path, "2", s, version_at)) return;
  Cursor fmt{s, version_at};
  std::string_view line;
  std::vector<int64_t> v;
  if (!fmt.line(line)) return;
  const std::string head(line);
  double version = 0;
  int binary = 0, data_size = 0;
  if (std::sscanf(head.c_str(), "%lf %d %d", &version, &binary, &data_size) != 3) return;
  if (!(version >= 2 && version < 3) || (binary == 1 && data_size != 8)) return;

  // The sections in file order: nodes read as they come (a binary section's length is
  // known, so its data is never searched for text), elements kept for after the nodes.
  std::vector<int64_t> tags;
  std::vector<size_t> element_sections;
  Cursor c{s, fmt.at};
  while (c.line(line)) {
    if (line.empty() || line[0] != '$') continue;  // between sections
    std::string name(line.substr(1));
    if (!name.empty() && name.back() == '\r') name.pop_back();
    if (name == "Nodes" || name == "ParametricNodes") {
      int64_t n = 0;
      if (!c.line(line) || !first_number(line, n) || n < 0) return;
      for (int64_t i = 0; i < n; ++i) {
        if (binary == 1 && name == "Nodes") {
          int32_t tag = 0;
          if (!c.int32(tag) || !c.skip(3 * 8)) return;
          tags.push_back(tag);
        } else {
          int64_t tag = 0;
          const size_t start = c.at;
          if (!c.line(line) || !first_number(line, tag)) return;
          check_tag(path, "node", tag, s, start);
          tags.push_back(tag);
        }
      }
    } else if (name == "Elements") {
      element_sections.push_back(c.at);
      int64_t m = 0;
      if (!c.line(line) || !first_number(line, m) || m < 0) return;
      if (binary == 1) {
        for (int64_t done = 0; done < m;) {  // blocks: type, count, tags per element
          const size_t start = c.at;
          int32_t type = 0, count = 0, ntags = 0;
          if (!c.int32(type) || !c.int32(count) || !c.int32(ntags)) return;
          // gmsh said only "Error loading" for these.
          const std::string where = "$Elements (byte " + std::to_string(start) + ")";
          const std::string block = "block of type " + std::to_string(type) + ": ";
          if (count <= 0 || count > m - done)
            throw InputError(path, where, block + "element count " + std::to_string(count) + " is not within the " +
                                              std::to_string(m - done) + " elements left of the section's " +
                                              std::to_string(m));
          if (ntags < 0) throw InputError(path, where, block + "tag count " + std::to_string(ntags) + " is negative");
          const int nodes = nodes_of(type);
          if (nodes <= 0) return;  // gmsh names the type
          const uint64_t bytes = 4 * (uint64_t(count) * (1 + uint64_t(ntags) + uint64_t(nodes)));
          if (!c.skip(bytes))
            throw InputError(path, where, block + std::to_string(count) + " elements take " + std::to_string(bytes) +
                                              " bytes but only " + std::to_string(s.size() - c.at) + " follow");
          done += count;
        }
      } else {
        for (int64_t e = 0; e < m; ++e)
          if (!c.line(line)) return;
      }
    } else if (name.rfind("End", 0) != 0) {  // another section ($NodeData, ...): to its end line
      const size_t end = find_line(s, "$End" + name, c.at);
      if (end == std::string::npos) return;
      c.at = end;
    }
  }
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  const bool dense = !tags.empty() && tags.front() == 1 && tags.back() == int64_t(tags.size());
  const auto check = [&](int64_t element, int64_t node) {
    const bool known = dense ? node >= 1 && node <= int64_t(tags.size())
                             : std::binary_search(tags.begin(), tags.end(), node);
    if (!known)
      throw InputError(path, "element " + std::to_string(element),
                       "names node " + std::to_string(node) + ", which $Nodes does not define");
  };

  std::map<int64_t, int> node_counts;  // per type: gmsh's lookup is not cheap per element
  const auto node_count = [&](int64_t type) {
    if (type < 0 || type > INT32_MAX) return 0;
    const auto [it, fresh] = node_counts.try_emplace(type, 0);
    if (fresh) it->second = nodes_of(int(type));
    return it->second;
  };
  for (size_t start : element_sections) {
    Cursor c{s, start};
    int64_t m = 0;
    if (!c.line(line) || !first_number(line, m) || m < 0) return;
    if (binary == 1) {
      for (int64_t done = 0; done < m;) {
        int32_t type = 0, count = 0, ntags = 0;
        if (!c.int32(type) || !c.int32(count) || !c.int32(ntags) || count <= 0 || ntags < 0) return;
        const int nodes = nodes_of(type);
        for (int32_t e = 0; e < count; ++e) {
          int32_t id = 0, node = 0;
          if (!c.int32(id) || !c.skip(4 * size_t(ntags))) return;
          for (int k = 0; k < nodes; ++k) {
            if (!c.int32(node)) return;
            check(id, node);
          }
        }
        done += count;
      }
    } else {
      for (int64_t e = 0; e < m; ++e) {  // id type ntags tag... node...
        const size_t start = c.at;
        int64_t id = 0;
        if (!c.line(line) || !first_number(line, id)) return;
        check_tag(path, "element", id, s, start);
        if (!numbers(line, v) || v.size() < 3) return;
        // gmsh reads numbers, not lines: a wrong tag count made it fail later on with
        // "Error loading" or "Wrong node index 0".
        const auto where = [&] { return "element " + std::to_string(v[0]) + " (" + line_of(s, start) + ")"; };
        if (v[2] < 0) throw InputError(path, where(), "tag count " + std::to_string(v[2]) + " is negative");
        const int nodes = node_count(v[1]);
        if (nodes > 0 && int64_t(v.size()) - 3 - nodes != v[2])
          throw InputError(path, where(), "type " + std::to_string(v[1]) + " has " + std::to_string(nodes) +
                                              " nodes and the tag count is " + std::to_string(v[2]) + ", but the line holds " +
                                              std::to_string(v.size() - 3) + " numbers after the tag count");
        if (int64_t(v.size()) < 3 + v[2]) return;  // a type gmsh does not know: it names it
        for (size_t k = 3 + size_t(v[2]); k < v.size(); ++k) check(v[0], v[k]);
      }
    }
  }
}

}  // namespace vob
