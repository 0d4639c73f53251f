#pragma once
// The planner's parameters as panel widgets, and as JSON for the API: n, the neighbour rule,
// the edge checker, the seed. Shared by every lesson that runs PRM.
#include <nlohmann/json.hpp>

#include <vector>

#include "app/shell/param_fields.hpp"

#include <string>

#include "app/shell/context.hpp"
#include "core/base/params.hpp"
#include "core/planning/prm.hpp"
#include "core/scene/scene.hpp"
#include "core/teaching/work.hpp"

namespace csl::app {

/// The largest r the lab allows with `samples` samples in `space` (infinite: any r).
double max_radius(const Space& space, int samples);
/// Lowers a radius rule's r to max_radius() (after n or the scene changed): true if it did.
bool keep_within_budget(PrmParams& params, const Space& space);

/// What is wrong with planning with `params` in `world` in the lab, or "": the budgets of
/// core/teaching/work.hpp, the same for the panel, links and the API. More candidate pairs than
/// kLabMaxPairs (a radius rule's r is kept within them; k up to 50, the slider's range, passes
/// at any n), or more work than kLabMaxWork (the samples, pairs and checker in this scene).
std::string prm_budget_problem(const PrmParams& params, const CollisionWorld& world);

/// prm_budget_problem() for `params` in a scene about to replace the lesson's (a radius rule's r
/// lowered first, as the lesson will), phrased for the scene: "with these parameters, this
/// scene means ...", or "".
std::string scene_budget_problem(PrmParams params, const Scene& scene);

/// Draws the controls for planning in `world`; returns true if `params` changed. A change past
/// the lab's budgets is undone, and the notice says why. `samples`: the lesson's budget for n
/// (kLabPrmSamples, or the torus's kLabTorusSamples). `with_sampler`: the sampler's choice too
/// (sampler_controls.hpp; Step PRM's, under the parameter "sampler"). `with_neighbors` false:
/// no neighbour rule (a planner that has none of its own: the trees, PRM*'s k(n)).
bool prm_controls(PrmParams& params, const CollisionWorld& world, LabContext& ctx,
                  const ParamSpec& samples = kLabPrmSamples, bool with_sampler = false, bool with_neighbors = true);

nlohmann::json prm_params_json(const PrmParams& params);
/// Applies {"samples", "neighbors", "checker", "seed"} (any subset) to a copy of `params` and
/// returns it; throws ApiError naming the bad field, so nothing changes on bad input. Refuses
/// what the panel cannot set either: `samples`' budget, prm_budget_problem(), a D under
/// kLabCheckerStepD's least.
PrmParams prm_params_from_json(const nlohmann::json& j, PrmParams params, const CollisionWorld& world,
                               const ParamSpec& samples = kLabPrmSamples);

/// Moves the four PRM keys (samples, neighbors, checker, seed) that `j` has out of it, into the
/// object returned (for prm_params_from_json): a lesson's set_params() reads the rest itself.
nlohmann::json take_prm_params(nlohmann::json& j);

/// The four PRM parameters for the page's controls: samples (the lesson's budget spec), the
/// neighbour rule and the checker (their syntax), the seed.
std::vector<ParamField> prm_param_fields(const ParamSpec& samples);

}  // namespace csl::app
