#pragma once
// The planner's parameters as panel widgets, and as JSON for the API: n, the neighbour rule,
// the edge checker, the seed. Shared by every lesson that runs PRM.
#include <nlohmann/json.hpp>

#include "core/prm.hpp"

namespace csl::app {

/// Draws the controls; returns true if `params` changed.
bool prm_controls(PrmParams& params, int max_samples = 20000);

nlohmann::json prm_params_json(const PrmParams& params);
/// Applies {"samples", "neighbors", "checker", "seed"} (any subset) to a copy of `params` and
/// returns it; throws ApiError naming the bad field, so nothing changes on bad input.
PrmParams prm_params_from_json(const nlohmann::json& j, PrmParams params, int max_samples = 20000);

}  // namespace csl::app
