#include "harness/bench/names.h"

#include <algorithm>
#include <cctype>
#include <vector>

namespace vob {

namespace {
std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Optimal string alignment distance: insertions, deletions, substitutions and swaps of
// neighbours ("mpov" is one edit from "mpvo"), the common typos.
size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}
}  // namespace

std::string closest_name(const std::string& name, const std::vector<std::string>& known) {
  const std::string n = lower(name);
  std::string best;
  size_t best_d = std::max<size_t>(1, n.size() / 3) + 1;
  for (const auto& k : known) {
    const std::string l = lower(k);
    const size_t d = n.size() >= 3 && l.rfind(n, 0) == 0 ? 1 : edit_distance(n, l);
    if (d < best_d) best = k, best_d = d;
  }
  return best;
}

std::string known_names_hint(const std::string& name, const std::vector<std::string>& known) {
  std::string s;
  const std::string close = closest_name(name, known);
  if (!close.empty()) s = "did you mean '" + close + "'? ";
  s += "known: ";
  for (size_t i = 0; i < known.size(); ++i) s += (i ? ", " : "") + known[i];
  return s;
}

}  // namespace vob
