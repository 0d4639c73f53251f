#include "core/planning/tree_planner.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/planning/graph.hpp"

namespace csl {

namespace {
// The vertices reset() makes room for (the arrays grow past it as they must).
constexpr int kReservedVertices = 64;
}  // namespace

double space_extent(const Space& space) {
  double sum = 0.0;
  for (int i = 0; i < space.dim(); ++i) {
    const Coordinate& c = space.coordinate(i);
    const double span = (c.angular ? kPi : c.hi - c.lo) * c.weight;
    sum += span * span;
  }
  return std::sqrt(sum);
}

double tree_step(const Space& space, double requested) {
  const double extent = space_extent(space);
  return requested > 0.0 ? std::max(requested, kMinTreeStepFraction * extent) : 0.2 * extent;
}

const char* phase_name(TreePhase p) {
  static const char* const kNames[] = {"endpoints", "growing", "query", "done"};
  return kNames[static_cast<int>(p)];
}

TreePlanner::TreePlanner(const CollisionWorld& world, Config start, Config goal, TreeParams params)
    : world_(&world),
      start_(world.space().wrap(start)),
      goal_(world.space().wrap(goal)),
      params_(params),
      step_(tree_step(world.space(), params.step)),
      checker_(world, params.checker, /*report_clearance=*/false),
      exact_(world, EdgeCheckerSpec::parse("bisection")),
      index_{NeighborIndex(world.space()), NeighborIndex(world.space())} {
  if (start.size() != world.space().dim() || goal.size() != world.space().dim())
    throw std::invalid_argument("start and goal must have " + std::to_string(world.space().dim()) + " coordinates");
  if (params.samples < 0 || params.samples > static_cast<int>(kPrmSamples.max))
    throw std::invalid_argument(param_error(kPrmSamples));
  if (!in_range(kGoalBias, params.goal_bias)) throw std::invalid_argument(param_error(kGoalBias));
  if (!in_range(kTreeStep, params.step) || !(step_ > 0.0) || !std::isfinite(step_))
    throw std::invalid_argument(param_error(kTreeStep));
}

void TreePlanner::reset() {
  reset_tested();
  rng_.reseed(params_.seed);
  phase_ = TreePhase::Endpoints;
  event_ = PlannerEvent{};
  steps_ = 0;
  roadmap_ = Roadmap{};
  tree_.clear();
  parent_.clear();
  parent_edge_.clear();
  for (int t = 0; t < 2; ++t) {
    index_[static_cast<std::size_t>(t)].build({});
    members_[static_cast<std::size_t>(t)].clear();
  }
  // Room for the first vertices at once: a query that ends within a few dozen (most
  // RRT-Connect queries) then allocates each array once instead of doubling it five or six
  // times (allocation was about a tenth of such a query's instructions, measured with callgrind
  // on the bench's plane). Capacity only: no result changes.
  const std::size_t room = static_cast<std::size_t>(std::min(params_.samples, kReservedVertices - 2) + 2);
  roadmap_.vertices.reserve(room);
  roadmap_.clearance.reserve(room);
  roadmap_.edges.reserve(room);
  tree_.reserve(room);
  parent_.reserve(room);
  parent_edge_.reserve(room);
  for (int t = 0; t < 2; ++t) {
    index_[static_cast<std::size_t>(t)].reserve(static_cast<int>(room));
    members_[static_cast<std::size_t>(t)].reserve(room);
  }
  samples_drawn_ = 0;
  join_edge_ = -1;
  path_.clear();
  path_edges_.clear();
  path_length_ = 0.0;
  edge_checks_ = evaluations_ = edges_alive_ = 0;
  reset_growth();
}

const PlannerEvent& TreePlanner::step() {
  const TestTally tally(*this);
  if (done()) throw std::logic_error("TreePlanner::step() after done()");
  event_ = PlannerEvent{};
  event_.step = ++steps_;
  switch (phase_) {
    case TreePhase::Endpoints:
      add_endpoint();
      break;
    case TreePhase::Growing:
      grow_emit();
      if (phase_ == TreePhase::Growing && samples_drawn_ >= params_.samples && !pending()) phase_ = TreePhase::Query;
      break;
    case TreePhase::Query:
      query();
      break;
    case TreePhase::Done:
      break;
  }
  return event_;
}

void TreePlanner::finish_phase() {
  const TestTally tally(*this);
  if (done()) return;
  const TreePhase phase = phase_;
  // The bulk of growing without events: no unit before the last sample can spend the budget,
  // and a join, which ends the phase early, writes its event anyway (extend()), so that
  // last_event() is the one stepping would leave. The rest by step().
  if (phase == TreePhase::Growing) {
    while (phase_ == TreePhase::Growing && samples_drawn_ + 1 < params_.samples) {
      ++steps_;
      grow_quiet();
    }
  }
  while (!done() && phase_ == phase) step();
}

void TreePlanner::add_endpoint() {
  const int v = static_cast<int>(roadmap_.vertices.size());
  const Config& q = v == 0 ? start_ : goal_;
  const auto nearest = world_->nearest(q);
  event_.q = q;
  event_.vertex = v;
  if (nearest.clearance <= 0.0) {
    event_.kind = PlannerEvent::Kind::EndpointInCollision;
    event_.obstacle = nearest.obstacle;
    phase_ = TreePhase::Done;
    return;
  }
  event_.kind = PlannerEvent::Kind::AddEndpoint;
  roadmap_.vertices.push_back(q);
  roadmap_.clearance.push_back(nearest.clearance);
  tree_.push_back(v);
  parent_.push_back(-1);
  parent_edge_.push_back(-1);
  index_[static_cast<std::size_t>(v)].insert(q);
  members_[static_cast<std::size_t>(v)].push_back(v);
  if (v == 1) phase_ = params_.samples > 0 ? TreePhase::Growing : TreePhase::Query;
}

int TreePlanner::nearest_in(int tree, const Config& q) {
  const auto t = static_cast<std::size_t>(tree);
  index_[t].k_nearest(q, 1, -1, scratch_);
  return members_[t][static_cast<std::size_t>(scratch_.front().index)];
}

int TreePlanner::add_edge(int a, int b, double length) {
  RoadmapEdge& slot = roadmap_.edges.emplace_back();
  slot.a = std::min(a, b);
  slot.b = std::max(a, b);
  slot.length = length;
  slot.alive = true;
  slot.path = -1;
  ++edges_alive_;
  return static_cast<int>(roadmap_.edges.size()) - 1;
}

int TreePlanner::add_vertex(const Config& q, double eta, int tree, int parent, double length) {
  const int v = static_cast<int>(roadmap_.vertices.size());
  roadmap_.vertices.push_back(q);
  roadmap_.clearance.push_back(eta);
  tree_.push_back(tree);
  parent_.push_back(parent);
  parent_edge_.push_back(add_edge(parent, v, length));
  index_[static_cast<std::size_t>(tree)].insert(q);
  members_[static_cast<std::size_t>(tree)].push_back(v);
  return v;
}

bool TreePlanner::check(int near, const Config& q, double length, double& eta_q, double& collision_t) {
  const auto un = static_cast<std::size_t>(near);
  const Config& p = roadmap_.vertices[un];
  if (params_.checker.kind == EdgeCheckerSpec::Kind::Bisection) {
    checker_.check_known_free(p, q, length, roadmap_.clearance[un], eta_q);
  } else {
    double eta_p = std::numeric_limits<double>::quiet_NaN();
    if (checker_.has_interior(length)) {
      // As PRM: a clearance is computed when an edge with configurations between its ends needs it.
      // Each one a configuration evaluated (counted: the bench compares evaluations with OMPL's).
      if (std::isnan(roadmap_.clearance[un])) {
        roadmap_.clearance[un] = world_->clearance(p);
        ++evaluations_;
      }
      if (std::isnan(eta_q)) {
        eta_q = world_->clearance(q);
        ++evaluations_;
      }
      eta_p = roadmap_.clearance[un];
    }
    checker_.check_grid_known_free(p, q, length, eta_p, eta_q);
  }
  ++edge_checks_;
  evaluations_ += checker_.evaluations();
  if (checker_.verdict() == Verdict::Free) return true;
  collision_t = *checker_.collision_t();
  return false;
}

template <bool kEmit>
TreePlanner::Extension TreePlanner::extend(int tree, int near, const Config& target, int target_vertex, int sample) {
  const Space& space = world_->space();
  const Config from = roadmap_.vertices[static_cast<std::size_t>(near)];  // a copy: V grows below
  const double d = space.distance(from, target);
  const bool reaches = d <= step_;
  double collision_t = std::numeric_limits<double>::quiet_NaN();
  if (reaches && target_vertex >= 0) {
    // The other tree's vertex within reach: the edge to it alone, the join if free.
    const auto ut = static_cast<std::size_t>(target_vertex);
    double eta = roadmap_.clearance[ut];
    const bool free = check(near, target, d, eta, collision_t);
    roadmap_.clearance[ut] = eta;
    if (free) {
      join_edge_ = add_edge(near, target_vertex, d);
      phase_ = TreePhase::Query;
      // Always written: the join ends the phase, and finish_phase() leaves its event.
      event_ = PlannerEvent{};
      event_.step = steps_;
      event_.kind = PlannerEvent::Kind::EdgeAdded;
      event_.vertex = near;
      event_.other = target_vertex;
      event_.sample = sample;
      event_.q = target;
      event_.evaluations = checker_.evaluations();
      event_.skipped = checker_.skipped();
      return Extension::Reached;
    }
    if constexpr (kEmit) {
      event_.kind = PlannerEvent::Kind::EdgeRejected;
      event_.vertex = near;
      event_.other = target_vertex;
      event_.sample = sample;
      event_.q = target;
      event_.evaluations = checker_.evaluations();
      event_.collision_t = collision_t;
    }
    return Extension::Trapped;
  }
  // The new end: the target itself within reach, else D along the space's shortest way to it.
  Config q = reaches ? target : space.interpolate(from, target, step_ / d);
  // Its length as the checker measures it (the same formula, so the same bits).
  const double length = reaches ? d : space.distance(from, q);
  double eta = std::numeric_limits<double>::quiet_NaN();
  bool free;
  if (params_.checker.kind == EdgeCheckerSpec::Kind::Bisection) {
    eta = world_->clearance(q);
    free = eta > 0.0;
  } else {
    free = world_->is_free(q);
  }
  ++evaluations_;  // the new end: a configuration evaluated, as the edge check's are
  if (!free) {
    if constexpr (kEmit) {
      event_.kind = PlannerEvent::Kind::SampleRejected;
      event_.vertex = near;
      event_.sample = sample;
      event_.q = q;
      event_.obstacle = world_->obstacle_hit(q);
    }
    return Extension::Trapped;
  }
  if (!check(near, q, length, eta, collision_t)) {
    if constexpr (kEmit) {
      event_.kind = PlannerEvent::Kind::EdgeRejected;
      event_.vertex = near;
      event_.sample = sample;
      event_.q = q;
      event_.evaluations = checker_.evaluations();
      event_.collision_t = collision_t;
    }
    return Extension::Trapped;
  }
  const int v = add_vertex(q, eta, tree, near, length);
  if constexpr (kEmit) {
    event_.kind = PlannerEvent::Kind::SampleAccepted;
    event_.vertex = v;
    event_.other = near;
    event_.sample = sample;
    event_.q = std::move(q);
    event_.evaluations = checker_.evaluations();
    event_.skipped = checker_.skipped();
  }
  return reaches ? Extension::Reached : Extension::Advanced;
}

template TreePlanner::Extension TreePlanner::extend<true>(int, int, const Config&, int, int);
template TreePlanner::Extension TreePlanner::extend<false>(int, int, const Config&, int, int);

bool TreePlanner::verify_edge(const RoadmapEdge& r, double& collision_t) {
  // The ends' clearances as bisection would evaluate them first: world_->clearance() of the
  // vertex, which the roadmap holds already for every vertex but q_init and q_final (theirs is
  // nearest()'s, maybe other bits) once a check needed it. The same numbers give the same
  // pieces, verdict and collision_t. Evaluating the ends again was most of the re-check's work:
  // on the rrt bench's plane, RRT-Connect's re-check took 28 evaluations a query, now 19
  // (callgrind; a query's instructions 15% fewer with the reserve() in reset()).
  const auto known = [this](int v) {
    const double eta = roadmap_.clearance[static_cast<std::size_t>(v)];
    return v >= 2 && !std::isnan(eta) ? eta : world_->clearance(roadmap_.vertices[static_cast<std::size_t>(v)]);
  };
  const double eta_a = known(r.a), eta_b = known(r.b);
  const Config& a = roadmap_.vertices[static_cast<std::size_t>(r.a)];
  const Config& b = roadmap_.vertices[static_cast<std::size_t>(r.b)];
  if (eta_a > 0.0 && eta_b > 0.0)
    exact_.reset(a, b, /*endpoints_known_free=*/true, eta_a, eta_b);
  else
    exact_.reset(a, b);  // never for a tree's vertices (all free); the checker's own verdict then
  while (!exact_.done()) exact_.step();
  if (exact_.verdict() == Verdict::Free) return true;
  collision_t = *exact_.collision_t();
  return false;
}

void TreePlanner::rebuild_index(int tree) {
  const auto t = static_cast<std::size_t>(tree);
  std::vector<int>& members = members_[t];
  members.clear();
  std::vector<Config> points;
  for (std::size_t v = 0; v < tree_.size(); ++v)
    if (tree_[v] == tree) {
      members.push_back(static_cast<int>(v));
      points.push_back(roadmap_.vertices[v]);
    }
  index_[t].build(points);
}

void TreePlanner::remove_edge(int edge) {
  RoadmapEdge& r = roadmap_.edges[static_cast<std::size_t>(edge)];
  r.alive = false;
  --edges_alive_;
  const int was_join = join_edge_;
  join_edge_ = -1;
  if (edge == was_join) return;
  // A tree edge of the path failed: the join it led to joins nothing now (one of its ends leaves
  // its tree below), so it goes too; growing will find another.
  if (was_join >= 0 && roadmap_.edges[static_cast<std::size_t>(was_join)].alive) {
    roadmap_.edges[static_cast<std::size_t>(was_join)].alive = false;
    --edges_alive_;
  }
  // A tree edge: its child (created after its parent: the larger index) and every vertex below
  // it leave the tree. Parents come before children, so one pass in order finds them all.
  const int child = r.b, tree = tree_[static_cast<std::size_t>(child)];
  for (std::size_t v = static_cast<std::size_t>(child); v < tree_.size(); ++v) {
    const int p = parent_[v];
    if (static_cast<int>(v) == child || (p >= 0 && tree_[v] == tree && tree_[static_cast<std::size_t>(p)] == -1))
      tree_[v] = -1;
  }
  rebuild_index(tree);
}

void TreePlanner::query() {
  if (join_edge_ < 0) {
    event_.kind = PlannerEvent::Kind::NoPath;
    phase_ = TreePhase::Done;
    return;
  }
  // q_init ... u (tree 0), the join, w ... q_final (tree 1).
  const RoadmapEdge& join = roadmap_.edges[static_cast<std::size_t>(join_edge_)];
  const int u = tree_[static_cast<std::size_t>(join.a)] == 0 ? join.a : join.b;
  const int w = u == join.a ? join.b : join.a;
  std::vector<int> path, edges;
  for (int v = u; v >= 0; v = parent_[static_cast<std::size_t>(v)]) {
    path.push_back(v);
    if (parent_edge_[static_cast<std::size_t>(v)] >= 0) edges.push_back(parent_edge_[static_cast<std::size_t>(v)]);
  }
  std::reverse(path.begin(), path.end());
  std::reverse(edges.begin(), edges.end());
  edges.push_back(join_edge_);
  for (int v = w; v >= 0; v = parent_[static_cast<std::size_t>(v)]) {
    path.push_back(v);
    if (parent_edge_[static_cast<std::size_t>(v)] >= 0) edges.push_back(parent_edge_[static_cast<std::size_t>(v)]);
  }
  // Every edge of it by the exact check, as PRM re-checks its path (a grid checker may have let
  // an edge through a thin obstacle); a failed one is removed and growing goes on.
  for (int edge : edges) {
    double collision_t = 0.0;
    const RoadmapEdge r = roadmap_.edges[static_cast<std::size_t>(edge)];
    if (verify_edge(r, collision_t)) continue;
    remove_edge(edge);
    event_.kind = PlannerEvent::Kind::PathEdgeRemoved;
    event_.vertex = r.a;
    event_.other = r.b;
    event_.collision_t = collision_t;
    phase_ = samples_drawn_ < params_.samples ? TreePhase::Growing : TreePhase::Query;
    return;
  }
  path_ = std::move(path);
  path_edges_ = std::move(edges);
  path_length_ = 0.0;
  for (int edge : path_edges_) path_length_ += roadmap_.edges[static_cast<std::size_t>(edge)].length;
  event_.kind = PlannerEvent::Kind::PathFound;
  event_.path_length = path_length_;
  phase_ = TreePhase::Done;
}

std::vector<Config> TreePlanner::path_configurations() const {
  std::vector<Config> out;
  for (int v : path_) out.push_back(roadmap_.vertices[static_cast<std::size_t>(v)]);
  return out;
}

int TreePlanner::components() const {
  const std::vector<int> labels = component_labels();
  return labels.empty() ? 0 : *std::max_element(labels.begin(), labels.end()) + 1;
}

double TreePlanner::progress() const {
  switch (phase_) {
    case TreePhase::Endpoints:
      return 0.0;
    case TreePhase::Growing:
      return 0.02 + 0.95 * samples_drawn_ / std::max(1, params_.samples);
    case TreePhase::Query:
      return 0.97;
    default:
      return 1.0;
  }
}

}  // namespace csl
