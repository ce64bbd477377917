#include "datasets/gmsh/msh4_blocks.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <cstdio>
#include <map>
#include <vector>

#include "datasets/gmsh/msh_text.h"
#include "harness/scene/input_error.h"

namespace vob {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// A cursor over the whole file reading gmsh's fields: binary ones raw (int 4 bytes,
// size_t and double 8), ASCII ones as whitespace-separated numbers, as gmsh's fscanf does.
// A field that is not there throws, naming the place being read.
class Fields {
 public:
  Fields(const std::string& path, const std::string& s, size_t at, bool binary)
      : path_(path), s_(s), at_(at), binary_(binary) {}

  void set_place(std::string place) { place_ = std::move(place); }
  size_t at() const { return at_; }
  size_t left() const { return s_.size() - at_; }

  uint64_t size() {
    if (binary_) return raw<uint64_t>("a count");
    uint64_t v = 0;
    token("a whole number", v);
    return v;
  }
  int32_t int32() {
    if (binary_) return raw<int32_t>("an integer");
    int32_t v = 0;
    token("an integer", v);
    return v;
  }
  void skip_reals(uint64_t n) {
    if (binary_) {
      if (n > left() / 8) fail("the file ends inside the data");
      at_ += size_t(n) * 8;
      return;
    }
    for (uint64_t i = 0; i < n; ++i) {
      double v = 0;
      token("a number", v);
    }
  }
  // Fewest bytes one field takes: a count bounded by left() / (fields * this) cannot be
  // larger than the file allows.
  size_t min_bytes(size_t binary_bytes) const { return binary_ ? binary_bytes : 2; }

  // After a section's data: the line "$End<name>" (whitespace before it allowed).
  void expect_end(const std::string& name) {
    while (at_ < s_.size() && is_space(s_[at_])) ++at_;
    const std::string tag = "$End" + name;
    if (s_.compare(at_, tag.size(), tag) != 0)
      throw InputError(path_, "$" + name,
                       "its data do not end at " + tag + " (the counts disagree with the data)");
    at_ += tag.size();
  }

  [[noreturn]] void fail(const std::string& reason) const { throw InputError(path_, place_, reason); }
  [[noreturn]] void fail_at(const std::string& element, const std::string& reason) const {
    throw InputError(path_, element, reason);
  }

