#include "core/planning/prm.hpp"

#include "core/base/params.hpp"
#include "core/base/text.hpp"
#include "core/planning/prm_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace csl {

int NeighborRule::prm_star_k(int n, int d) {
  if (n < 2) return 1;
  const double e = 2.718281828459045;
  return static_cast<int>(std::ceil(e * (1.0 + 1.0 / d) * std::log(static_cast<double>(n))));
}

NeighborRule NeighborRule::parse(const std::string& text) {
  // Numbers in the one syntax of core/base/text.hpp (no spaces, no hexadecimal, no '+').
  NeighborRule r;
  const auto number_after = [&](std::size_t prefix) {
    const auto v = parse_decimal(std::string_view(text).substr(prefix));
    if (!v) throw std::invalid_argument("neighbour rule '" + printable(text, 40) + "': not a number after ':'");
    return *v;
  };
  if (text == "prm*") {
    r.kind = Kind::PrmStar;
  } else if (text.rfind("k:", 0) == 0) {
    const auto k = parse_integer(std::string_view(text).substr(2));
    if (!k || !in_range(kNeighborK, static_cast<double>(*k))) throw std::invalid_argument("k must be " + range_text(kNeighborK));
    r.kind = Kind::Nearest;
    r.k = static_cast<int>(*k);
  } else if (text.rfind("radius:", 0) == 0) {
    r.kind = Kind::Radius;
    r.radius = number_after(7);
    if (!(r.radius > 0)) throw std::invalid_argument("the radius must be > 0");
  } else {
    throw std::invalid_argument("unknown neighbour rule '" + printable(text, 40) + "' (k:K, radius:R or prm*)");
  }
  return r;
}

std::string NeighborRule::name() const {
  if (kind == Kind::PrmStar) return "prm*";
  if (kind == Kind::Nearest) return "k:" + std::to_string(k);
  char text[48];
  std::snprintf(text, sizeof text, "radius:%.17g", radius);
  return text;
}

namespace {
double vertex_pairs(int samples) {
  const double n = static_cast<double>(samples) + 2.0;  // with q_init and q_final
  return n * (n - 1.0) / 2.0;
}
}  // namespace

double expected_candidate_pairs(const Space& space, const NeighborRule& rule, int samples) {
  const double n = static_cast<double>(samples) + 2.0;
  const int d = space.dim();
  switch (rule.kind) {
    case NeighborRule::Kind::Nearest:
      return std::min(n * rule.k, vertex_pairs(samples));
    case NeighborRule::Kind::PrmStar:
      return std::min(n * NeighborRule::prm_star_k(samples + 2, d), vertex_pairs(samples));
    case NeighborRule::Kind::Radius:
      break;
  }
  // The ball in the space's (weighted) metric against the space's (weighted) volume.
  const double ball = unit_ball_volume(d) * std::pow(rule.radius, d);
  return vertex_pairs(samples) * std::min(1.0, ball / space.volume());
}

double radius_for_pairs(const Space& space, int samples, double pairs) {
  // With every pair within `pairs`, no radius reaches it.
  if (pairs >= vertex_pairs(samples)) return std::numeric_limits<double>::infinity();
  const int d = space.dim();
  return std::pow(pairs / vertex_pairs(samples) * space.volume() / unit_ball_volume(d), 1.0 / d);
}

bool within_pairs_budget(const Space& space, const NeighborRule& rule, int samples, double max_pairs) {
  if (expected_candidate_pairs(space, rule, samples) <= max_pairs) return true;
  return rule.kind == NeighborRule::Kind::Radius && rule.radius <= radius_for_pairs(space, samples, max_pairs);
}

std::string radius_for_pairs_text(const Space& space, int samples, double pairs) {
  const double fits = radius_for_pairs(space, samples, pairs);
  if (!(fits > 0.0) || !std::isfinite(fits)) return fits > 0.0 ? "any" : "0";
  const double digit = std::pow(10.0, std::floor(std::log10(fits)) - 3.0);  // the 4th significant one
  const double shown = std::floor(fits / digit) * digit;
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", shown);
  // Rounding in the product or the printing may land a hair above: one digit less then.
  if (std::strtod(text, nullptr) > fits) std::snprintf(text, sizeof text, "%.4g", shown - digit);
  return text;
}

