#pragma once
// Options and JSON shared by the potential-field commands (potential, descend).
#include <nlohmann/json.hpp>

#include "cli/args.hpp"
#include "core/fields/potential.hpp"

namespace csl::cli {

/// [--rho0 R] [--zeta Z] [--eta E] [--switch D], defaults those of PotentialParams; UsageError
/// naming the option for a value out of range.
PotentialParams take_potential_options(Args& args);
/// A number option: `fallback` if absent; UsageError unless > 0 (`positive`) or >= 0.
double take_number(Args& args, const std::string& name, double fallback, bool positive);
/// The field's constants as {"zeta", "switch", "eta", "rho0"}.
nlohmann::json potential_params_json(const PotentialParams& p);
/// [x, y]; non-finite coordinates print as null.
nlohmann::json vec2_json(const Vec2& v);

/// Help text for the field and its four options, shared by both commands' usage: the option
/// lines from their specs (core/base/params.hpp), so that the ranges are the ones parsed.
std::string potential_options_help();

}  // namespace csl::cli
