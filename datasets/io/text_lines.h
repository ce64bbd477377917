// Line-oriented reading of small text formats (TetGen .node/.ele, OFF): the whole file in
// memory, '#' comments and blank lines skipped, tokens as views, and numbers parsed with
// errors that name the file, the line and the element.
#pragma once
#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace vob {

class TextLines {
 public:
  explicit TextLines(const std::string& path);  // InputError when unreadable
  // The next line with at least one token; false at the end of the file.
  bool next();
  const std::vector<std::string_view>& tokens() const { return tokens_; }
  int line() const { return line_; }
  const std::string& path() const { return path_; }
  // An upper bound for a count promised by a header, given the shortest possible record:
  // reserving by it cannot exhaust memory on a lying header.
  size_t capacity_for(int64_t promised, size_t min_record_bytes) const {
    const size_t fit = text_.size() / min_record_bytes + 1;
    return promised < 0 ? 0 : std::min(static_cast<size_t>(promised), fit);
  }
  // Fails unless `promised` records of at least `min_record_bytes` each fit in the file:
  // a header's count is checked against the file before anything is allocated for it.
  void require_fits(int64_t promised, size_t min_record_bytes, const std::string& element,
                    const std::string& what) const;
  // "line 12 (point 3)" style element names for errors.
  std::string where(const std::string& element) const;

  double number(size_t token, const std::string& element) const;   // finite double
  int64_t integer(size_t token, const std::string& element) const;
  // Throws unless the current line has at least n tokens.
  void need(size_t n, const std::string& element, const std::string& what) const;
  [[noreturn]] void fail(const std::string& element, const std::string& reason) const;

 private:
  std::string path_, text_;
  size_t pos_ = 0;
  int line_ = 0;
  std::vector<std::string_view> tokens_;
};

}  // namespace vob