 private:
  template <class T>
  T raw(const char* what) {
    if (left() < sizeof(T)) fail(std::string("the file ends where ") + what + " was expected");
    T v;
    std::memcpy(&v, s_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return v;
  }
  template <class T>
  void token(const char* what, T& v) {
    while (at_ < s_.size() && is_space(s_[at_])) ++at_;
    const char *p = s_.data() + at_, *end = s_.data() + s_.size();
    const char* stop = p;
    while (stop < end && !is_space(*stop)) ++stop;
    if (p == stop) fail(std::string("the file ends where ") + what + " was expected");
    // fscanf takes a leading '+'; from_chars does not.
    const char* digits = p + (*p == '+' && stop - p > 1 && *(p + 1) != '-' && *(p + 1) != '+' ? 1 : 0);
    const auto [next, ec] = std::from_chars(digits, stop, v);
    if (ec != std::errc() || next != stop)
      fail(std::string("expected ") + what + ", found '" + std::string(p, size_t(std::min<ptrdiff_t>(stop - p, 40))) +
           "'");
    at_ = size_t(stop - s_.data());
  }

  const std::string& path_;
  const std::string& s_;
  size_t at_;
  bool binary_;
  std::string place_;
};

// A count read from the file, refused when its entries cannot fit in the bytes left.
uint64_t bounded_count(Fields& f, size_t bytes_each, const char* what) {
  const uint64_t n = f.size();
  const uint64_t fit = f.left() / std::max<size_t>(bytes_each, 1);
  if (n > fit)
    f.fail("declares " + std::to_string(n) + " " + what + " but only " + std::to_string(f.left()) +
           " bytes follow");
  return n;
}

void read_entities(Fields& f) {
  f.set_place("$Entities");
  uint64_t count[4];
  for (uint64_t& c : count) c = f.size();
  for (int dim = 0; dim < 4; ++dim) {
    const uint64_t fit = f.left() / f.min_bytes(4 + 3 * 8 + 8);
    if (count[dim] > fit)
      f.fail("declares " + std::to_string(count[dim]) + " entities of dimension " + std::to_string(dim) +
             " but only " + std::to_string(f.left()) + " bytes follow");
    for (uint64_t i = 0; i < count[dim]; ++i) {
      f.set_place("$Entities: entity " + std::to_string(i + 1) + " of dimension " + std::to_string(dim));
      f.int32();                                    // tag
      f.skip_reals(dim == 0 ? 3 : 6);  // the point, or a bounding box
      const uint64_t physicals = bounded_count(f, f.min_bytes(4), "physical tags");
      for (uint64_t k = 0; k < physicals; ++k) f.int32();
      if (dim > 0) {
        const uint64_t bounding = bounded_count(f, f.min_bytes(4), "bounding entities");
        for (uint64_t k = 0; k < bounding; ++k) f.int32();
      }
    }
  }
  f.expect_end("Entities");
}

void read_nodes(Fields& f, std::vector<uint64_t>& tags) {
  f.set_place("$Nodes");
  const uint64_t blocks = bounded_count(f, f.min_bytes(3 * 4 + 8), "entity blocks");
  const uint64_t total = f.size();
  f.size();  // min and max tags: gmsh only warns when they are wrong
  f.size();
  for (uint64_t b = 0; b < blocks; ++b) {
    f.set_place("$Nodes: block " + std::to_string(b + 1));
    const int32_t dim = f.int32();
    f.int32();  // entity tag: gmsh makes a discrete entity for one $Entities lacks
    const int32_t parametric = f.int32();
    if (dim < 0 || dim > 3) f.fail("entity dimension " + std::to_string(dim) + " is not 0 to 3");
    if (parametric != 0 && parametric != 1) f.fail("parametric flag " + std::to_string(parametric) + " is not 0 or 1");
    const uint64_t per_node = 3 + (parametric ? uint64_t(dim) : 0);
    const uint64_t n = bounded_count(f, f.min_bytes(8) * (1 + per_node), "nodes");
    if (tags.size() + n > total)
      f.fail("holds " + std::to_string(tags.size() + n) + " nodes so far but the section declares " +
             std::to_string(total));
    for (uint64_t i = 0; i < n; ++i) {
      const uint64_t tag = f.size();
      if (tag == 0) f.fail("node tag 0 (tags start at 1)");
      if (tag > kMaxGmshTag) f.fail("node tag " + std::to_string(tag) + " " + kGmshTagLimit);
      tags.push_back(tag);
    }
    f.skip_reals(n * per_node);
  }
  f.set_place("$Nodes");
  if (tags.size() != total)
    f.fail("the blocks hold " + std::to_string(tags.size()) + " nodes but the section declares " +
           std::to_string(total));
  f.expect_end("Nodes");
}

// Whether a node tag was defined: a bitmap when tags are fairly dense, else a sorted list.
class NodeSet {
 public:
  explicit NodeSet(std::vector<uint64_t>& tags) : sorted_(tags) {
    std::sort(sorted_.begin(), sorted_.end());
    max_ = sorted_.empty() ? 0 : sorted_.back();
    if (max_ / 8 <= sorted_.size() + 1024) {
      dense_.assign(size_t(max_) + 1, 0);
      for (const uint64_t t : sorted_) dense_[size_t(t)] = 1;
    }
  }
  // The first tag given twice, or 0.
  uint64_t duplicate() const {
    const auto it = std::adjacent_find(sorted_.begin(), sorted_.end());
    return it == sorted_.end() ? 0 : *it;
  }
  bool has(uint64_t t) const {
    if (t == 0 || t > max_) return false;
    if (!dense_.empty()) return dense_[size_t(t)] != 0;
    return std::binary_search(sorted_.begin(), sorted_.end(), t);
  }

