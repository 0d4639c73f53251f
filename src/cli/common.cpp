// Helpers shared by the CLI's commands: files, scenes, configurations, output.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <ostream>
#include <sstream>

#include "cli/commands.hpp"
#include "core/base/angles.hpp"

namespace csl::cli {

std::string read_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw UsageError(path + ": is a directory, not a scene file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError(path + ": cannot read file");
  // In pieces, stopping past the limit: a huge file is refused without being read into memory.
  std::string text;
  char piece[1 << 16];
  while (in.read(piece, sizeof piece) || in.gcount() > 0) {
    text.append(piece, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxSceneBytes) throw UsageError(path + ": larger than 64 MB, more than any scene within the limits");
  }
  if (in.bad()) throw UsageError(path + ": read error");
  return text;
}

Scene load_scene(const std::string& path) {
  try {
    return scene_from_string(read_file(path));
  } catch (const SceneError& e) {
    throw UsageError(path + ": " + e.what());
  }
}

Config parse_config(const std::string& text, const Scene& scene, const std::string& what) {
  const std::vector<double> v = parse_numbers(text, what);
  const int dof = robot_dof(scene.robot);
  if (static_cast<int>(v.size()) != dof)
    throw UsageError(what + ": expected " + std::to_string(dof) + " comma-separated numbers for robot type '" +
                     robot_type_name(scene.robot) + "', got " + std::to_string(v.size()));
  Config q(dof);
  for (int i = 0; i < dof; ++i) q[i] = v[static_cast<std::size_t>(i)];
  if (std::holds_alternative<ArmRobot>(scene.robot)) return robot_space(scene.robot, {0, 0}, {1, 1}).wrap(q);
  if (q[0] < scene.workspace_min.x() || q[0] > scene.workspace_max.x() || q[1] < scene.workspace_min.y() ||
      q[1] > scene.workspace_max.y())
    throw UsageError(what + ": (" + text + ") lies outside the workspace");
  if (robot_kind(scene.robot) == RobotKind::RigidPolygon) q[2] = wrap_angle(q[2]);
  return q;
}

Vec2 parse_point(const std::string& text, const std::string& what) {
  const std::vector<double> v = parse_numbers(text, what);
  if (v.size() != 2) throw UsageError(what + ": expected x,y");
  return {v[0], v[1]};
}

PlannerOptions take_planner_options(Args& args) {
  PlannerOptions o;
  const auto k = args.take("k"), radius = args.take("radius");
  const bool star = args.take_flag("prm-star");
  if ((k ? 1 : 0) + (radius ? 1 : 0) + (star ? 1 : 0) > 1)
    throw UsageError("choose one neighbour rule: --k, --radius or --prm-star");
  try {
    if (k) o.neighbors = NeighborRule::parse("k:" + *k);
    if (radius) o.neighbors = NeighborRule::parse("radius:" + *radius);
    if (star) o.neighbors = NeighborRule::parse("prm*");
    o.neighbor_flag = k ? "--k" : radius ? "--radius" : star ? "--prm-star" : "";
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string(k ? "--k: " : "--radius: ") + e.what());
  }
  try {
    o.checker = EdgeCheckerSpec::parse(args.take("checker").value_or("bisection"));
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--checker: ") + e.what());
  }
  try {
    o.sampler = SamplerSpec::parse(args.take("sampler").value_or("uniform"));
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--sampler: ") + e.what());
  }
  if (const auto max_pairs = args.take("max-pairs")) {
    o.max_pairs = parse_number(*max_pairs, "--max-pairs");
    if (!(o.max_pairs >= 1.0)) throw UsageError("--max-pairs: must be at least 1");
  }
  if (const auto max_work = args.take("max-work")) o.max_work = parse_max_work(*max_work, "--max-work");
  o.seed = static_cast<std::uint64_t>(take_param(args, kSeed));
  return o;
}

std::string pairs_text(double v, int digits) {
  char text[32];
  if (v < 1e6 && digits <= 6)
    std::snprintf(text, sizeof text, "%.0f", v);
  else
    std::snprintf(text, sizeof text, "%.*g", digits, v);
  return text;
}

std::pair<std::string, std::string> pairs_and_limit_text(double pairs, double limit) {
  std::string limit_text = pairs_text(limit, 17);
  for (int digits = 1; digits < 17; ++digits) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*g", digits, limit);
    if (std::strtod(text, nullptr) == limit) {
      limit_text = text;
      break;
    }
  }
  if (limit < 1e6 && limit == std::floor(limit)) limit_text = pairs_text(limit);
  for (int digits = 3; digits < 17; ++digits)
    if (pairs_text(pairs, digits) != limit_text) return {pairs_text(pairs, digits), limit_text};
  return {pairs_text(pairs, 17), limit_text};
}

