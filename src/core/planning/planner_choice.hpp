#pragma once
// Which planner to run, with its options, as the CLI (plan --planner, experiment --planner) and
// the lessons name it: parsed and checked once here, then turned into a PlannerFactory, so that
// no surface names a planner's type. A planner is one row of the table in planner_choice.cpp
// (its name, a line of help, and how to make it); a new one (lazy-prm) is a row, an enum value
// and its make function, and every surface that lists the table offers it.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/checking/edge_check.hpp"
#include "core/planning/local_connector.hpp"
#include "core/planning/planner.hpp"
#include "core/planning/prm.hpp"
#include "core/planning/sampler.hpp"
#include "core/planning/tree_planner.hpp"

namespace csl {

struct PlannerChoice {
  enum class Kind { Prm, PrmStar, LazyPrm, Rrt, RrtConnect };
  Kind kind = Kind::Prm;
  /// The sample budget: PRM's n; a tree planner's samples drawn (goal draws included).
  int samples = 200;
  /// PRM's rule for close vertices (prm-star ignores it: PRM*'s k(n) always).
  NeighborRule neighbors;
  EdgeCheckerSpec checker;  ///< default: exact bisection
  /// Where the roadmap planners (prm, prm-star, lazy-prm) draw their samples; the tree planners
  /// sample uniformly (another sampler is an error).
  SamplerSpec sampler;
  std::uint64_t seed = 1;
  /// PRM's local connector (null: the straight line).
  std::shared_ptr<const LocalConnector> connector;
  /// The tree planners': B (RRT's goal bias; RRT-Connect has none) and D (0: tree_step()'s default).
  double goal_bias = kGoalBias.def;
  double step = kTreeStep.def;
};

/// One planner the choice offers.
struct PlannerKindInfo {
  PlannerChoice::Kind kind;
  const char* name;     ///< as the CLI and the API spell it: "prm-star"
  const char* summary;  ///< one line for --help
  bool tree;            ///< grows trees (takes --goal-bias and --step) rather than a roadmap
};
/// Every planner, in the order help texts list them.
const std::vector<PlannerKindInfo>& planner_kinds();
const PlannerKindInfo& planner_kind_info(PlannerChoice::Kind kind);
/// "prm|prm-star|..." (`separator` between the names).
std::string planner_names(const char* separator = "|");
/// The kind named `name`; std::invalid_argument "unknown planner 'x' (prm, prm-star, ...)".
PlannerChoice::Kind parse_planner_kind(const std::string& name);

/// std::invalid_argument with one line naming the first bad option (params.hpp's error text:
/// "samples: an integer in [0, 1000000]"), or an option the planner does not take (a local
/// connector for a tree planner), a goal bias or step outside kGoalBias's or kTreeStep's range.
void validate(const PlannerChoice& choice);
/// Makes planners of `choice` (validated first: throws as validate() does).
PlannerFactory make_planner_factory(const PlannerChoice& choice);
/// The tree planners' parameters of `choice`.
TreeParams tree_params(const PlannerChoice& choice);

}  // namespace csl
