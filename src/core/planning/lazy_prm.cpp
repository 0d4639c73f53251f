#include "core/planning/lazy_prm.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace csl {

const char* phase_name(LazyPrmPhase p) {
  static const char* const kNames[] = {"endpoints", "sampling", "connecting", "search", "checking", "done"};
  return kNames[static_cast<int>(p)];
}

LazyPrm::LazyPrm(const CollisionWorld& world, Config start, Config goal, PrmParams params)
    : world_(&world),
      start_(world.space().wrap(start)),
      goal_(world.space().wrap(goal)),
      params_(std::move(params)),
      sampler_(world, params_.sampler),
      checker_(world, params_.checker, /*report_clearance=*/false),
      index_(world.space()) {
  if (start.size() != world.space().dim() || goal.size() != world.space().dim())
    throw std::invalid_argument("start and goal must have " + std::to_string(world.space().dim()) + " coordinates");
  if (params_.samples < 0 || params_.samples > kMaxPrmSamples)
    throw std::invalid_argument("the number of samples must be in [0, " + std::to_string(kMaxPrmSamples) + "]");
  if (params_.connector) throw std::invalid_argument("Lazy PRM joins vertices by straight lines: no local connector");
  reset();
}

void LazyPrm::reset() {
  reset_tested();
  rng_.reseed(params_.seed);
  phase_ = LazyPrmPhase::Endpoints;
  event_ = PlannerEvent{};
  steps_ = 0;
  roadmap_ = Roadmap{};
  roadmap_.vertices.reserve(static_cast<std::size_t>(params_.samples) + 2);
  roadmap_.clearance.reserve(static_cast<std::size_t>(params_.samples) + 2);
  checked_.clear();
  samples_drawn_ = 0;
  k_ = 0;
  knn_.clear();
  seen_.clear();
  p_ = -1;
  pairs_.clear();
  next_pair_ = 0;
  candidate_.clear();
  candidate_edges_.clear();
  paths_.clear();
  to_goal_.clear();
  next_check_ = 0;
  path_.clear();
  path_length_ = 0.0;
  edge_checks_ = evaluations_ = edges_alive_ = checked_alive_ = 0;
}

void LazyPrm::finish_phase() {
  const TestTally tally(*this);
  if (done()) return;
  const LazyPrmPhase phase = phase_;
  // As Prm::finish_phase(): the bulk of the building phases without events, the last unit by
  // step(). The search and checking phases alternate unit by unit and build no text either way.
  if (phase == LazyPrmPhase::Sampling) {
    while (samples_drawn_ + 1 < params_.samples) {
      ++steps_;
      draw_sample<false>();
    }
  } else if (phase == LazyPrmPhase::Connecting) {
    const int n = static_cast<int>(roadmap_.vertices.size());
    for (;;) {
      if (next_pair_ < pairs_.size()) {
        ++steps_;
        add_pair<false>();
      } else if (p_ + 2 < n) {
        ++steps_;
        ++p_;
        find_pairs<false>();
      } else {
        break;
      }
    }
  }
  while (!done() && phase_ == phase) step();
}

const PlannerEvent& LazyPrm::step() {
  const TestTally tally(*this);
  if (done()) throw std::logic_error("LazyPrm::step() after done()");
  PlannerEvent& e = event_;
  e = PlannerEvent{};
  e.step = ++steps_;
  switch (phase_) {
    case LazyPrmPhase::Endpoints: {
      const Config& q = roadmap_.vertices.empty() ? start_ : goal_;
      const auto nearest = world_->nearest(q);
      e.q = q;
      e.vertex = static_cast<int>(roadmap_.vertices.size());
      if (nearest.clearance <= 0.0) {
        e.kind = PlannerEvent::Kind::EndpointInCollision;
        e.obstacle = nearest.obstacle;
        phase_ = LazyPrmPhase::Done;
        break;
      }
      e.kind = PlannerEvent::Kind::AddEndpoint;
      roadmap_.vertices.push_back(q);
      roadmap_.clearance.push_back(nearest.clearance);
      if (roadmap_.vertices.size() == 2) {
        phase_ = params_.samples > 0 ? LazyPrmPhase::Sampling : LazyPrmPhase::Connecting;
        if (phase_ == LazyPrmPhase::Connecting) begin_connecting();
      }
      break;
    }
    case LazyPrmPhase::Sampling:
      draw_sample<true>();
      if (samples_drawn_ == params_.samples) {
        phase_ = LazyPrmPhase::Connecting;
        begin_connecting();
      }
      break;
    case LazyPrmPhase::Connecting:
      if (next_pair_ < pairs_.size()) {
        add_pair<true>();
      } else {
        ++p_;
        find_pairs<true>();
      }
      if (next_pair_ == pairs_.size() && p_ + 1 == static_cast<int>(roadmap_.vertices.size()))
        phase_ = LazyPrmPhase::Search;
      break;
    case LazyPrmPhase::Search:
      search();
      break;
    case LazyPrmPhase::Checking:
      check_next();
      break;
    case LazyPrmPhase::Done:
      break;
  }
  return e;
}

