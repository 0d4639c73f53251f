#include "cli/potential_options.hpp"

namespace csl::cli {

double take_number(Args& args, const std::string& name, double fallback, bool positive) {
  const auto text = args.take(name);
  if (!text) return fallback;
  const double v = parse_number(*text, "--" + name);
  if (positive ? !(v > 0.0) : !(v >= 0.0))
    throw UsageError("--" + name + ": must be " + (positive ? "> 0" : ">= 0") + ", got " + *text);
  return v;
}

PotentialParams take_potential_options(Args& args) {
  PotentialParams p;
  p.rho0 = take_number(args, "rho0", p.rho0, true);
  p.zeta = take_number(args, "zeta", p.zeta, false);
  p.eta = take_number(args, "eta", p.eta, false);
  p.switch_distance = take_number(args, "switch", p.switch_distance, true);
  return p;
}

nlohmann::json potential_params_json(const PotentialParams& p) {
  return {{"zeta", p.zeta}, {"switch", p.switch_distance}, {"eta", p.eta}, {"rho0", p.rho0}};
}

nlohmann::json vec2_json(const Vec2& v) { return nlohmann::json::array({v.x(), v.y()}); }

}  // namespace csl::cli
