#include "datasets/io/text_lines.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "harness/scene/input_error.h"

namespace vob {

TextLines::TextLines(const std::string& path) : path_(path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "file", std::string("cannot be opened: ") + std::strerror(errno));
  std::ostringstream ss;
  ss << in.rdbuf();
  text_ = ss.str();
}

bool TextLines::next() {
  while (pos_ < text_.size()) {
    size_t end = text_.find('\n', pos_);
    if (end == std::string::npos) end = text_.size();
    std::string_view l(text_.data() + pos_, end - pos_);
    pos_ = end + 1;
    ++line_;
    if (const size_t hash = l.find('#'); hash != std::string_view::npos) l = l.substr(0, hash);
    tokens_.clear();
    size_t i = 0;
    while (i < l.size()) {
      while (i < l.size() && (l[i] == ' ' || l[i] == '\t' || l[i] == '\r')) ++i;
      const size_t start = i;
      while (i < l.size() && !(l[i] == ' ' || l[i] == '\t' || l[i] == '\r')) ++i;
      if (i > start) tokens_.push_back(l.substr(start, i - start));
    }
    if (!tokens_.empty()) return true;
  }
  tokens_.clear();
  return false;
}

std::string TextLines::where(const std::string& element) const {
  return element.empty() ? "line " + std::to_string(line_)
                         : element + " (line " + std::to_string(line_) + ")";
}

void TextLines::fail(const std::string& element, const std::string& reason) const {
  throw InputError(path_, where(element), reason);
}

void TextLines::need(size_t n, const std::string& element, const std::string& what) const {
  if (tokens_.size() < n)
    fail(element, "expected " + what + ", found " + std::to_string(tokens_.size()) + " values");
}

void TextLines::require_fits(int64_t promised, size_t min_record_bytes, const std::string& element,
                             const std::string& what) const {
  if (promised > 0 && static_cast<uint64_t>(promised) > text_.size() / min_record_bytes + 1)
    fail(element, what + " " + std::to_string(promised) + " cannot fit in a file of " +
                      std::to_string(text_.size()) + " bytes");
}

double TextLines::number(size_t t, const std::string& element) const {
  const std::string_view s = tokens_.at(t);
  double v = 0;
  const char* b = s.data();
  if (!s.empty() && *b == '+') ++b;  // from_chars rejects a leading '+'
  const auto [p, ec] = std::from_chars(b, s.data() + s.size(), v);
  if (ec != std::errc() || p != s.data() + s.size())
    fail(element, "'" + std::string(s) + "' is not a number");
  if (!std::isfinite(v)) fail(element, "value '" + std::string(s) + "' is not finite");
  return v;
}

int64_t TextLines::integer(size_t t, const std::string& element) const {
  const std::string_view s = tokens_.at(t);
  int64_t v = 0;
  const char* b = s.data();
  if (!s.empty() && *b == '+') ++b;
  const auto [p, ec] = std::from_chars(b, s.data() + s.size(), v);
  if (ec != std::errc() || p != s.data() + s.size())
    fail(element, "'" + std::string(s) + "' is not an integer");
  return v;
}

}  // namespace vob
