#pragma once
// The planner's parameters as panel widgets, and as JSON for the API: n, the neighbour rule,
// the edge checker, the seed. Shared by every lesson that runs PRM.
#include <nlohmann/json.hpp>

#include "core/prm.hpp"

namespace csl::app {

/// The most candidate pairs a roadmap in the lab may be expected to check: as many as k = 50
/// with the most samples. A radius rule's pairs grow with n^2 (radius 0.3 with 20000 samples:
/// 57 million pairs, minutes and gigabytes), so its r is kept where this bound allows.
inline constexpr double kMaxCandidatePairs = 1e6;
/// The largest r the lab allows with `samples` samples in `space` (infinite: any r).
double max_radius(const Space& space, int samples);
/// Lowers a radius rule's r to max_radius() (after n or the scene changed): true if it did.
bool keep_within_budget(PrmParams& params, const Space& space);

/// Draws the controls for planning in `space`; returns true if `params` changed.
bool prm_controls(PrmParams& params, const Space& space, int max_samples = 20000);

nlohmann::json prm_params_json(const PrmParams& params);
/// Applies {"samples", "neighbors", "checker", "seed"} (any subset) to a copy of `params` and
/// returns it; throws ApiError naming the bad field, so nothing changes on bad input. Refuses
/// what the panel cannot set either: more pairs than kMaxCandidatePairs, a step D under 0.001.
PrmParams prm_params_from_json(const nlohmann::json& j, PrmParams params, const Space& space, int max_samples = 20000);

}  // namespace csl::app
