#pragma once
// Graph tools for roadmaps: union-find for connected components, and A* shortest paths.
#include <algorithm>
#include <functional>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace csl {

/// Disjoint sets with path halving and union by size (Tarjan 1975).
class UnionFind {
 public:
  explicit UnionFind(int n = 0) { reset(n); }
  void reset(int n);
  /// Adds one more singleton set; returns its element.
  int add();
  int find(int x);
  /// Merges the sets of a and b; returns false if they were already one.
  bool unite(int a, int b);
  int sets() const { return sets_; }
  int size() const { return static_cast<int>(parent_.size()); }

 private:
  std::vector<int> parent_, size_;
  int sets_ = 0;
};

struct GraphEdge {
  int a, b;
  double length;
};

/// A* from `source` to `target` over undirected edges (those with usable(i) true), with an
/// admissible heuristic h(v) (a lower bound on the distance from v to target; h = 0 gives
/// Dijkstra). Returns the vertices of a shortest path, source first, or nothing; `via`, if
/// given, receives the index of each edge taken. Ties are broken by vertex index, so the answer
/// is deterministic. One search on a graph built for it: ShortestPaths (below) for many.
std::vector<int> shortest_path(int vertices, const std::vector<GraphEdge>& edges,
                               const std::function<bool(int)>& usable, int source, int target,
                               const std::function<double(int)>& heuristic, std::vector<int>* via = nullptr);

/// The same A* for a planner that searches one graph again and again, removing edges between
/// searches (Lazy PRM): the adjacency (compressed rows, each vertex's edges in index order, as
/// shortest_path() builds it) is built once, a removed edge keeps its slots with an infinite
/// length (no relaxation through it can succeed, so every search returns what shortest_path()
/// would over the edges left), and the per-vertex arrays are kept, only the entries the last
/// search touched reset. The heuristic is a template: no std::function call per relaxation, and
/// the open vertices are an indexed 4-ary heap that lowers a vertex's f in place.
class ShortestPaths {
 public:
  /// The graph: `vertices` vertices, edges[i] for the i with usable(i) true. Edges: a vector of
  /// GraphEdge, or of anything with the same fields a, b and length (RoadmapEdge).
  template <class Edges, class Usable>
  void build(int vertices, const Edges& edges, Usable&& usable);
  /// Forgets the graph (build() must come before the next search).
  void clear();
  bool built() const { return built_; }
  int vertices() const { return static_cast<int>(dist_.size()); }
  /// Edges given to build() (usable or not).
  std::size_t edges() const { return slot_a_.size(); }
  /// Takes edge i out of every later search.
  void remove(int edge);
  /// As shortest_path(): `path` receives the vertices (empty: none), `via` the edges.
  template <class Heuristic>
  void search(int source, int target, Heuristic&& heuristic, std::vector<int>& path, std::vector<int>* via = nullptr);

 private:
  struct Slot {
    double weight;  // the edge's length; +infinity once removed
    int vertex;     // the other end
    int edge;
  };
  void begin_slots();
  void add_edge(int i, int a, int b, double length) {
    const auto ui = static_cast<std::size_t>(i);
    const int fa = fill_[static_cast<std::size_t>(a)]++;
    const int fb = fill_[static_cast<std::size_t>(b)]++;
    slots_[static_cast<std::size_t>(fa)] = {length, b, i};
    slots_[static_cast<std::size_t>(fb)] = {length, a, i};
    slot_a_[ui] = fa;
    slot_b_[ui] = fb;
  }