const char* phase_name(PrmPhase p) {
  static const char* const kNames[] = {"endpoints", "sampling", "connecting", "query", "done"};
  return kNames[static_cast<int>(p)];
}

std::uint64_t pair_seed(std::uint64_t seed, int a, int b) {
  // splitmix64's finaliser over the seed and the pair packed into one word.
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * (1u + ((static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
                                                          static_cast<std::uint32_t>(b)));
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

Prm::Prm(const CollisionWorld& world, Config start, Config goal, PrmParams params)
    : world_(&world),
      start_(world.space().wrap(start)),
      goal_(world.space().wrap(goal)),
      params_(params),
      sampler_(world, params.sampler),
      checker_(world, params.checker, /*report_clearance=*/false),
      exact_(world, EdgeCheckerSpec::parse("bisection")),
      index_(world.space()) {
  if (start.size() != world.space().dim() || goal.size() != world.space().dim())
    throw std::invalid_argument("start and goal must have " + std::to_string(world.space().dim()) + " coordinates");
  if (params.samples < 0 || params.samples > kMaxPrmSamples)
    throw std::invalid_argument("the number of samples must be in [0, " + std::to_string(kMaxPrmSamples) + "]");
  reset();
}

void Prm::reset() {
  reset_tested();
  rng_.reseed(params_.seed);
  phase_ = PrmPhase::Endpoints;
  event_ = PrmEvent{};
  steps_ = 0;
  roadmap_ = Roadmap{};
  // Room for the endpoints and every sample (no regrowth while sampling).
  roadmap_.vertices.reserve(static_cast<std::size_t>(params_.samples) + 2);
  roadmap_.clearance.reserve(static_cast<std::size_t>(params_.samples) + 2);
  components_.reset(0);
  samples_drawn_ = 0;
  k_ = 0;
  knn_.clear();
  seen_.clear();
  p_ = -1;
  candidates_.clear();
  next_candidate_ = 0;
  path_.clear();
  path_edges_.clear();
  path_length_ = 0.0;
  edge_checks_ = evaluations_ = edges_alive_ = 0;
}

void Prm::finish_phase() {
  const TestTally tally(*this);
  if (done()) return;
  const PrmPhase phase = phase_;
  // The bulk of the phase without events (the same units, in the same order, counted as
  // steps); its last unit by step(), so that last_event() is the one stepping would leave.
  if (phase == PrmPhase::Sampling) {
    while (samples_drawn_ + 1 < params_.samples) {
      ++steps_;
      draw_sample<false>();
    }
  } else if (phase == PrmPhase::Connecting) {
    const int n = static_cast<int>(roadmap_.vertices.size());
    for (;;) {
      if (next_candidate_ < candidates_.size()) {
        ++steps_;
        check_candidate<false>();
      } else if (p_ + 2 < n) {  // not yet the last vertex (which step() finishes)
        ++steps_;
        ++p_;
        find_candidates<false>();
      } else {
        break;
      }
    }
  }
  while (!done() && phase_ == phase) step();
}

const PrmEvent& Prm::step() {
  const TestTally tally(*this);
  if (done()) throw std::logic_error("Prm::step() after done()");
  PrmEvent& e = event_;
  e = PrmEvent{};
  e.step = ++steps_;
  switch (phase_) {
    case PrmPhase::Endpoints: {
      const Config& q = roadmap_.vertices.empty() ? start_ : goal_;
      const auto nearest = world_->nearest(q);
      e.q = q;
      e.vertex = static_cast<int>(roadmap_.vertices.size());
      if (nearest.clearance <= 0.0) {
        e.kind = PrmEvent::Kind::EndpointInCollision;
        e.obstacle = nearest.obstacle;
        phase_ = PrmPhase::Done;
        break;
      }
      e.kind = PrmEvent::Kind::AddEndpoint;
      roadmap_.vertices.push_back(q);
      roadmap_.clearance.push_back(nearest.clearance);
      components_.add();
      if (roadmap_.vertices.size() == 2) phase_ = params_.samples > 0 ? PrmPhase::Sampling : PrmPhase::Connecting;
      if (phase_ == PrmPhase::Connecting) begin_connecting();
      break;
    }
    case PrmPhase::Sampling: {
      draw_sample<true>();
      if (samples_drawn_ == params_.samples) {
        phase_ = PrmPhase::Connecting;
        begin_connecting();
      }
      break;
    }
    case PrmPhase::Connecting:
      if (next_candidate_ < candidates_.size()) {
        check_candidate<true>();
      } else {
        ++p_;
        find_candidates<true>();
      }
      // The last vertex's last candidate done: the search is the next step.
      if (next_candidate_ == candidates_.size() && p_ + 1 == static_cast<int>(roadmap_.vertices.size()))
        phase_ = PrmPhase::Query;
      break;
    case PrmPhase::Query:
      query();
      break;
    case PrmPhase::Done:
      break;
  }
  return e;
}

template <bool kEmit>
void Prm::draw_sample() {
  if (params_.sampler.kind != SamplerSpec::Kind::Uniform) {
    draw_from_sampler<kEmit>();
    return;
  }
  const Config q = world_->space().sample(rng_);
  ++samples_drawn_;
  const bool free = world_->is_free(q);
  if (free) {
    roadmap_.vertices.push_back(q);
    // Bisection needs every vertex's clearance; the grid checkers only some (check_candidate).
    roadmap_.clearance.push_back(params_.checker.kind == EdgeCheckerSpec::Kind::Bisection
                                     ? world_->clearance(q)
                                     : std::numeric_limits<double>::quiet_NaN());
    components_.add();
  }
  if constexpr (kEmit) {
    PrmEvent& e = event_;
    e.q = q;
    e.sample = samples_drawn_;
    if (free) {
      e.kind = PrmEvent::Kind::SampleAccepted;
      e.vertex = static_cast<int>(roadmap_.vertices.size()) - 1;
    } else {
      e.kind = PrmEvent::Kind::SampleRejected;
      e.obstacle = world_->obstacle_hit(q);
    }
  }
}

template <bool kEmit>
void Prm::draw_from_sampler() {
  // The uniform sampler stays in draw_sample() above, as it always was (its roadmaps' hashes
  // are pinned); the others keep at most one configuration per draw.
  SamplerDraw d = sampler_.draw(rng_, samples_drawn_ + 1);
  ++samples_drawn_;
  if (d.kept) {
    roadmap_.vertices.push_back(d.q);
    roadmap_.clearance.push_back(params_.checker.kind == EdgeCheckerSpec::Kind::Bisection
                                     ? world_->clearance(d.q)
                                     : std::numeric_limits<double>::quiet_NaN());
    components_.add();
  }
  if constexpr (kEmit) {
    PrmEvent& e = event_;
    e.sample = samples_drawn_;
    e.evaluations = d.tested;
    if (d.kept) {
      e.kind = PrmEvent::Kind::SampleAccepted;
      e.vertex = static_cast<int>(roadmap_.vertices.size()) - 1;
    } else {
      e.kind = PrmEvent::Kind::SampleRejected;
      // A free q rejected (no obstacle near it): obstacle stays -1.
      if (!d.q_free) e.obstacle = world_->obstacle_hit(d.q);
    }
    e.q = std::move(d.q);
  }
}

void Prm::begin_connecting() {
  const int n = static_cast<int>(roadmap_.vertices.size());
  const NeighborRule& rule = params_.neighbors;
  k_ = rule.kind == NeighborRule::Kind::Nearest  ? rule.k
       : rule.kind == NeighborRule::Kind::PrmStar ? NeighborRule::prm_star_k(n, world_->space().dim())
                                                  : 0;
  if (rule.kind == NeighborRule::Kind::Radius) {
    index_.build(roadmap_.vertices);
  } else {
    // The k nearest of all vertices at once (the same answers as asking one by one).
    all_k_nearest(world_->space(), roadmap_.vertices, k_, knn_);
  }
  // Being among the k nearest is not symmetric: the pair (p, q), q < p, is skipped when p is
  // connected if q had p among its own k nearest, i.e. if the pair was checked from q's side.
  // Flagged here once for all vertices; the rest are the candidates, at most one edge each.
  const std::size_t pairs = mark_pairs_seen(knn_, k_, seen_);
  roadmap_.edges.reserve(roadmap_.edges.size() + pairs);
  p_ = -1;
  candidates_.clear();
  next_candidate_ = 0;
}

template <bool kEmit>
void Prm::find_candidates() {
  const Config& q = roadmap_.vertices[static_cast<std::size_t>(p_)];
  candidates_.clear();
  next_candidate_ = 0;
  if (params_.neighbors.kind == NeighborRule::Kind::Radius) {
    index_.within(q, params_.neighbors.radius, p_, scratch_);
    // Being close is symmetric: the pair was a candidate of the smaller vertex already.
    for (const Neighbor& nb : scratch_)
      if (nb.index > p_) candidates_.push_back(nb);
  } else {
    // The k nearest but those already checked from the other side (see begin_connecting()).
    const std::size_t row = static_cast<std::size_t>(p_) * static_cast<std::size_t>(k_);
    const NearNeighbor* mine = &knn_[row];
    const unsigned char* seen = &seen_[row];
    // Written whether seen or not, kept only if not: about a third are seen, in no order a
    // branch could predict.
    scratch_.resize(static_cast<std::size_t>(k_));  // its size stays k_: no work after the first
    Neighbor* out = scratch_.data();
    std::size_t kept = 0;
    for (int i = 0; i < k_ && mine[i].index >= 0; ++i) {
      out[kept] = {mine[i].index, 0.0};
      kept += seen[i] ? 0 : 1;
    }
    candidates_.assign(out, out + kept);
  }
  // The exact distance (the rows keep a float): the same formula as the index's, so the same bits.
  if (params_.neighbors.kind != NeighborRule::Kind::Radius)
    for (Neighbor& nb : candidates_)
      nb.squared_distance = world_->space().squared_distance(q, roadmap_.vertices[static_cast<std::size_t>(nb.index)]);
  if constexpr (kEmit) {
    event_.kind = PrmEvent::Kind::Neighbors;
    event_.vertex = p_;
    event_.q = q;
    event_.candidates = static_cast<int>(candidates_.size());
    if (params_.neighbors.kind == NeighborRule::Kind::Radius) {
      event_.seen = static_cast<int>(scratch_.size() - candidates_.size());
    } else {
      const std::size_t row = static_cast<std::size_t>(p_) * static_cast<std::size_t>(k_);
      int close = 0;
      for (int i = 0; i < k_ && knn_[row + static_cast<std::size_t>(i)].index >= 0; ++i) ++close;
      event_.seen = close - event_.candidates;
    }
  }
}

template <bool kEmit>
void Prm::check_candidate() {
  const Neighbor candidate = candidates_[next_candidate_++];
  const int q = candidate.index;
  const auto up = static_cast<std::size_t>(p_), uq = static_cast<std::size_t>(q);
  if (params_.connector) {
    connect_candidate<kEmit>(q);
    return;
  }
  // Measured as the checker would measure it (the same formula, so the same bits): the length.
  const double length = std::sqrt(candidate.squared_distance);
  if (params_.checker.kind == EdgeCheckerSpec::Kind::Bisection) {
    checker_.check_known_free(roadmap_.vertices[up], roadmap_.vertices[uq], length, roadmap_.clearance[up],
                              roadmap_.clearance[uq]);
  } else {
    double eta_p = std::numeric_limits<double>::quiet_NaN(), eta_q = eta_p;
    if (checker_.has_interior(length)) {
      // The grid checkers skip what the endpoints' clearances prove free: each vertex's is
      // computed when an edge with configurations between its ends first needs it. (Edges
      // without such configurations, most in large roadmaps, read neither: a cache miss each.)
      eta_p = roadmap_.clearance[up];
      eta_q = roadmap_.clearance[uq];
      if (std::isnan(eta_p)) eta_p = roadmap_.clearance[up] = world_->clearance(roadmap_.vertices[up]);
      if (std::isnan(eta_q)) eta_q = roadmap_.clearance[uq] = world_->clearance(roadmap_.vertices[uq]);
    }
    checker_.check_grid_known_free(roadmap_.vertices[up], roadmap_.vertices[uq], length, eta_p, eta_q);
  }
  ++edge_checks_;
  evaluations_ += checker_.evaluations();
  const bool free = checker_.verdict() == Verdict::Free;
  if (free) add_edge(q, length);
  if constexpr (kEmit) {
    PrmEvent& e = event_;
    e.vertex = p_;
    e.other = q;
    e.evaluations = checker_.evaluations();
    e.skipped = checker_.skipped();
    e.kind = free ? PrmEvent::Kind::EdgeAdded : PrmEvent::Kind::EdgeRejected;
    if (!free) e.collision_t = *checker_.collision_t();
  }
}

void Prm::add_edge(int q, double length, int path) {
  // Written into its slot field by field: a copy of a whole struct read it back from the
  // stack as wider loads than the stores that built it, a stalled store-to-load forward on
  // every edge (perf: half of check_candidate's time); and the wasm passed the struct through
  // memory.
  RoadmapEdge& slot = roadmap_.edges.emplace_back();
  slot.a = std::min(p_, q);
  slot.b = std::max(p_, q);
  slot.length = length;
  slot.alive = true;
  slot.path = path;
  ++edges_alive_;
  components_.unite(p_, q);
}

template <bool kEmit>
void Prm::connect_candidate(int q) {
  const auto up = static_cast<std::size_t>(p_), uq = static_cast<std::size_t>(q);
  const int a = std::min(p_, q), b = std::max(p_, q);
  // From the vertex being connected toward its candidate, as the straight line is checked.
  LocalPath path = params_.connector->connect(*world_, roadmap_.vertices[up], roadmap_.vertices[uq],
                                              pair_seed(params_.seed, a, b));
  ++edge_checks_;
  evaluations_ += path.evaluations;
  if (path.connected) {
    int stored = -1;
    if (!path.waypoints.empty()) {
      if (p_ > q) std::reverse(path.waypoints.begin(), path.waypoints.end());  // stored from a to b
      stored = static_cast<int>(roadmap_.paths.size());
      roadmap_.paths.push_back(std::move(path.waypoints));
    }
    add_edge(q, path.length, stored);
  }
  if constexpr (kEmit) {
    PrmEvent& e = event_;
    e.vertex = p_;
    e.other = q;
    e.evaluations = static_cast<int>(std::min<long>(path.evaluations, std::numeric_limits<int>::max()));
    e.kind = path.connected ? PrmEvent::Kind::EdgeAdded : PrmEvent::Kind::EdgeRejected;
  }
}

bool Prm::verify_edge(const RoadmapEdge& r, double& collision_t) {
  const Config* from = &roadmap_.vertices[static_cast<std::size_t>(r.a)];
  const std::vector<Config>& waypoints = roadmap_.waypoints(r);
  for (std::size_t i = 0; i <= waypoints.size(); ++i) {
    const Config& to = i < waypoints.size() ? waypoints[i] : roadmap_.vertices[static_cast<std::size_t>(r.b)];
    exact_.reset(*from, to);
    while (!exact_.done()) exact_.step();
    if (exact_.verdict() != Verdict::Free) {
      collision_t = *exact_.collision_t();
      return false;
    }
    from = &to;
  }
  return true;
}

std::vector<Config> Prm::path_configurations() const {
  std::vector<Config> out;
  if (path_.empty()) return out;
  out.push_back(roadmap_.vertices[static_cast<std::size_t>(path_.front())]);
  for (std::size_t k = 0; k < path_edges_.size(); ++k) {
    const RoadmapEdge& r = roadmap_.edges[static_cast<std::size_t>(path_edges_[k])];
    const bool forward = r.a == path_[k];  // the waypoints run from a to b
    const std::vector<Config>& waypoints = roadmap_.waypoints(r);
    if (forward)
      out.insert(out.end(), waypoints.begin(), waypoints.end());
    else
      out.insert(out.end(), waypoints.rbegin(), waypoints.rend());
    out.push_back(roadmap_.vertices[static_cast<std::size_t>(path_[k + 1])]);
  }
  return out;
}

void Prm::query() {
  std::vector<GraphEdge> graph;
  graph.reserve(roadmap_.edges.size());
  for (const RoadmapEdge& r : roadmap_.edges) graph.push_back({r.a, r.b, r.length});
  const auto& vertices = roadmap_.vertices;
  const Config& goal = vertices[1];
  std::vector<int> via;
  const std::vector<int> path = shortest_path(
      static_cast<int>(vertices.size()), graph,
      [&](int i) { return roadmap_.edges[static_cast<std::size_t>(i)].alive; }, 0, 1,
      [&](int v) { return world_->space().distance(vertices[static_cast<std::size_t>(v)], goal); }, &via);
  PrmEvent& e = event_;
  if (path.empty()) {
    e.kind = PrmEvent::Kind::NoPath;
    phase_ = PrmPhase::Done;
    return;
  }
  // Re-verify every edge of the path with the exact check (a grid checker may have let an edge
  // through a thin obstacle; a connector's path is checked piece by piece). A failed edge is
  // removed and the search runs again next step.
  for (int edge : via) {
    RoadmapEdge& r = roadmap_.edges[static_cast<std::size_t>(edge)];
    double collision_t = 0.0;
    if (verify_edge(r, collision_t)) continue;
    r.alive = false;
    --edges_alive_;
    components_.reset(static_cast<int>(vertices.size()));
    for (const RoadmapEdge& k : roadmap_.edges)
      if (k.alive) components_.unite(k.a, k.b);
    e.kind = PrmEvent::Kind::PathEdgeRemoved;
    e.vertex = r.a;
    e.other = r.b;
    e.collision_t = collision_t;
    return;
  }
  path_ = path;
  path_edges_ = via;
  path_length_ = 0.0;
  for (int edge : via) path_length_ += roadmap_.edges[static_cast<std::size_t>(edge)].length;
  e.kind = PrmEvent::Kind::PathFound;
  e.path_length = path_length_;
  phase_ = PrmPhase::Done;
}

std::vector<int> Prm::component_labels() const {
  std::vector<int> label(roadmap_.vertices.size(), -1), by_root(roadmap_.vertices.size(), -1);
  int next = 0;
  for (std::size_t v = 0; v < label.size(); ++v) {
    const auto root = static_cast<std::size_t>(components_.find(static_cast<int>(v)));
    if (by_root[root] < 0) by_root[root] = next++;
    label[v] = by_root[root];
  }
  return label;
}

std::string Prm::describe(const PlannerEvent& e, const Scene& scene) const { return describe_prm_event(e, *this, scene); }

double Prm::progress() const {
  if (done()) return 1.0;
  // By phase; the connecting phase, by the vertex it connects, takes most of the time.
  const double vertices = std::max<double>(1.0, static_cast<double>(roadmap_.vertices.size()));
  switch (phase_) {
    case PrmPhase::Endpoints:
      return 0.0;
    case PrmPhase::Sampling:
      return 0.02 + 0.18 * samples_drawn_ / std::max(1, params_.samples);
    case PrmPhase::Connecting:
      return 0.2 + 0.77 * std::max(0, p_) / vertices;
    default:
      return 0.97;
  }
}

PlannerFactory prm_factory(PrmParams params) {
  return [params](const CollisionWorld& world, const Config& start, const Config& goal) {
    return std::make_unique<Prm>(world, start, goal, params);
  };
}

}  // namespace csl
