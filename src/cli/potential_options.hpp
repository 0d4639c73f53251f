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

}  // namespace csl::cli

/// Help text for the field and its four options, shared by both commands' usage (a macro so
/// that it joins their string literals: Command::usage is a plain const char*).
#define CSPACELAB_POTENTIAL_OPTIONS_HELP                                                           \
  "Field (Spong, Hutchinson, Vidyasagar 2006, section 5.2; homework P13), at each control\n"     \
  "point (point robot: the point; arm2: elbow and tip; polygon: its vertices):\n"                \
  "  attractive, toward the control point's place at the goal, e = o(q) - o(q_goal):\n"          \
  "    U = 1/2 zeta |e|^2 for |e| <= d,  U = d zeta |e| - 1/2 zeta d^2 beyond;  F = -grad U\n"   \
  "  repulsive, from each obstacle within rho0 (rho = distance to it, grad rho = unit vector\n"  \
  "  away from its nearest point):\n"                                                            \
  "    U = 1/2 eta (1/rho - 1/rho0)^2,  F = eta (1/rho - 1/rho0) (1/rho^2) grad rho\n"           \
  "  --zeta Z      attractive gain (default 1)\n"                                                \
  "  --switch D    d, where the attraction turns from quadratic to conic (default 0.2)\n"        \
  "  --eta E       repulsive gain (default 0.0001: in a unit workspace the push matches the\n"   \
  "                largest pull, d zeta = 0.2, at rho ~ 0.06, and is 10 at rho = 0.02)\n"       \
  "  --rho0 R      an obstacle's region of influence (default 0.1)\n"

namespace csl::cli {

}  // namespace csl::cli
