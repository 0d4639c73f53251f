#include "core/planning/graph.hpp"

#include <algorithm>
#include <limits>
#include <queue>
#include <utility>

namespace csl {

void UnionFind::reset(int n) {
  parent_.resize(static_cast<std::size_t>(n));
  size_.assign(static_cast<std::size_t>(n), 1);
  for (int i = 0; i < n; ++i) parent_[static_cast<std::size_t>(i)] = i;
  sets_ = n;
}

int UnionFind::add() {
  const int x = size();
  parent_.push_back(x);
  size_.push_back(1);
  ++sets_;
  return x;
}

int UnionFind::find(int x) {
  auto& p = parent_;
  while (p[static_cast<std::size_t>(x)] != x) {
    const auto ux = static_cast<std::size_t>(x);
    p[ux] = p[static_cast<std::size_t>(p[ux])];  // halve the path
    x = p[ux];
  }
  return x;
}

bool UnionFind::unite(int a, int b) {
  a = find(a);
  b = find(b);
  if (a == b) return false;
  if (size_[static_cast<std::size_t>(a)] < size_[static_cast<std::size_t>(b)]) std::swap(a, b);
  parent_[static_cast<std::size_t>(b)] = a;
  size_[static_cast<std::size_t>(a)] += size_[static_cast<std::size_t>(b)];
  --sets_;
  return true;
}

std::vector<int> shortest_path(int vertices, const std::vector<GraphEdge>& edges,
                               const std::function<bool(int)>& usable, int source, int target,
                               const std::function<double(int)>& heuristic, std::vector<int>* via) {
  const auto n = static_cast<std::size_t>(vertices);
  // Adjacency in compressed rows, built for this search.
  std::vector<int> start(n + 1, 0);
  for (std::size_t i = 0; i < edges.size(); ++i)
    if (usable(static_cast<int>(i))) {
      ++start[static_cast<std::size_t>(edges[i].a) + 1];
      ++start[static_cast<std::size_t>(edges[i].b) + 1];
    }
  for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<int> fill(start.begin(), start.end() - 1), adjacent(static_cast<std::size_t>(start[n]));
  std::vector<int> edge_of(adjacent.size());
  std::vector<double> weight(adjacent.size());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (!usable(static_cast<int>(i))) continue;
    const GraphEdge& e = edges[i];
    const auto fa = static_cast<std::size_t>(fill[static_cast<std::size_t>(e.a)]++);
    const auto fb = static_cast<std::size_t>(fill[static_cast<std::size_t>(e.b)]++);
    adjacent[fa] = e.b;
    weight[fa] = e.length;
    adjacent[fb] = e.a;
    weight[fb] = e.length;
    edge_of[fa] = edge_of[fb] = static_cast<int>(i);
  }

  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> dist(n, inf);
  std::vector<int> previous(n, -1), previous_edge(n, -1);
  std::vector<char> closed(n, 0);
  using Item = std::pair<double, int>;  // (f = g + h, vertex): smaller f, then smaller index
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  dist[static_cast<std::size_t>(source)] = 0.0;
  open.push({heuristic(source), source});
  while (!open.empty()) {
    const int v = open.top().second;
    open.pop();
    const auto uv = static_cast<std::size_t>(v);
    if (closed[uv]) continue;
    closed[uv] = 1;
    if (v == target) break;
    for (int j = start[uv]; j < start[uv + 1]; ++j) {
      const auto w = static_cast<std::size_t>(adjacent[static_cast<std::size_t>(j)]);
      const double d = dist[uv] + weight[static_cast<std::size_t>(j)];
      if (d < dist[w]) {
        dist[w] = d;
        previous[w] = v;
        previous_edge[w] = edge_of[static_cast<std::size_t>(j)];
        open.push({d + heuristic(static_cast<int>(w)), static_cast<int>(w)});
      }
    }
  }
  std::vector<int> path;
  if (via) via->clear();
  if (!closed[static_cast<std::size_t>(target)]) return path;
  for (int v = target; v != -1; v = previous[static_cast<std::size_t>(v)]) {
    path.push_back(v);
    if (via && v != source) via->push_back(previous_edge[static_cast<std::size_t>(v)]);
  }
  std::reverse(path.begin(), path.end());
  if (via) std::reverse(via->begin(), via->end());
  return path;
}

}  // namespace csl
