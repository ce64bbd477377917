#include "harness/bench/sorter_answer.h"

#include <charconv>
#include <cmath>
#include <string_view>

#include <nlohmann/json.hpp>

namespace vob {

namespace {
using json = nlohmann::json;

std::string quoted(const std::string& s) { return "'" + s.substr(0, 60) + (s.size() > 60 ? "...'" : "'"); }

// Depth 1 is the answer object; "order" and "phases" are read at depth 2, any other
// value is skipped whatever its depth.
class AnswerSax final : public nlohmann::json_sax<json> {
 public:
  explicit AnswerSax(SorterAnswer& out) : out_(out) {}
  std::string problem;
  bool saw_order = false;

  bool null() override { return scalar("null"); }
  bool boolean(bool b) override { return scalar(b ? "true" : "false"); }
  bool number_integer(number_integer_t v) override { return integer(v, std::to_string(v)); }
  bool number_unsigned(number_unsigned_t v) override {
    return v > static_cast<number_unsigned_t>(INT32_MAX) ? scalar(std::to_string(v))
                                                         : integer(static_cast<int64_t>(v), std::to_string(v));
  }
  bool number_float(number_float_t v, const string_t& text) override {
    if (field_ == Field::Phase && depth_ == 2) return phase(v, text);
    return scalar(text);
  }
  bool string(string_t& s) override { return scalar("\"" + s.substr(0, 20) + "\""); }
  bool binary(binary_t&) override { return scalar("binary"); }
  bool start_object(std::size_t) override {
    if (depth_ == 0) {
      ++depth_;
      return true;
    }
    if (depth_ == 1 && key_ == "phases") field_ = Field::Phases, saw_phases_ = true;
    else if (depth_ == 1 && key_ == "order") return fail("\"order\" is not an array of ids");
    else if (field_ == Field::Order && depth_ == 2) return scalar("an object");
    else if (field_ == Field::Phase) return fail("phase '" + key_ + "' is an object, not seconds");
    ++depth_;
    return true;
  }
  bool end_object() override { return end(); }
  bool start_array(std::size_t) override {
    if (depth_ == 0) return fail("answered no \"order\" array (not a JSON object)");
    if (depth_ == 1 && key_ == "order") {
      field_ = Field::Order;
      saw_order = true;
    } else if (depth_ == 1 && key_ == "phases") {
      return fail("\"phases\" is not an object of seconds");
    } else if (field_ == Field::Order && depth_ == 2) {
      return scalar("an array");
    } else if (field_ == Field::Phase) {
      return fail("phase '" + key_ + "' is an array, not seconds");
    }
    ++depth_;
    return true;
  }
  bool end_array() override { return end(); }
  bool key(string_t& k) override {
    // A repeated member is refused: one JSON library keeps the last, another joins them.
    if (depth_ == 1) {
      if ((k == "order" && saw_order) || (k == "phases" && saw_phases_)) return fail("answered \"" + k + "\" twice");
      key_ = k;
    }
    if (depth_ == 2 && field_ == Field::Phases) {
      for (const auto& [name, seconds] : out_.phases)
        if (name == k) return fail("phase '" + k + "' given twice");
      key_ = k;
      field_ = Field::Phase;
    }
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
    if (problem.empty()) problem = "malformed";
    return false;
  }

 private:
  enum class Field { Other, Order, Phases, Phase };
  SorterAnswer& out_;
  int depth_ = 0;
  bool saw_phases_ = false;
  std::string key_;
  Field field_ = Field::Other;

