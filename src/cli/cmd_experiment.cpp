// cspacelab experiment: PRM's empirical failure rate against the bound, for several n.
#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "cli/commands.hpp"
#include "core/teaching/experiment.hpp"

namespace csl::cli {
namespace {

using json = nlohmann::json;

json number_or_null(bool has, double v) { return has ? json(v) : json(nullptr); }

// The candidate pairs a whole experiment may be expected to check unless --max-total-pairs says
// otherwise: --max-pairs bounds each run, but T runs for each n multiply it (T = 100000 at
// n = 10^6 passes it and would run for days, printing nothing until the end). The default is 50
// runs at the per-run limit: 1e9 with --max-pairs' default, 3 to 8 minutes here (wall-gap,
// k = 10, bisection, 20 runs of 100000 samples and the reference run: 2.4e7 pairs expected,
// 4.1 s; the radius run measured for --max-pairs: 2e7 in 9 s).
constexpr double kDefaultRunsInTotal = 50;

// UsageError if the experiment (T runs per n, and the reference run) is expected to check more
// candidate pairs in all than `limit`.
void require_total_budget(const Space& space, const PlannerOptions& options, const ExperimentParams& params,
                          const std::string& list, int reference_samples, double limit) {
  const double reference = expected_candidate_pairs(space, options.neighbors, reference_samples);
  double total = reference;
  for (int n : params.sample_counts) total += params.trials * expected_candidate_pairs(space, options.neighbors, n);
  if (total <= limit) return;
  const auto [total_text, limit_text] = pairs_and_limit_text(total, limit);
  // A long list is named by its size and largest value: the error stays short.
  const std::string named = list.size() <= 40 ? list
                                              : "(" + std::to_string(params.sample_counts.size()) + " values up to " +
                                                    std::to_string(*std::max_element(params.sample_counts.begin(),
                                                                                     params.sample_counts.end())) +
                                                    ")";
  const bool radius = options.neighbors.kind == NeighborRule::Kind::Radius;
  throw UsageError("--trials " + std::to_string(params.trials) + " with --samples-list " + named + " means about " +
                   total_text + " candidate pairs in all (the reference run: " + pairs_text(reference) +
                   "), more than the " + limit_text +
                   " an experiment may check (--max-total-pairs); take fewer trials, fewer samples or " +
                   (radius ? "a smaller --radius" : "fewer neighbours (--k)") +
                   (reference > limit ? ", and fewer --reference-samples" : ""));
}

// The runs' work together (work.hpp): each run is held to --max-work, and all of them, with the
// reference run and its Monte Carlo volume, to `limit` (--max-total-work).
void require_total_work(const CollisionWorld& world, const ExperimentParams& params, double limit) {
  const double total = expected_experiment_work(world, params).total;
  if (total <= limit) return;
  throw UsageError("the experiment's runs mean about " + work_text(total) + " of work in all, more than the " +
                   work_text(limit) + " an experiment may take (--max-total-work, default 10 x --max-work); " +
                   "take fewer trials, fewer samples or fewer neighbours");
}

int run_experiment(Args& args, std::ostream& os) {
  const auto list = args.take("samples-list"), trials = args.take("trials"), reference = args.take("reference-samples");
  const auto max_total_text = args.take("max-total-pairs");
  const auto max_total_work_text = args.take("max-total-work");
  PlannerOptions options = take_planner_options(args);
  const PlannerChoice choice = take_planner_choice(args, options);
  const PlannerKindInfo& info = planner_kind_info(choice.kind);
  if (choice.kind == PlannerChoice::Kind::PrmStar) options.neighbors = NeighborRule::parse("prm*");
  const double max_total_work =
      max_total_work_text ? parse_max_work(*max_total_work_text, "--max-total-work") : 10.0 * options.max_work;
  double max_total = kDefaultRunsInTotal * options.max_pairs;
  if (max_total_text) {
    max_total = parse_number(*max_total_text, "--max-total-pairs");
    if (!(max_total >= 1.0)) throw UsageError("--max-total-pairs: must be at least 1");
  }
  const std::string path = args.take_positional("SCENE.json");
  args.finish();
  if (!list) throw UsageError("missing --samples-list (e.g. --samples-list 50,100,200)");

  const Scene scene = load_scene(path);
  const CollisionWorld world(scene);
  require_free(world, scene.start, "the start");
  require_free(world, scene.goal, "the goal");
  ExperimentParams params;
  for (double n : parse_numbers(*list, "--samples-list")) {
    if (!in_range(kExperimentSamples, n)) throw UsageError("--samples-list: each n is " + range_text(kExperimentSamples));
    params.sample_counts.push_back(static_cast<int>(n));
  }
  params.trials = static_cast<int>(trials ? parse_param(*trials, kExperimentTrials) : kExperimentTrials.def);
  if (reference) params.reference_samples = static_cast<int>(parse_param(*reference, kReferenceSamples));
  params.seed = options.seed;
  params.neighbors = options.neighbors;
  params.checker = options.checker;
  params.sampler = options.sampler;
  if (choice.kind != PlannerChoice::Kind::Prm && choice.kind != PlannerChoice::Kind::PrmStar) {
    // The trials' planner (a tree, Lazy PRM); the reference run stays PRM's (it measures the scene).
    params.planner = [choice](int samples, std::uint64_t seed) {
      PlannerChoice trial = choice;
      trial.samples = samples;
      trial.seed = seed;
      return make_planner_factory(trial);
    };
  }
  std::optional<Experiment> ex;
  try {
    ex.emplace(world, scene.start, scene.goal, params);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const int largest_n = *std::max_element(params.sample_counts.begin(), params.sample_counts.end());
  PrmParams largest;
  largest.neighbors = params.neighbors;
  largest.checker = params.checker;
  if (!info.tree) {
    // Every run within the budget: the largest n, and the reference run (by default 4 x that n).
    require_pairs_budget(world.space(), options, largest_n);
    require_pairs_budget(world.space(), options, ex->params().reference_samples,
                         "the reference run (--reference-samples M, by default 4 x the largest n, within [2000, 1000000]): ");
    require_total_budget(world.space(), options, params, *list, ex->params().reference_samples, max_total);
    largest.samples = largest_n;
    largest.sampler = params.sampler;  // (Lazy PRM's work is PRM's at most: it checks fewer edges)
    require_work_budget(world, options, largest);
    largest.sampler = SamplerSpec{};  // the reference run samples uniformly
    largest.samples = ex->params().reference_samples;
    require_work_budget(world, options, largest, "the reference run: ");
    require_total_work(world, ex->params(), max_total_work);
  } else {
    // The trials' tree runs, and the reference run, which is PRM's all the same.
    PlannerChoice run = choice;
    run.samples = largest_n;
    require_tree_work_budget(world, options, run);
    require_pairs_budget(world.space(), options, ex->params().reference_samples,
                         "the reference run (--reference-samples M, by default 4 x the largest n, within [2000, 1000000]): ");
    largest.samples = ex->params().reference_samples;
    require_work_budget(world, options, largest, "the reference run: ");
    // All runs' work: the reference run's (an experiment with no rows) and T tree runs per n.
    ExperimentParams reference_only = ex->params();
    reference_only.sample_counts.clear();
    double total = expected_experiment_work(world, reference_only).total;
    for (int n : params.sample_counts) {
      run.samples = n;
      total += params.trials * expected_tree_work(world, run).total();
    }
    if (total > max_total_work)
      throw UsageError("the experiment's runs mean about " + work_text(total) + " of work in all, more than the " +
                       work_text(max_total_work) + " an experiment may take (--max-total-work, default 10 x --max-work); " +
                       "take fewer trials or fewer samples");
  }
  ex->run();

  const ExperimentReference& ref = ex->reference();
  json rows = json::array();
  for (const ExperimentRow& row : ex->rows()) {
    rows.push_back({{"samples", row.samples},
                    {"trials", row.trials},
                    {"failures", row.failures},
                    {"configurations_tested",
                     row.trials > 0 ? json(static_cast<double>(row.configurations_tested) / row.trials) : json(nullptr)},
                    {"failure_rate", row.failure_rate.estimate},
                    {"ci_low", row.failure_rate.low},
                    {"ci_high", row.failure_rate.high},
                    {"bound", number_or_null(row.has_bound, row.bound.bound)},
                    {"bound_vacuous", row.has_bound ? json(row.bound.vacuous) : json(nullptr)}});
  }
  print_json(os, {{"reference",
                   {{"path_exists", ref.path_exists},
                    {"samples", ref.samples},
                    {"path_length", number_or_null(ref.path_exists, ref.path_length)},
                    {"workspace_clearance", number_or_null(ref.path_exists, ref.workspace_clearance)},
                    {"clearance", number_or_null(ref.path_exists, ref.clearance)},
                    {"free_fraction", ref.free_fraction},
                    {"free_volume", ref.free_volume},
                    {"dimension", ref.dimension}}},
                  {"planner", info.name},
                  {"neighbors", info.tree ? json(nullptr) : json(params.neighbors.name())},
                  {"goal_bias", choice.kind == PlannerChoice::Kind::Rrt ? json(choice.goal_bias) : json(nullptr)},
                  {"step", info.tree ? json(tree_step(world.space(), choice.step)) : json(nullptr)},
                  {"checker", params.checker.name()},
                  {"sampler", info.tree ? json(nullptr) : json(params.sampler.name())},
                  {"seed", params.seed},
                  {"rows", rows}});
  return 0;
}

}  // namespace

const Command kExperimentCommand{
    "experiment", "a planner's failure rate over many runs, for several n, against PRM's bound",
    "Usage: cspacelab experiment SCENE.json --samples-list N1,N2,... [--trials T]\n"
    "                            [--planner prm|prm-star|lazy-prm|rrt|rrt-connect]\n"
    "                            [--goal-bias B] [--step D]\n"
    "                            [--k K | --radius R | --prm-star] [--checker C] [--seed S]\n"
    "                            [--reference-samples M] [--max-pairs P] [--max-total-pairs P]\n"
    "                            [--max-work W] [--max-total-work W]\n"
    "                            [--sampler uniform|gaussian:S|bridge:S|halton]\n\n" +
    option_help(kExperimentSamples, "N1,...", false) + option_help(kExperimentTrials, "T") +
    option_help(kReferenceSamples, "M") + planner_choice_help() + option_help(kNeighborK, "K") + option_help(kSeed, "S") +
    "\nRuns the planner (PRM by default) T times (each with its own seed derived from S) for each n,\n"
    "and counts "
    "failures: start and goal not connected. Whether a path exists at all, and its length L and\n"
    "clearance r for the bound of section 2.1, come from a reference run with M samples (default,\n"
    "or M = 0: max(2000, 4 x the largest n), at most 1000000): its roadmap's widest path (the\n"
    "largest least clearance its vertices and edges prove, then the shortest), not PRM's\n"
    "shortest, which grazes corners; mu(F) from 100000 Monte Carlo samples. r is the path's least\n"
    "workspace clearance, proven (a lower bound from clearances and motion bounds, a few percent\n"
    "below the truth at most), divided by the robot's Lipschitz constant (a C-space clearance).\n"
    "  -> {\"reference\": {\"path_exists\", \"samples\", \"path_length\", \"workspace_clearance\",\n"
    "      \"clearance\", \"free_fraction\", \"free_volume\", \"dimension\"},\n"
    "      \"rows\": [{\"samples\": n, \"trials\": T, \"failures\", \"configurations_tested\" (the mean\n"
    "      per run of `cspacelab help plan`'s configurations_tested), \"failure_rate\", \"ci_low\",\n"
    "      \"ci_high\" (95% Wilson interval), \"bound\" (null without a reference path),\n"
    "      \"bound_vacuous\"}], \"planner\", \"neighbors\" (null for a tree planner), \"checker\",\n"
    "      \"sampler\" (null for a tree planner), \"seed\", \"goal_bias\" (rrt's B, else null), \"step\"\n"
    "      (a tree planner's D, else null)}\n"
    "With --planner rrt, rrt-connect or lazy-prm the T runs for each n are that planner's with a\n"
    "budget of n samples (see `cspacelab help plan`); the reference run is PRM's all the same (it\n"
    "measures the scene), and the bound stays PRM's, for comparison.\n"
    "--sampler is the trials' (below); the reference run samples uniformly.\n" + kSamplerHelp +
    "If the reference run finds no path, failures are still counted but mean little.\n"
    "If any run, the reference run included, is expected to check more than P candidate pairs\n"
    "(--max-pairs, default 2e7), nothing runs: an error (exit status 2) says so, and for --radius\n"
    "the largest radius that fits. So does an experiment whose runs, T for each n and the reference\n"
    "run, are expected to check more than --max-total-pairs in all (default 50 x --max-pairs: 1e9,\n"
    "minutes; raising --max-pairs raises it too).\n"
    "Work is held the same way (see `cspacelab help plan`): each run to --max-work (default\n"
    "1e11 units), all of them with the reference run and its Monte Carlo volume to\n"
    "--max-total-work (default 10 x --max-work).\n",
    run_experiment};

}  // namespace csl::cli