void require_pairs_budget(const Space& space, const PlannerOptions& options, int samples, const std::string& run) {
  const NeighborRule& rule = options.neighbors;
  if (within_pairs_budget(space, rule, samples, options.max_pairs)) return;
  const auto [pairs, limit] = pairs_and_limit_text(expected_candidate_pairs(space, rule, samples), options.max_pairs);
  char text[400];
  if (rule.kind == NeighborRule::Kind::Radius) {
    std::snprintf(text, sizeof text,
                  "--radius %g with %d samples means about %s candidate pairs, more than the %s a run may "
                  "check (--max-pairs); with this n, r at most %s",
                  rule.radius, samples, pairs.c_str(), limit.c_str(),
                  radius_for_pairs_text(space, samples, options.max_pairs).c_str());
  } else {
    const std::string named = rule.kind == NeighborRule::Kind::PrmStar ? "--prm-star" : "--k " + std::to_string(rule.k);
    std::snprintf(text, sizeof text,
                  "%s with %d samples means up to %s candidate pairs, more than the %s a run may check "
                  "(--max-pairs); take fewer samples or fewer neighbours (--k)",
                  named.c_str(), samples, pairs.c_str(), limit.c_str());
  }
  throw UsageError(run + text);
}

PlannerChoice take_planner_choice(Args& args, const PlannerOptions& options) {
  const auto name = args.take("planner"), bias = args.take("goal-bias"), step = args.take("step");
  PlannerChoice c;
  if (name) {
    try {
      c.kind = parse_planner_kind(*name);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--planner: ") + e.what());
    }
  }
  const PlannerKindInfo& info = planner_kind_info(c.kind);
  if (info.tree && !options.neighbor_flag.empty())
    throw UsageError(options.neighbor_flag + " is PRM's: " + info.name + " grows trees (choose --planner prm or prm-star)");
  if (c.kind == PlannerChoice::Kind::PrmStar && (options.neighbor_flag == "--k" || options.neighbor_flag == "--radius"))
    throw UsageError(options.neighbor_flag + " does not go with --planner prm-star, which takes PRM*'s k(n)");
  if (bias && c.kind != PlannerChoice::Kind::Rrt)
    throw UsageError(std::string("--goal-bias is RRT's (--planner rrt); ") + info.name + " has no goal bias");
  if (step && !info.tree) throw UsageError(std::string("--step is the tree planners' (rrt, rrt-connect), not ") + info.name + "'s");
  c.neighbors = options.neighbors;
  c.checker = options.checker;
  c.sampler = options.sampler;
  c.seed = options.seed;
  if (info.tree && c.sampler.kind != SamplerSpec::Kind::Uniform)
    throw UsageError(std::string("--sampler is the roadmap planners' (prm, prm-star, lazy-prm); ") + info.name + " samples uniformly");
  if (bias) c.goal_bias = parse_param(*bias, kGoalBias);
  if (step) c.step = parse_param(*step, kTreeStep);
  return c;
}

std::string planner_choice_help() {
  std::string out = "  --planner NAME      the planner: " + planner_names(", ") + "; default prm\n";
  for (const PlannerKindInfo& info : planner_kinds()) {
    std::string name = info.name;
    name.resize(std::max<std::size_t>(name.size(), 14), ' ');
    out += "      " + name + info.summary + "\n";
  }
  return out + option_help(kGoalBias, "B") + option_help(kTreeStep, "D");
}

void require_tree_work_budget(const CollisionWorld& world, const PlannerOptions& options, const PlannerChoice& choice,
                              const std::string& run) {
  const TreeParams params = tree_params(choice);
  const WorkEstimate w = expected_tree_work(world, choice);
  if (w.total() <= options.max_work) return;
  char text[600];
  std::snprintf(text, sizeof text,
                "%s with %d samples, step %g and %s means about %s of work (one configuration of this scene costs "
                "%.0f), more than the %s a run may take (--max-work); take fewer samples, a longer step or a "
                "coarser checker",
                planner_kind_info(choice.kind).name, params.samples, tree_step(world.space(), params.step),
                params.checker.name().c_str(), work_text(w.total()).c_str(), world.evaluation_cost(),
                work_text(options.max_work).c_str());
  throw UsageError(run + text);
}

double parse_max_work(const std::string& text, const std::string& what) {
  const double v = parse_number(text, what);
  if (!(v >= 1.0)) throw UsageError(what + ": must be at least 1");
  return v;
}

void require_work_budget(const CollisionWorld& world, const PlannerOptions& options, const PrmParams& params,
                         const std::string& run) {
  const WorkEstimate w = expected_prm_work(world, params);
  if (w.total() <= options.max_work) return;
  char text[600];
  std::snprintf(text, sizeof text,
                "%d samples with %s and %s mean about %s of work (%s candidate pairs at %s each; one "
                "configuration of this scene costs %.0f), more than the %s a run may take (--max-work); "
                "take fewer samples, fewer neighbours or a coarser checker",
                params.samples, params.neighbors.name().c_str(),
                params.connector ? "the potential connector" : params.checker.name().c_str(), work_text(w.total()).c_str(),
                pairs_text(w.pairs).c_str(), work_text(w.per_edge).c_str(), world.evaluation_cost(),
                work_text(options.max_work).c_str());
  throw UsageError(run + text);
}

void require_free(const CollisionWorld& world, const Config& q, const std::string& what) {
  const auto n = world.nearest(q);
  if (n.clearance > 0.0) return;
  const Obstacle& o = world.obstacles()[static_cast<std::size_t>(n.obstacle)];
  throw UsageError(what + " is in collision with obstacles[" + std::to_string(n.obstacle) + "] (a " +
                   obstacle_type_name(o) + ")");
}

void print_json(std::ostream& os, const nlohmann::json& j) {
  os << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
}

}  // namespace csl::cli