  bool fail(const std::string& why) {
    problem = why;
    return false;
  }
  bool end() {
    --depth_;
    if (depth_ == 1) field_ = Field::Other;
    return true;
  }
  bool integer(int64_t v, const std::string& text) {
    if (field_ == Field::Order && depth_ == 2) {
      if (v < INT32_MIN || v > INT32_MAX) return scalar(text);
      out_.order.push_back(static_cast<int32_t>(v));
      return true;
    }
    if (field_ == Field::Phase && depth_ == 2) return phase(static_cast<double>(v), text);
    return scalar(text);
  }
  bool phase(double v, const std::string& text) {
    if (!std::isfinite(v) || v < 0) return fail("phase '" + key_ + "' is " + text + ", not seconds");
    out_.phases.emplace_back(key_, v);
    field_ = Field::Phases;
    return true;
  }
  // A value that is neither an id in "order" nor seconds in "phases".
  bool scalar(const std::string& text) {
    if (depth_ == 0) return fail("answered no \"order\" array (not a JSON object)");
    if (field_ == Field::Order && depth_ == 2)
      return fail("order[" + std::to_string(out_.order.size()) + "] is " + text + ", not an id");
    if (field_ == Field::Phase && depth_ == 2) return fail("phase '" + key_ + "' is " + text + ", not seconds");
    if (depth_ == 1 && key_ == "order") return fail("\"order\" is " + text + ", not an array of ids");
    if (depth_ == 1 && key_ == "phases") return fail("\"phases\" is " + text + ", not an object of seconds");
    return true;
  }
};
// The SAX decode of a whole line; empty when it is an answer.
std::string sax_decode(const std::string& line, SorterAnswer& out) {
  out = {};
  AnswerSax sax(out);
  const bool ok = json::sax_parse(line, &sax);
  if (!ok || !sax.problem.empty()) {
    if (sax.problem.empty() || sax.problem == "malformed") return "answered malformed JSON: " + quoted(line);
    return sax.problem;
  }
  if (!sax.saw_order) return "answered no \"order\" array: " + quoted(line);
  return "";
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The common shape, {"order": [plain integers], ...}, read with from_chars (ten times the
// SAX parser's speed); the members after "order" are small and go through sax_decode.
// false: anything else, then the SAX decode decides and names the fault.
bool fast_decode(const std::string& line, SorterAnswer& out) {
  const char* p = line.data();
  const char* const e = p + line.size();
  const auto ws = [&] {
    while (p < e && (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n')) ++p;
  };
  const auto take = [&](char c) {
    ws();
    if (p == e || *p != c) return false;
    ++p;
    return true;
  };
  if (!take('{')) return false;
  ws();
  if (e - p < 7 || std::string_view(p, 7) != "\"order\"") return false;
  p += 7;
  if (!take(':') || !take('[')) return false;
  out = {};
  ws();
  if (p < e && *p == ']') {
    ++p;
  } else {
    for (;;) {
      ws();
      const char* digits = p < e && *p == '-' ? p + 1 : p;
      if (digits + 1 < e && digits[0] == '0' && is_digit(digits[1])) return false;  // JSON has no leading zeros
      int32_t v = 0;
      const auto [q, ec] = std::from_chars(p, e, v);
      if (ec != std::errc() || q == p) return false;
      p = q;
      out.order.push_back(v);
      ws();
      if (p == e) return false;
      if (*p == ',') {
        ++p;
        continue;
      }
      if (*p != ']') return false;  // 1.5, 1e3, ... : the SAX decode names them
      ++p;
      break;
    }
  }
  ws();
  if (p < e && *p == '}') {
    ++p;
    ws();
    return p == e;
  }
  if (!take(',')) return false;
  ws();
  if (p == e || *p != '"') return false;
  SorterAnswer rest;
  const std::string tail = "{\"order\":[]," + std::string(p, e);
  if (!sax_decode(tail, rest).empty() || !rest.order.empty()) return false;  // a second "order": SAX decides
  out.phases = std::move(rest.phases);
  return true;
}
}  // namespace

std::string decode_sorter_answer(const std::string& line, SorterAnswer& out) {
  if (fast_decode(line, out)) return "";
  return sax_decode(line, out);
}

}  // namespace vob
