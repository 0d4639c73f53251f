#include "core/planning/planner_choice.hpp"

#include <stdexcept>

#include "core/base/params.hpp"
#include "core/base/text.hpp"
#include "core/planning/lazy_prm.hpp"
#include "core/planning/rrt.hpp"
#include "core/planning/rrt_connect.hpp"

namespace csl {
namespace {

PrmParams prm_params(const PlannerChoice& c) {
  PrmParams p;
  p.samples = c.samples;
  p.neighbors = c.kind == PlannerChoice::Kind::PrmStar ? NeighborRule::parse("prm*") : c.neighbors;
  p.checker = c.checker;
  p.seed = c.seed;
  p.connector = c.connector;
  p.sampler = c.sampler;
  return p;
}

PlannerFactory make_prm(const PlannerChoice& c) { return prm_factory(prm_params(c)); }
PlannerFactory make_lazy_prm(const PlannerChoice& c) { return lazy_prm_factory(prm_params(c)); }
PlannerFactory make_rrt(const PlannerChoice& c) { return rrt_factory(tree_params(c)); }
PlannerFactory make_rrt_connect(const PlannerChoice& c) { return rrt_connect_factory(tree_params(c)); }

// The table: a planner is a row here (and its Kind).
struct Row {
  PlannerKindInfo info;
  PlannerFactory (*make)(const PlannerChoice&);
};
const std::vector<Row>& rows() {
  static const std::vector<Row> kRows = {
      {{PlannerChoice::Kind::Prm, "prm", "the probabilistic roadmap (--k, --radius or --prm-star close vertices)", false},
       make_prm},
      {{PlannerChoice::Kind::PrmStar, "prm-star", "PRM with PRM*'s k(n) = ceil(e (1 + 1/d) ln n) nearest", false},
       make_prm},
      {{PlannerChoice::Kind::LazyPrm, "lazy-prm",
        "PRM with its edges checked only when a shortest path uses them (Bohlin and Kavraki)", false},
       make_lazy_prm},
      {{PlannerChoice::Kind::Rrt, "rrt", "a rapidly-exploring random tree from the start (--goal-bias, --step)", true},
       make_rrt},
      {{PlannerChoice::Kind::RrtConnect, "rrt-connect", "two trees, from start and goal, grown toward each other (--step)",
        true},
       make_rrt_connect},
  };
  return kRows;
}

const Row& row_of(PlannerChoice::Kind kind) {
  for (const Row& r : rows())
    if (r.info.kind == kind) return r;
  throw std::logic_error("planner kind without a row in planner_choice.cpp");
}

}  // namespace

const std::vector<PlannerKindInfo>& planner_kinds() {
  static const std::vector<PlannerKindInfo> kInfos = [] {
    std::vector<PlannerKindInfo> out;
    for (const Row& r : rows()) out.push_back(r.info);
    return out;
  }();
  return kInfos;
}

const PlannerKindInfo& planner_kind_info(PlannerChoice::Kind kind) { return row_of(kind).info; }

std::string planner_names(const char* separator) {
  std::string out;
  for (const Row& r : rows()) out += (out.empty() ? "" : separator) + std::string(r.info.name);
  return out;
}

PlannerChoice::Kind parse_planner_kind(const std::string& name) {
  for (const Row& r : rows())
    if (name == r.info.name) return r.info.kind;
  throw std::invalid_argument("unknown planner '" + printable(name, 40) + "' (" + planner_names(", ") + ")");
}

void validate(const PlannerChoice& c) {
  const PlannerKindInfo& info = planner_kind_info(c.kind);
  if (!in_range(kPrmSamples, c.samples)) throw std::invalid_argument(param_error(kPrmSamples));
  if (info.tree && c.connector)
    throw std::invalid_argument(std::string(info.name) + " joins its trees by straight lines: no local connector");
  if (c.kind == PlannerChoice::Kind::LazyPrm && c.connector)
    throw std::invalid_argument("lazy-prm checks straight edges only when a path uses them: no local connector");
  if (info.tree && c.sampler.kind != SamplerSpec::Kind::Uniform)
    throw std::invalid_argument(std::string(info.name) + " samples uniformly: the sampler " + c.sampler.name() + " is PRM's");
  if (!in_range(kGoalBias, c.goal_bias)) throw std::invalid_argument(param_error(kGoalBias));
  if (!in_range(kTreeStep, c.step)) throw std::invalid_argument(param_error(kTreeStep));
}

TreeParams tree_params(const PlannerChoice& c) {
  TreeParams p;
  p.samples = c.samples;
  p.goal_bias = c.goal_bias;
  p.step = c.step;
  p.checker = c.checker;
  p.seed = c.seed;
  return p;
}

PlannerFactory make_planner_factory(const PlannerChoice& choice) {
  validate(choice);
  return row_of(choice.kind).make(choice);
}

}  // namespace csl