  bool built_ = false;
  std::vector<int> start_, fill_;
  std::unique_ptr<Slot[]> slots_;  // not a vector: filled by build(), never zeroed first
  std::size_t slots_capacity_ = 0;
  std::vector<int> slot_a_, slot_b_;  // per edge: its two slots, -1 if not usable
  std::vector<double> dist_;          // +infinity but where touched_ says
  std::vector<int> previous_, previous_edge_;
  std::vector<char> closed_;
  std::vector<int> touched_;  // vertices whose dist_ the last search set
  // The open vertices: a 4-ary heap of (f = g + h, vertex), smallest f first, then smallest
  // index, each vertex at most once (place_: its index in open_, -1 if not there), its f lowered
  // in place when a shorter way to it is found. It closes the vertices in the order of a queue
  // that keeps a copy per improvement and skips closed ones (std::priority_queue, as this search
  // had before): each time the open vertex with the smallest (f, vertex).
  using Item = std::pair<double, int>;
  std::vector<Item> open_;
  std::vector<int> place_;
  void sift_up(std::size_t i, Item x) {
    while (i > 0) {
      const std::size_t parent = (i - 1) / 4;
      if (!(x < open_[parent])) break;
      open_[i] = open_[parent];
      place_[static_cast<std::size_t>(open_[i].second)] = static_cast<int>(i);
      i = parent;
    }
    open_[i] = x;
    place_[static_cast<std::size_t>(x.second)] = static_cast<int>(i);
  }
  void push_or_lower(Item x) {  // x.first is at most the vertex's f in open_, if it is there
    int i = place_[static_cast<std::size_t>(x.second)];
    if (i < 0) {
      i = static_cast<int>(open_.size());
      open_.push_back(x);
    }
    sift_up(static_cast<std::size_t>(i), x);
  }
  int pop() {
    const int top = open_.front().second;
    place_[static_cast<std::size_t>(top)] = -1;
    const Item x = open_.back();
    open_.pop_back();
    const std::size_t n = open_.size();
    if (n == 0) return top;
    std::size_t i = 0;
    for (;;) {
      const std::size_t first = 4 * i + 1;
      if (first >= n) break;
      std::size_t best = first;
      const std::size_t last = std::min(first + 4, n);
      for (std::size_t c = first + 1; c < last; ++c)
        if (open_[c] < open_[best]) best = c;
      if (!(open_[best] < x)) break;
      open_[i] = open_[best];
      place_[static_cast<std::size_t>(open_[i].second)] = static_cast<int>(i);
      i = best;
    }
    open_[i] = x;
    place_[static_cast<std::size_t>(x.second)] = static_cast<int>(i);
    return top;
  }
};

template <class Edges, class Usable>
void ShortestPaths::build(int vertices, const Edges& edges, Usable&& usable) {
  const auto n = static_cast<std::size_t>(vertices);
  const std::size_t m = edges.size();
  start_.assign(n + 1, 0);
  slot_a_.assign(m, -1);
  slot_b_.assign(m, -1);
  for (std::size_t i = 0; i < m; ++i)
    if (usable(static_cast<int>(i))) {
      ++start_[static_cast<std::size_t>(edges[i].a) + 1];
      ++start_[static_cast<std::size_t>(edges[i].b) + 1];
    }
  begin_slots();
  for (std::size_t i = 0; i < m; ++i)
    if (usable(static_cast<int>(i))) add_edge(static_cast<int>(i), edges[i].a, edges[i].b, edges[i].length);
  dist_.assign(n, std::numeric_limits<double>::infinity());
  previous_.assign(n, -1);
  previous_edge_.assign(n, -1);
  closed_.assign(n, 0);
  place_.assign(n, -1);
  touched_.clear();
  open_.clear();
  built_ = true;
}

template <class Heuristic>
void ShortestPaths::search(int source, int target, Heuristic&& heuristic, std::vector<int>& path, std::vector<int>* via) {
  const double inf = std::numeric_limits<double>::infinity();
  for (int v : touched_) {
    dist_[static_cast<std::size_t>(v)] = inf;
    closed_[static_cast<std::size_t>(v)] = 0;
    place_[static_cast<std::size_t>(v)] = -1;
  }
  touched_.clear();
  open_.clear();
  double* const dist = dist_.data();
  char* const closed = closed_.data();
  const int* const start = start_.data();
  const Slot* const slots = slots_.get();
  dist[static_cast<std::size_t>(source)] = 0.0;
  previous_[static_cast<std::size_t>(source)] = -1;
  touched_.push_back(source);
  open_.push_back({heuristic(source), source});
  place_[static_cast<std::size_t>(source)] = 0;
  while (!open_.empty()) {
    const int v = pop();
    const auto uv = static_cast<std::size_t>(v);
    closed[uv] = 1;
    if (v == target) break;
    const double dv = dist[uv];
    for (int j = start[uv], end = start[uv + 1]; j < end; ++j) {
      const Slot& s = slots[j];
      const auto w = static_cast<std::size_t>(s.vertex);
      const double d = dv + s.weight;
      if (d < dist[w]) {
        if (dist[w] == inf) touched_.push_back(s.vertex);
        dist[w] = d;
        previous_[w] = v;
        previous_edge_[w] = s.edge;
        // A closed vertex is not queued again: shortest_path()'s queue would pop it and skip it.
        if (!closed[w]) push_or_lower({d + heuristic(s.vertex), s.vertex});
      }
    }
  }
  path.clear();
  if (via) via->clear();
  if (!closed[static_cast<std::size_t>(target)]) return;
  for (int v = target; v != -1; v = previous_[static_cast<std::size_t>(v)]) {
    path.push_back(v);
    if (via && v != source) via->push_back(previous_edge_[static_cast<std::size_t>(v)]);
  }
  std::reverse(path.begin(), path.end());
  if (via) std::reverse(via->begin(), via->end());
}

}  // namespace csl
