#pragma once
// The JSON form of an edge check, shared by the CLI (cspacelab check --trace) and the app's
// API, so both report the very same structure.
#include <nlohmann/json.hpp>

#include "core/checking/edge_check.hpp"

namespace csl {

/// {"collision", "evaluations", "collision_t" (number|null), "checker"} and, with a trace,
/// "trace": one entry per configuration evaluated ({"t", "q", "eta", "free"}, plus "t0", "t1",
/// "lambda", "depth" for bisection) and, for bisection, "pieces": the certified or unresolved
/// pieces ({"t0", "t1", "lambda", "eta0", "eta1", "depth", "unresolved"}).
nlohmann::json edge_check_to_json(const EdgeCheckResult& result, const EdgeCheckerSpec& spec, bool with_trace);

}  // namespace csl