template <bool kEmit>
void LazyPrm::draw_sample() {
  SamplerDraw d = sampler_.draw(rng_, samples_drawn_ + 1);
  ++samples_drawn_;
  if (d.kept) {
    roadmap_.vertices.push_back(d.q);
    // Clearance is computed only when a check needs it: lazily, as the edges are.
    roadmap_.clearance.push_back(std::numeric_limits<double>::quiet_NaN());
  }
  if constexpr (kEmit) {
    PlannerEvent& e = event_;
    e.sample = samples_drawn_;
    e.evaluations = d.tested;
    if (d.kept) {
      e.kind = PlannerEvent::Kind::SampleAccepted;
      e.vertex = static_cast<int>(roadmap_.vertices.size()) - 1;
    } else {
      e.kind = PlannerEvent::Kind::SampleRejected;
      if (!d.q_free) e.obstacle = world_->obstacle_hit(d.q);
    }
    e.q = std::move(d.q);
  }
}

void LazyPrm::begin_connecting() {
  // The close pairs exactly as PRM finds them (Prm::begin_connecting()).
  const int n = static_cast<int>(roadmap_.vertices.size());
  const NeighborRule& rule = params_.neighbors;
  k_ = rule.kind == NeighborRule::Kind::Nearest  ? rule.k
       : rule.kind == NeighborRule::Kind::PrmStar ? NeighborRule::prm_star_k(n, world_->space().dim())
                                                  : 0;
  if (rule.kind == NeighborRule::Kind::Radius)
    index_.build(roadmap_.vertices);
  else
    all_k_nearest(world_->space(), roadmap_.vertices, k_, knn_);
  const std::size_t pairs = mark_pairs_seen(knn_, k_, seen_);
  roadmap_.edges.reserve(pairs);
  checked_.reserve(pairs);
  p_ = -1;
  pairs_.clear();
  next_pair_ = 0;
}

template <bool kEmit>
void LazyPrm::find_pairs() {
  const Config& q = roadmap_.vertices[static_cast<std::size_t>(p_)];
  pairs_.clear();
  next_pair_ = 0;
  int close = 0;
  if (params_.neighbors.kind == NeighborRule::Kind::Radius) {
    index_.within(q, params_.neighbors.radius, p_, scratch_);
    for (const Neighbor& nb : scratch_)
      if (nb.index > p_) pairs_.push_back(nb);
    close = static_cast<int>(scratch_.size());
  } else {
    const std::size_t row = static_cast<std::size_t>(p_) * static_cast<std::size_t>(k_);
    for (int i = 0; i < k_ && knn_[row + static_cast<std::size_t>(i)].index >= 0; ++i) {
      ++close;
      if (!seen_[row + static_cast<std::size_t>(i)]) pairs_.push_back({knn_[row + static_cast<std::size_t>(i)].index, 0.0});
    }
    for (Neighbor& nb : pairs_)
      nb.squared_distance = world_->space().squared_distance(q, roadmap_.vertices[static_cast<std::size_t>(nb.index)]);
  }
  if constexpr (kEmit) {
    event_.kind = PlannerEvent::Kind::Neighbors;
    event_.vertex = p_;
    event_.q = q;
    event_.candidates = static_cast<int>(pairs_.size());
    event_.seen = close - event_.candidates;
  }
}

template <bool kEmit>
void LazyPrm::add_pair() {
  const Neighbor nb = pairs_[next_pair_++];
  RoadmapEdge& slot = roadmap_.edges.emplace_back();
  slot.a = std::min(p_, nb.index);
  slot.b = std::max(p_, nb.index);
  slot.length = std::sqrt(nb.squared_distance);
  slot.alive = true;
  slot.path = -1;
  checked_.push_back(0);
  ++edges_alive_;
  if constexpr (kEmit) {
    event_.kind = PlannerEvent::Kind::EdgeAdded;  // unchecked: no evaluation
    event_.vertex = p_;
    event_.other = nb.index;
  }
}

