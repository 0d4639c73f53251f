#include "core/planning/graph.hpp"

#include <algorithm>
#include <limits>
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
  ShortestPaths search;
  search.build(vertices, edges, usable);
  std::vector<int> path;
  search.search(source, target, heuristic, path, via);
  return path;
}

void ShortestPaths::begin_slots() {
  const std::size_t n = start_.size() - 1;
  for (std::size_t v = 0; v < n; ++v) start_[v + 1] += start_[v];
  fill_.assign(start_.begin(), start_.end() - 1);
  const auto slots = static_cast<std::size_t>(start_[n]);
  if (slots > slots_capacity_) {
    slots_.reset(new Slot[slots]);
    slots_capacity_ = slots;
  }
}

void ShortestPaths::remove(int edge) {
  const auto ui = static_cast<std::size_t>(edge);
  if (ui >= slot_a_.size() || slot_a_[ui] < 0) return;
  slots_[static_cast<std::size_t>(slot_a_[ui])].weight = std::numeric_limits<double>::infinity();
  slots_[static_cast<std::size_t>(slot_b_[ui])].weight = std::numeric_limits<double>::infinity();
  slot_a_[ui] = slot_b_[ui] = -1;
}

void ShortestPaths::clear() {
  built_ = false;
  start_.clear();
  fill_.clear();
  slots_.reset();
  slots_capacity_ = 0;
  slot_a_.clear();
  slot_b_.clear();
  dist_.clear();
  previous_.clear();
  previous_edge_.clear();
  closed_.clear();
  touched_.clear();
  open_.clear();
  place_.clear();
}

}  // namespace csl
