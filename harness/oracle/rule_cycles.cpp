#include "harness/oracle/rule_cycles.h"

#include <algorithm>
#include <limits>
#include <map>
#include <numeric>
#include <stdexcept>
#include <utility>
#include <vector>

namespace vob {

namespace {

// The oracle's keys under the gl rule: a fragment drawn after x violates when its query
// key lies behind x's key (oracle.cpp).
void keys(const Fragment& f, bool cells, double& in, double& query) {
  if (cells) in = f.t_in, query = f.mid();
  else in = query = f.t_out;
}

struct Graph {
  std::vector<int64_t> start;
  std::vector<uint32_t> to;
};

Graph csr(int64_t nodes, const std::vector<std::pair<uint32_t, uint32_t>>& edges) {
  Graph g;
  g.start.assign(size_t(nodes) + 1, 0);
  for (const auto& e : edges) ++g.start[e.first + 1];
  std::partial_sum(g.start.begin(), g.start.end(), g.start.begin());
  g.to.resize(edges.size());
  std::vector<int64_t> cur(g.start.begin(), g.start.end() - 1);
  for (const auto& e : edges) g.to[size_t(cur[e.first]++)] = e.second;
  return g;
}

// Tarjan's strongly connected components, iteratively; component id per node.
std::vector<int32_t> components(const Graph& g) {
  const int64_t n = int64_t(g.start.size()) - 1;
  std::vector<int32_t> comp(static_cast<size_t>(n), -1), index(static_cast<size_t>(n), -1);
  std::vector<int32_t> low(static_cast<size_t>(n), 0);
  std::vector<uint32_t> stack;
  std::vector<std::pair<uint32_t, int64_t>> call;  // node, next edge
  int32_t counter = 0, ncomp = 0;
  for (int64_t s = 0; s < n; ++s) {
    if (index[size_t(s)] >= 0) continue;
    call.push_back({uint32_t(s), g.start[size_t(s)]});
    index[size_t(s)] = low[size_t(s)] = counter++;
    stack.push_back(uint32_t(s));
    while (!call.empty()) {
      auto& [v, e] = call.back();
      if (e < g.start[v + 1]) {
        const uint32_t w = g.to[size_t(e++)];
        if (index[w] < 0) {
          index[w] = low[w] = counter++;
          stack.push_back(w);
          call.push_back({w, g.start[w]});
        } else if (comp[w] < 0) {
          low[v] = std::min(low[v], index[w]);
        }
        continue;
      }
      const uint32_t done = v;
      call.pop_back();
      if (!call.empty()) low[call.back().first] = std::min(low[call.back().first], low[done]);
      if (low[done] == index[done]) {
        uint32_t w;
        do {
          w = stack.back();
          stack.pop_back();
          comp[w] = ncomp;
        } while (w != done);
        ++ncomp;
      }
    }
  }
  return comp;
}

// The fewest violated (edge, pixel) pairs over all orders of k primitives, w[a * k + b]
// counting the pixels where a must be drawn before b.
int64_t fewest(int k, const std::vector<int64_t>& w) {
  std::vector<int> p(static_cast<size_t>(k), 0);
  std::iota(p.begin(), p.end(), 0);
  int64_t best = std::numeric_limits<int64_t>::max();
  do {
    int64_t c = 0;
    for (int i = 0; i < k; ++i)
      for (int j = i + 1; j < k; ++j) c += w[size_t(p[j] * k + p[i])];  // p[j] after p[i]
    best = std::min(best, c);
  } while (std::next_permutation(p.begin(), p.end()));
  return best;
}

}  // namespace

nlohmann::json RuleCycles::to_json() const {
  return {{"components", components},          {"primitives", primitives},
          {"largest", largest},                {"cycle_fragments", cycle_fragments},
          {"cycle_pixels", cycle_pixels},      {"avoidable_fragments", avoidable_fragments},
          {"avoidable_pixels", avoidable_pixels}, {"forced_pairs", forced_pairs},
          {"excess", excess},                  {"unbounded", unbounded}};
}

RuleCycles find_rule_cycles(const FragmentCollector& fc, bool cells) {
  const int64_t prims = int64_t(fc.scene().num_primitives());
  std::vector<std::pair<uint32_t, uint32_t>> edges;
  int64_t nodes = prims;
  FragmentLists fl;
  std::vector<int> idx;
  std::vector<double> in, query, sorted;
  for (int b = 0; b < fc.num_bands(); ++b) {  // the precedence graph, prefixes as nodes
    fc.collect_band(b, fl);
    for (int64_t i = 0; i < fl.num_samples(); ++i) {
      const auto f = fl.local(i);
      const int n = int(f.size());
      if (n < 2) continue;
      in.resize(n), query.resize(n), idx.resize(n), sorted.resize(n);
      for (int j = 0; j < n; ++j) keys(f[j], cells, in[j], query[j]);
      std::iota(idx.begin(), idx.end(), 0);
      std::sort(idx.begin(), idx.end(), [&](int a, int c) { return in[a] < in[c]; });
      for (int k = 0; k < n; ++k) sorted[k] = in[idx[k]];
      if (nodes + n >= int64_t(std::numeric_limits<uint32_t>::max()))
        throw std::runtime_error("gl rule cycles: more than 2^32 graph nodes");
      const uint32_t base = uint32_t(nodes);  // node base + k: the k + 1 nearest fragments
      nodes += n;
      for (int k = 0; k < n; ++k) {
        edges.push_back({base + k, uint32_t(f[idx[k]].prim)});
        if (k > 0) edges.push_back({base + k, base + k - 1});
      }
      for (int j = 0; j < n; ++j) {
        const int k = int(std::lower_bound(sorted.begin(), sorted.end(), query[j]) - sorted.begin());
        if (k > 0) edges.push_back({uint32_t(f[j].prim), base + k - 1});
      }
    }
  }
  const std::vector<int32_t> comp = components(csr(nodes, edges));
  std::vector<std::pair<uint32_t, uint32_t>>().swap(edges);
  // Cyclic components: two or more primitives. Local index of each primitive in its own.
  std::map<int32_t, std::vector<int32_t>> members;
  {
    std::vector<int32_t> size(size_t(nodes), 0);
    for (int64_t p = 0; p < prims; ++p) ++size[size_t(comp[size_t(p)])];
    for (int64_t p = 0; p < prims; ++p)
      if (size[size_t(comp[size_t(p)])] > 1) members[comp[size_t(p)]].push_back(int32_t(p));
  }
  RuleCycles r;
  std::map<int32_t, int> local;
  for (const auto& [c, m] : members) {
    ++r.components;
    r.primitives += int64_t(m.size());
    r.largest = std::max(r.largest, int64_t(m.size()));
    for (size_t i = 0; i < m.size(); ++i) local[m[i]] = int(i);
  }
  std::map<int32_t, std::vector<int64_t>> weight;  // small components: w[a * k + b]
  std::map<int32_t, int64_t> order_cost;
  for (const auto& [c, m] : members)
    if (int(m.size()) <= kMaxExactComponent) weight[c].assign(m.size() * m.size(), 0);
  std::vector<int> cyc;
  for (int b = 0; b < fc.num_bands(); ++b) {  // split the order's violations
    fc.collect_band(b, fl);
    for (int64_t i = 0; i < fl.num_samples(); ++i) {
      const auto f = fl.local(i);
      const int n = int(f.size());
      if (n < 2) continue;
      in.resize(n), query.resize(n);
      for (int j = 0; j < n; ++j) keys(f[j], cells, in[j], query[j]);
      // The nearest key drawn so far (its component) and the nearest of any other component.
      double m1 = std::numeric_limits<double>::infinity(), m2 = m1;
      int32_t c1 = -1;
      bool violated = false, avoidable = false;
      for (int j = 0; j < n; ++j) {
        const int32_t cj = comp[size_t(f[j].prim)];
        if (query[j] > m1) {
          violated = true;
          const double other = c1 != cj ? m1 : m2;  // nearest drawn key outside j's component
          if (query[j] > other || !members.count(cj)) avoidable = true, ++r.avoidable_fragments;
          else ++r.cycle_fragments;
        }
        if (in[j] < m1) {
          if (c1 != cj) m2 = m1;
          m1 = in[j], c1 = cj;
        } else if (cj != c1 && in[j] < m2) {
          m2 = in[j];
        }
      }
      if (violated) ++(avoidable ? r.avoidable_pixels : r.cycle_pixels);
      cyc.clear();
      for (int j = 0; j < n; ++j)
        if (members.count(comp[size_t(f[j].prim)])) cyc.push_back(j);
      for (size_t x = 0; x < cyc.size(); ++x)
        for (size_t y = x + 1; y < cyc.size(); ++y) {  // cyc[x] drawn before cyc[y]
          const int a = cyc[x], c = cyc[y];
          const int32_t ca = comp[size_t(f[a].prim)];
          if (ca != comp[size_t(f[c].prim)]) continue;
          if (query[c] > in[a]) ++order_cost[ca];  // c had to come first
          auto w = weight.find(ca);
          if (w == weight.end()) continue;
          const size_t k = members[ca].size();
          const int la = local[f[a].prim], lc = local[f[c].prim];
          if (query[c] > in[a]) ++w->second[size_t(lc) * k + size_t(la)];
          if (query[a] > in[c]) ++w->second[size_t(la) * k + size_t(lc)];
        }
    }
  }
  for (const auto& [c, m] : members) {
    const auto it = order_cost.find(c);
    const int64_t cost = it == order_cost.end() ? 0 : it->second;
    const auto w = weight.find(c);
    if (w == weight.end()) {
      r.unbounded += cost > 0;
      continue;
    }
    const int64_t best = fewest(int(m.size()), w->second);
    r.forced_pairs += best;
    r.excess += cost - best;
  }
  return r;
}

}  // namespace vob