void LazyPrm::search() {
  const auto& vertices = roadmap_.vertices;
  // The graph and A*'s heuristic (the distance to q_final) once, at the first search: between
  // searches only edges are removed (check_next() takes them out of paths_), and a search is most
  // of Lazy PRM's time (on the arm's T^2 with 5000 samples, 11 searches took 63 of 75 ms when each
  // rebuilt both; shortest_path() rebuilding its adjacency per search was still up to a quarter).
  if (!paths_.built() || paths_.edges() != roadmap_.edges.size() || paths_.vertices() != static_cast<int>(vertices.size())) {
    const RoadmapEdge* const edges = roadmap_.edges.data();
    paths_.build(static_cast<int>(vertices.size()), roadmap_.edges,
                 [edges](int i) { return edges[static_cast<std::size_t>(i)].alive; });
    to_goal_.resize(vertices.size());
    for (std::size_t v = 0; v < vertices.size(); ++v) to_goal_[v] = world_->space().distance(vertices[v], vertices[1]);
  }
  const double* const to_goal = to_goal_.data();
  paths_.search(
      0, 1, [to_goal](int v) { return to_goal[static_cast<std::size_t>(v)]; }, candidate_, &candidate_edges_);
  PlannerEvent& e = event_;
  if (candidate_.empty()) {
    e.kind = PlannerEvent::Kind::NoPath;
    phase_ = LazyPrmPhase::Done;
    return;
  }
  double length = 0.0;
  int unchecked = 0;
  for (int edge : candidate_edges_) {
    length += roadmap_.edges[static_cast<std::size_t>(edge)].length;
    unchecked += checked_[static_cast<std::size_t>(edge)] ? 0 : 1;
  }
  e.path_length = length;
  next_check_ = 0;
  if (unchecked == 0) {  // every edge proven free by earlier checks: the path
    path_ = candidate_;
    path_length_ = length;
    e.kind = PlannerEvent::Kind::PathFound;
    phase_ = LazyPrmPhase::Done;
    return;
  }
  e.kind = PlannerEvent::Kind::PathCandidate;
  e.candidates = unchecked;
  phase_ = LazyPrmPhase::Checking;
}

void LazyPrm::check_next() {
  PlannerEvent& e = event_;
  while (next_check_ < candidate_edges_.size() && checked_[static_cast<std::size_t>(candidate_edges_[next_check_])])
    ++next_check_;
  if (next_check_ == candidate_edges_.size()) {  // all checked free: proven
    path_ = candidate_;
    path_length_ = 0.0;
    for (int edge : candidate_edges_) path_length_ += roadmap_.edges[static_cast<std::size_t>(edge)].length;
    e.kind = PlannerEvent::Kind::PathFound;
    e.path_length = path_length_;
    phase_ = LazyPrmPhase::Done;
    return;
  }
  const int index = candidate_edges_[next_check_];
  RoadmapEdge& r = roadmap_.edges[static_cast<std::size_t>(index)];
  const auto ua = static_cast<std::size_t>(r.a), ub = static_cast<std::size_t>(r.b);
  // The ends' clearances, computed the first time an edge at that vertex is checked (each an
  // evaluation of the collision checker, counted as one).
  double& eta_a = roadmap_.clearance[ua];
  double& eta_b = roadmap_.clearance[ub];
  if (std::isnan(eta_a)) {
    eta_a = world_->clearance(roadmap_.vertices[ua]);
    ++evaluations_;
  }
  if (std::isnan(eta_b)) {
    eta_b = world_->clearance(roadmap_.vertices[ub]);
    ++evaluations_;
  }
  checker_.check_known_free(roadmap_.vertices[ua], roadmap_.vertices[ub], r.length, eta_a, eta_b);
  ++edge_checks_;
  evaluations_ += checker_.evaluations();
  checked_[static_cast<std::size_t>(index)] = 1;
  // Reported from the path's direction: vertex is the end nearer q_init on the candidate.
  e.vertex = candidate_[next_check_];
  e.other = candidate_[next_check_ + 1];
  e.evaluations = checker_.evaluations();
  if (checker_.verdict() == Verdict::Free) {
    ++checked_alive_;
    ++next_check_;
    e.kind = PlannerEvent::Kind::EdgeChecked;
    return;
  }
  r.alive = false;
  paths_.remove(index);
  --edges_alive_;
  e.kind = PlannerEvent::Kind::PathEdgeRemoved;
  e.collision_t = *checker_.collision_t();
  phase_ = LazyPrmPhase::Search;
}

int LazyPrm::components() const {
  UnionFind sets;
  sets.reset(static_cast<int>(roadmap_.vertices.size()));
  for (const RoadmapEdge& r : roadmap_.edges)
    if (r.alive) sets.unite(r.a, r.b);
  return sets.sets();
}

