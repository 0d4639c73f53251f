// cspacelab plan: the probabilistic roadmap method on a scene, from start to goal.
#include <chrono>
#include <cstring>

#include "cli/commands.hpp"
#include "core/planning/lazy_prm.hpp"
#include "core/planning/planner_json.hpp"
#include "core/planning/potential_connector.hpp"

namespace csl::cli {
namespace {

using json = nlohmann::json;

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

int run_plan(Args& args, std::ostream& os) {
  const auto samples = args.take("samples");
  const PlannerOptions options = take_planner_options(args);
  PlannerChoice choice = take_planner_choice(args, options);
  const bool roadmap_out = args.take_flag("roadmap");
  const auto connector_flag = args.take("connector");
  const std::string connector = connector_flag.value_or("straight");
  if (connector != "straight" && connector != "potential")
    throw UsageError("--connector: '" + connector + "' is not straight or potential");
  const PlannerKindInfo& info = planner_kind_info(choice.kind);
  if (info.tree && connector_flag)
    throw UsageError(std::string("--connector is PRM's: ") + info.name + " joins its trees by straight lines");
  const std::string path = args.take_positional("SCENE.json");
  args.finish();

  const Scene scene = load_scene(path);
  const CollisionWorld world(scene);
  require_free(world, scene.start, "the start");
  require_free(world, scene.goal, "the goal");
  choice.samples = static_cast<int>(samples ? parse_param(*samples, kPrmSamples) : kPrmSamples.def);
  if (connector == "potential") choice.connector = std::make_shared<const PotentialConnector>();
  if (info.tree) {
    require_tree_work_budget(world, options, choice);
  } else {
    PrmParams params;
    params.samples = choice.samples;
    params.neighbors = choice.kind == PlannerChoice::Kind::PrmStar ? NeighborRule::parse("prm*") : options.neighbors;
    params.checker = options.checker;
    params.connector = choice.connector;
    params.sampler = choice.sampler;
    PlannerOptions budget = options;
    budget.neighbors = params.neighbors;
    require_pairs_budget(world.space(), budget, params.samples);
    require_work_budget(world, budget, params);
  }
  std::unique_ptr<Planner> planner;
  try {
    planner = make_planner_factory(choice)(world, scene.start, scene.goal);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }

  // Build: to the query (PRM's graph search, a tree's path check); then the query.
  const auto t0 = std::chrono::steady_clock::now();
  while (!planner->done() && std::strcmp(planner->phase_label(), "query") != 0) planner->finish_phase();
  const double build = seconds_since(t0);
  const auto t1 = std::chrono::steady_clock::now();
  planner->run();
  const double query = seconds_since(t1);

  // The planner's state as the lab reports it (core/planning/planner_json.hpp), and how this run went.
  json out = planner_state_json(*planner, roadmap_out);
  out["build_seconds"] = build;
  out["query_seconds"] = query;
  out["planner"] = info.name;
  out["samples"] = choice.samples;
  out["checker"] = choice.checker.name();
  out["sampler"] = info.tree ? json(nullptr) : json(choice.sampler.name());
  out["connector"] = connector;
  out["seed"] = choice.seed;
  if (const auto* prm = dynamic_cast<const Prm*>(planner.get())) {
    out["neighbors"] = prm->params().neighbors.name();
    out["goal_bias"] = nullptr;
    out["step"] = nullptr;
  } else if (const auto* lazy = dynamic_cast<const LazyPrm*>(planner.get())) {
    out["neighbors"] = lazy->params().neighbors.name();
    out["goal_bias"] = nullptr;
    out["step"] = nullptr;
  } else {
    const auto& tree = dynamic_cast<const TreePlanner&>(*planner);
    out["neighbors"] = nullptr;
    out["goal_bias"] = choice.kind == PlannerChoice::Kind::Rrt ? json(choice.goal_bias) : json(nullptr);
    out["step"] = tree.step_size();
  }
  print_json(os, out);
  return 0;
}

}  // namespace

const Command kPlanCommand{
    "plan", "plan from start to goal with the probabilistic roadmap method",
    "Usage: cspacelab plan SCENE.json [--planner prm|prm-star|lazy-prm|rrt|rrt-connect]\n"
    "                      [--samples N] [--k K | --radius R | --prm-star] [--goal-bias B] [--step D]\n"
    "                      [--checker bisection|grid:N|step:D] [--seed S] [--roadmap]\n"
    "                      [--sampler uniform|gaussian:S|bridge:S|halton]\n"
    "                      [--connector straight|potential] [--max-pairs P] [--max-work W]\n\n" +
    planner_choice_help() + option_help(kPrmSamples, "N") + option_help(kNeighborK, "K") + option_help(kSeed, "S") +
    "\nRuns PRM as the homework states it: add start and goal to V; draw N samples\n"
    "uniformly in the configuration space and keep the free ones; for each vertex, check the\n"
    "straight line to each close vertex (the K nearest; all within distance R; or\n"
    "PRM*'s k(n) = ceil(e (1 + 1/d) ln n)) with the chosen checker (default bisection, exact);\n"
    "then search the graph (A*). The path's edges are re-checked exactly; an edge that fails is\n"
    "removed and the search repeated. The same scene, options and seed give the\n"
    "same roadmap on every machine and in the browser.\n"
    "--connector potential joins close vertices by gradient descent on the potential field\n"
    "toward the other vertex instead of the straight line (homework section 2.4; see\n"
    "`cspacelab help potential`; here a gentle field, eta = 1e-6 and rho0 = 0.05, steps of\n"
    "0.01, at most 200, tolerance 0.02, no escapes): an edge exists if the descent gets there;\n"
    "its pieces are proven free by the exact check (--checker then plays no part). The path\n"
    "then runs through the descents' waypoints.\n"
    "--planner prm-star is PRM with --prm-star (which keeps working with the default planner).\n"
    "--planner rrt grows a tree from the start: each step draws the goal with probability B\n"
    "(--goal-bias) or else a uniform sample, and extends the tree's nearest vertex toward it by at\n"
    "most D (--step, in the space's metric, angles the short way round); the new end and the\n"
    "edge are checked with --checker. Only a goal draw within D of the tree reaches the goal, so\n"
    "B = 0 finds no path. --planner rrt-connect grows one tree from the start and one from the\n"
    "goal: one extends toward a sample, the other then extends toward that new vertex by steps of\n"
    "D until it reaches it (a path) or is blocked; then they swap. N is the tree planners' budget\n"
    "of samples drawn. Their path is re-checked exactly, as PRM's. --k, --radius, --prm-star and\n"
    "--connector are PRM's; --goal-bias is RRT's alone, --step the tree planners'. Each is an\n"
    "error (exit status 2) with a planner that does not take it.\n"
    "--planner lazy-prm builds PRM's roadmap without checking its edges (Bohlin and Kavraki 2000),\n"
    "then repeatedly takes the shortest path, checks its unchecked edges with --checker (bisection:\n"
    "exact), removes those in collision and searches again, until a path is proven free or none is\n"
    "left. It adds \"edges_unchecked\": the edges never checked; with --roadmap also \"edge_checked\":\n"
    "[bool, ...] beside \"edge_list\". It takes no --connector.\n" + kSamplerHelp + "\n"
    "Output: {\"solved\": bool, \"path\": [Q, ...] (with any connector's waypoints),\n"
    "  \"path_length\": x|null, \"nodes\": int, \"edges\": int, \"components\": int,\n"
    "  \"edge_checks\": int, \"evaluations\": int, \"build_seconds\": x, \"query_seconds\": x,\n"
    "  (evaluations: configurations the collision checker tested, as each planner counts them:\n"
    "  PRM's and Lazy PRM's leave their samples out; with grid:N or step:D a roadmap edge skips\n"
    "  those its endpoints' clearances prove free, which changes no verdict),\n"
    "  \"configurations_tested\": int (every configuration given to the collision checker: the\n"
    "  endpoints, samples, the bridge and Gaussian samplers' partner draws, edge checks' points,\n"
    "  the ends' clearances and the path's exact re-check; the same measure for every planner),\n"
    "  \"planner\", \"samples\", \"neighbors\" (null for a tree planner), \"checker\", \"sampler\" (null\n"
    "  for a tree planner), \"connector\", \"seed\", \"goal_bias\" (rrt's B, else null), \"step\" (a tree\n"
    "  planner's D as used, else null),\n"
    "  \"steps\": the planner's step count, \"roadmap_hash\": 16 hex digits (FNV-1a of V and E),\n"
    "  \"phase\": \"done\", \"done\": true, \"samples_drawn\": int (accepted and rejected),\n"
    "  \"last_event\": \"path_found\" or \"no_path\"} (the fields the lab's state() reports)\n"
    "With --roadmap also \"vertices\": [Q, ...] and \"edge_list\": [[a, b], ...] (indices into\n"
    "vertices; 0 is the start, 1 the goal). A tree planner's edges join each vertex to its parent\n"
    "(and the one edge that joins the start's tree to the goal or its tree).\n"
    "A start or goal in collision is an error (exit status 2) naming the obstacle.\n"
    "So is a run expected to check more than P candidate pairs (default 2e7): a radius makes them\n"
    "grow with N^2 ((N+2)(N+1)/2 times the chance that two vertices lie within R), k rules with\n"
    "(N+2) K.\n"
    "For --radius the error says the largest R that fits; --max-pairs raises the limit.\n"
    "And so is a run expected to take more than W units of work (default 1e11, a minute or\n"
    "so): a unit is one primitive distance test (the robot's point, link or edge against a\n"
    "disk, a wall or a polygon edge); a configuration costs one per obstacle plus the robot's\n"
    "parts times the obstacles' (a point among 1000 polygons of 256 vertices: 257000); a run\n"
    "costs its samples' configurations plus its candidate pairs times the configurations one\n"
    "edge check is expected to test (grid:N: N - 2; step:D: the expected edge length / D;\n"
    "bisection: 2; the potential connector: 800). The error gives the figures; --max-work\n"
    "raises the limit. The lab in the browser takes at most 4e9.\n",
    run_plan};

}  // namespace csl::cli