 private:
  std::vector<uint64_t>& sorted_;
  uint64_t max_ = 0;
  std::vector<uint8_t> dense_;
};

void read_elements(Fields& f, const NodeSet& nodes, const std::function<GmshElementType(int)>& type_of) {
  f.set_place("$Elements");
  const uint64_t blocks = bounded_count(f, f.min_bytes(3 * 4 + 8), "entity blocks");
  const uint64_t total = f.size();
  f.size();
  f.size();
  std::map<int, GmshElementType> types;
  uint64_t seen = 0;
  for (uint64_t b = 0; b < blocks; ++b) {
    f.set_place("$Elements: block " + std::to_string(b + 1));
    const int32_t dim = f.int32();
    const int32_t entity = f.int32();
    const int32_t code = f.int32();
    if (dim < 0 || dim > 3) f.fail("entity dimension " + std::to_string(dim) + " is not 0 to 3");
    auto it = types.find(code);
    if (it == types.end()) it = types.emplace(code, type_of(code)).first;
    const GmshElementType type = it->second;
    if (type.nodes <= 0) f.fail("element type " + std::to_string(code) + " is not a gmsh element type");
    if (type.dim != dim)
      f.fail("element type " + std::to_string(code) + " has dimension " + std::to_string(type.dim) +
             " but its entity (" + std::to_string(dim) + ", " + std::to_string(entity) + ") has dimension " +
             std::to_string(dim));
    const uint64_t n = bounded_count(f, f.min_bytes(8) * (1 + uint64_t(type.nodes)), "elements");
    seen += n;
    if (seen > total)
      f.fail("holds " + std::to_string(seen) + " elements so far but the section declares " + std::to_string(total));
    for (uint64_t e = 0; e < n; ++e) {
      const uint64_t tag = f.size();
      if (tag > kMaxGmshTag) f.fail("element tag " + std::to_string(tag) + " " + kGmshTagLimit);
      for (int k = 0; k < type.nodes; ++k) {
        const uint64_t node = f.size();
        if (!nodes.has(node))
          f.fail_at("element " + std::to_string(tag),
                    "names node " + std::to_string(node) + ", which $Nodes does not define");
      }
    }
  }
  f.expect_end("Elements");
}

}  // namespace

void check_msh4_blocks(const std::string& path, const std::function<GmshElementType(int)>& type_of) {
  std::string s;  // only MSH 4.1 files are read whole
  size_t at = 0;
  if (!read_msh_if_version(path, "4.1 ", s, at)) return;

  const size_t eol = s.find('\n', at);
  if (eol == std::string::npos) return;  // prescan_msh has checked the format line
  int binary = 0;
  if (std::sscanf(s.substr(at, eol - at).c_str(), "%*f %d", &binary) != 1) return;
  at = eol + 1;
  if (binary == 1) {
    int32_t one = 0;
    if (at + 4 > s.size()) throw InputError(path, "$MeshFormat", "the file ends before the byte-order integer");
    std::memcpy(&one, s.data() + at, 4);
    if (one != 1)
      throw InputError(path, "$MeshFormat",
                       "the byte-order integer is " + std::to_string(one) +
                           ", not 1 (files written on a machine of the other byte order are not read)");
    at += 4;
  }
  const size_t format_end = s.find("$EndMeshFormat", at);
  if (format_end == std::string::npos) throw InputError(path, "$MeshFormat", "no $EndMeshFormat");
  at = format_end + std::strlen("$EndMeshFormat");

  // The sections in file order; the nodes come before the elements (gmsh requires it).
  std::vector<uint64_t> tags;
  bool have_nodes = false;
  std::vector<size_t> element_sections;
  while (at < s.size()) {
    while (at < s.size() && is_space(s[at])) ++at;
    if (at >= s.size()) break;
    if (s[at] != '$') throw InputError(path, "byte " + std::to_string(at), "expected a section ($Name)");
    size_t stop = at + 1;
    while (stop < s.size() && !is_space(s[stop])) ++stop;
    const std::string name = s.substr(at + 1, stop - at - 1);
    // The section's data start on the next line (binary data may start with any byte).
    while (stop < s.size() && s[stop] != '\n') ++stop;
    stop = std::min(stop + 1, s.size());
    Fields f(path, s, stop, binary == 1);
    if (name == "Entities") {
      read_entities(f);
      at = f.at();
    } else if (name == "Nodes") {
      if (have_nodes) throw InputError(path, "$Nodes", "a second $Nodes section");
      read_nodes(f, tags);
      have_nodes = true;
      at = f.at();
    } else if (name == "Elements") {
      element_sections.push_back(stop);
      const size_t end = s.find("$EndElements", stop);
      if (end == std::string::npos) throw InputError(path, "$Elements", "no $EndElements");
      at = end + std::strlen("$EndElements");
    } else {  // gmsh reads and checks the other sections itself
      const size_t end = s.find("$End" + name, stop);
      if (end == std::string::npos) throw InputError(path, "$" + name, "no $End" + name);
      at = end + 4 + name.size();
    }
  }
  NodeSet nodes(tags);
  if (const uint64_t twice = nodes.duplicate())
    throw InputError(path, "node " + std::to_string(twice), "defined twice in $Nodes");
  for (const size_t start : element_sections) {
    Fields f(path, s, start, binary == 1);
    read_elements(f, nodes, type_of);
  }
}

}  // namespace vob