std::vector<Config> LazyPrm::path_configurations() const {
  std::vector<Config> out;
  for (int v : path_) out.push_back(roadmap_.vertices[static_cast<std::size_t>(v)]);
  return out;
}

double LazyPrm::progress() const {
  if (done()) return 1.0;
  const double vertices = std::max<double>(1.0, static_cast<double>(roadmap_.vertices.size()));
  switch (phase_) {
    case LazyPrmPhase::Endpoints: return 0.0;
    case LazyPrmPhase::Sampling: return 0.02 + 0.48 * samples_drawn_ / std::max(1, params_.samples);
    case LazyPrmPhase::Connecting: return 0.5 + 0.4 * std::max(0, p_) / vertices;
    default: return 0.9;  // the searches: how many is not known in advance
  }
}

std::string LazyPrm::describe(const PlannerEvent& e, const Scene& scene) const {
  char buf[256];
  const std::string q = format_config(e.q);
  switch (e.kind) {
    case PlannerEvent::Kind::AddEndpoint:
      std::snprintf(buf, sizeof buf, "%s added as vertex %d at %s", e.vertex == 0 ? "q_init" : "q_final", e.vertex, q.c_str());
      break;
    case PlannerEvent::Kind::EndpointInCollision:
      std::snprintf(buf, sizeof buf, "%s at %s is inside %s: no path", e.vertex == 0 ? "q_init" : "q_final", q.c_str(),
                    obstacle_label(scene, e.obstacle).c_str());
      break;
    case PlannerEvent::Kind::SampleAccepted:
      std::snprintf(buf, sizeof buf, "sample #%d (%s) at %s: kept as vertex %d", e.sample,
                    params_.sampler.name().c_str(), q.c_str(), e.vertex);
      break;
    case PlannerEvent::Kind::SampleRejected:
      if (e.obstacle >= 0)
        std::snprintf(buf, sizeof buf, "sample #%d (%s) at %s: rejected, inside %s", e.sample,
                      params_.sampler.name().c_str(), q.c_str(), obstacle_label(scene, e.obstacle).c_str());
      else
        std::snprintf(buf, sizeof buf, "sample #%d (%s) at %s: rejected, free but not what the sampler keeps", e.sample,
                      params_.sampler.name().c_str(), q.c_str());
      break;
    case PlannerEvent::Kind::Neighbors:
      std::snprintf(buf, sizeof buf, "connecting vertex %d: %d close pairs (%s) added unchecked", e.vertex, e.candidates,
                    params_.neighbors.name().c_str());
      break;
    case PlannerEvent::Kind::EdgeAdded:
      std::snprintf(buf, sizeof buf, "edge %d-%d added unchecked (checked only if a shortest path needs it)", e.vertex, e.other);
      break;
    case PlannerEvent::Kind::EdgeRejected:  // Lazy PRM rejects no edge unchecked
      std::snprintf(buf, sizeof buf, "edge %d-%d rejected", e.vertex, e.other);
      break;
    case PlannerEvent::Kind::PathCandidate:
      std::snprintf(buf, sizeof buf, "shortest path over the edges not disproved: length %.4f, %d edges still unchecked",
                    e.path_length, e.candidates);
      break;
    case PlannerEvent::Kind::EdgeChecked:
      std::snprintf(buf, sizeof buf, "path edge %d-%d checked (%s): free (%d evaluations)", e.vertex, e.other,
                    params_.checker.name().c_str(), e.evaluations);
      break;
    case PlannerEvent::Kind::PathEdgeRemoved:
      std::snprintf(buf, sizeof buf, "path edge %d-%d collides at t = %.3f: removed, searching again", e.vertex, e.other,
                    e.collision_t);
      break;
    case PlannerEvent::Kind::PathFound:
      // (Proven only by the exact check: a grid or step checker's "free" may miss a collision.)
      std::snprintf(buf, sizeof buf, "every edge of the path %s: %zu edges, length %.4f (%ld edges never checked)",
                    params_.checker.kind == EdgeCheckerSpec::Kind::Bisection ? "proven free" : "passed the checker",
                    path_.size() - 1, e.path_length, edges_unchecked());
      break;
    case PlannerEvent::Kind::NoPath:
      std::snprintf(buf, sizeof buf, "q_init and q_final are not connected by edges not disproved: no path (n = %d)",
                    params_.samples);
      break;
  }
  return buf;
}

PlannerFactory lazy_prm_factory(PrmParams params) {
  return [params](const CollisionWorld& world, const Config& start, const Config& goal) {
    return std::make_unique<LazyPrm>(world, start, goal, params);
  };
}

}  // namespace csl
