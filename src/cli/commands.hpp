#pragma once
// The CLI's commands. Each lives in its own cmd_*.cpp; cli.cpp lists them in kCommands.
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <utility>

#include "cli/args.hpp"
#include "core/checking/collision.hpp"
#include "core/planning/planner_choice.hpp"
#include "core/planning/prm.hpp"
#include "core/scene/scene.hpp"
#include "core/teaching/work.hpp"

namespace csl::cli {

struct Command {
  const char* name;
  const char* summary;  ///< one line for `cspacelab --help`
  std::string usage;    ///< full help for `cspacelab help NAME` / `cspacelab NAME --help` (option_help() lines for
                        ///< the options of core/base/params.hpp: built once, at start)
  int (*run)(Args& args, std::ostream& os);  ///< prints JSON on os (stdout); throws UsageError for bad input
};

extern const Command kValidateCommand;
extern const Command kCheckCommand;
extern const Command kDistanceCommand;
extern const Command kCspaceOfCommand;
extern const Command kPlanCommand;
extern const Command kBoundCommand;
extern const Command kVisibilityCommand;
extern const Command kExperimentCommand;
extern const Command kCspaceCommand;
extern const Command kPotentialCommand;
extern const Command kDescendCommand;
extern const Command kHomeworkCommand;
extern const Command kExerciseCommand;
extern const Command kLinkCommand;
extern const Command kAssignmentCommand;

/// Reads a whole file; UsageError naming the path if it cannot be read.
std::string read_file(const std::string& path);
/// Reads and validates a scene file; UsageError "PATH: field: problem" if it is not valid.
Scene load_scene(const std::string& path);
/// A configuration for the scene's robot from "a,b[,c]": right arity, finite, angles wrapped,
/// positions inside the workspace; UsageError naming `what` otherwise.
Config parse_config(const std::string& text, const Scene& scene, const std::string& what);
/// A point "x,y"; UsageError naming `what` otherwise.
Vec2 parse_point(const std::string& text, const std::string& what);
/// The candidate pairs a run may be expected to check unless --max-pairs says otherwise: a
/// radius rule grows the work with n^2 (200000 samples within r = 5 is 2e10 pairs: hours and
/// gigabytes). 2e7 is about 10 seconds and 1 GB (measured: 100000 samples, r = 0.0353 in the
/// narrow passage, 1.96e7 pairs expected, 1.5e7 checked: 9 s, 1.07 GB); it admits k = 19 at
/// the largest n ((10^6 + 2) k pairs).
inline constexpr double kDefaultMaxPairs = 2e7;

/// The planner options shared by plan and experiment: [--k K | --radius R | --prm-star]
/// [--checker bisection|grid:N|step:D] [--sampler ...] [--seed S] [--max-pairs P]; defaults k = 10, bisection, uniform,
/// seed 1, kDefaultMaxPairs.
struct PlannerOptions {
  NeighborRule neighbors;
  std::string neighbor_flag;  ///< the neighbour option given ("--k", "--radius", "--prm-star"), "" for none
  EdgeCheckerSpec checker;
  SamplerSpec sampler;  ///< --sampler uniform|gaussian:S|bridge:S|halton (default uniform)
  std::uint64_t seed = 1;
  double max_pairs = kDefaultMaxPairs;  ///< --max-pairs
  double max_work = kCliMaxWork;        ///< --max-work (work.hpp's units)
};
PlannerOptions take_planner_options(Args& args);
/// --sampler in plan's and experiment's help.
inline const std::string kSamplerHelp =
    "--sampler: where PRM's N samples come from (N counts draws; a draw keeps at most one\n"
    "configuration; core/planning/sampler.hpp): uniform (default) keeps q if free; gaussian:S\n"
    "draws q1 uniformly and q2 ~ N(q1, S) in the space's metric and keeps whichever is free if\n"
    "exactly one is (Boor et al. 1999: samples near obstacles' boundaries); bridge:S keeps the\n"
    "midpoint of q1 and q2 when both are in collision and it is free (Hsu et al. 2003: samples\n"
    "inside narrow passages); halton takes the Halton sequence (bases 2, 3, 5, ...; the seed plays\n"
    "no part). S > 0, in the units of the space's metric. q2 is clamped into the bounds.\n"
    "gaussian:S,uniform:W and bridge:S,uniform:W (W in [0, 1)) are Hsu et al.'s hybrids: a\n"
    "draw is a uniform one with chance W. A bridge alone keeps points in passages only, which a\n"
    "start and goal out in the open rarely see.\n"
    "Gaussian and bridge need obstacles with an inside: a wall (a segment) has none, and\n"
    "near walls alone they keep next to nothing.\n";
/// An expected count of candidate pairs as an error names it: in full below 10^6, else with
/// `digits` significant digits.
std::string pairs_text(double pairs, int digits = 3);
/// `pairs` over a limit it exceeds, and the limit, as text: the limit as given (the shortest text
/// that reads back as it), `pairs` with as few digits as tell the two apart (never "2e+07 ...
/// more than the 2e+07").
std::pair<std::string, std::string> pairs_and_limit_text(double pairs, double limit);
/// UsageError if PRM with `samples` samples is expected to check more candidate pairs than
/// options.max_pairs (expected_candidate_pairs()): said before the run, with what would fit.
/// `run`, if not empty, names the run first ("the reference run: ").
void require_pairs_budget(const Space& space, const PlannerOptions& options, int samples,
                          const std::string& run = "");
/// UsageError if PRM with `params` on `world` is expected to take more than options.max_work
/// units (expected_prm_work(): the pairs times what one edge check costs in this scene with this
/// checker, so 1000 polygons of 256 vertices with grid:1000000 is refused, where the pairs
/// alone passed and the run took hours). `run` as for require_pairs_budget.
void require_work_budget(const CollisionWorld& world, const PlannerOptions& options, const PrmParams& params,
                         const std::string& run = "");
/// --planner NAME (default prm), --goal-bias B and --step D, checked against each other and
/// against the neighbour option in `options` (a tree planner takes none; prm-star takes no --k or
/// --radius; only rrt takes --goal-bias, only the tree planners --step): UsageError naming the
/// flag. The choice carries `options`' neighbour rule, checker and seed; the caller sets samples.
PlannerChoice take_planner_choice(Args& args, const PlannerOptions& options);
/// The --help lines of --planner, --goal-bias and --step.
std::string planner_choice_help();
/// require_work_budget() for a tree planner (expected_tree_work()).
void require_tree_work_budget(const CollisionWorld& world, const PlannerOptions& options, const PlannerChoice& choice,
                              const std::string& run = "");
/// --max-work's value: a number >= 1.
double parse_max_work(const std::string& text, const std::string& what);
/// UsageError if q is not free in the scene ("where it matters": planning from it).
void require_free(const CollisionWorld& world, const Config& q, const std::string& what);
/// Prints JSON on os (one line; invalid UTF-8 in strings is replaced, not an error).
void print_json(std::ostream& os, const nlohmann::json& j);

}  // namespace csl::cli
