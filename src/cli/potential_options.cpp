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
  p.rho0 = take_param(args, kFieldRho0);
  p.zeta = take_param(args, kFieldZeta);
  p.eta = take_param(args, kFieldEta);
  p.switch_distance = take_param(args, kFieldSwitch);
  return p;
}

nlohmann::json potential_params_json(const PotentialParams& p) {
  return {{"zeta", p.zeta}, {"switch", p.switch_distance}, {"eta", p.eta}, {"rho0", p.rho0}};
}

nlohmann::json vec2_json(const Vec2& v) { return nlohmann::json::array({v.x(), v.y()}); }

std::string potential_options_help() {
  return "Field (Spong, Hutchinson, Vidyasagar 2006, section 5.2; homework P13), at each control\n"
         "point (point robot: the point; arm2: elbow and tip; polygon: its vertices):\n"
         "  attractive, toward the control point's place at the goal, e = o(q) - o(q_goal):\n"
         "    U = 1/2 zeta |e|^2 for |e| <= d,  U = d zeta |e| - 1/2 zeta d^2 beyond;  F = -grad U\n"
         "  repulsive, from each obstacle within rho0 (rho = distance to it, grad rho = unit vector\n"
         "  away from its nearest point):\n"
         "    U = 1/2 eta (1/rho - 1/rho0)^2,  F = eta (1/rho - 1/rho0) (1/rho^2) grad rho\n" +
         option_help(kFieldZeta, "Z") + option_help(kFieldSwitch, "D") + option_help(kFieldEta, "E") +
         "                         (in a unit workspace the default push matches the largest pull,\n"
         "                         d zeta = 0.2, at rho ~ 0.06, and is 10 at rho = 0.02)\n" +
         option_help(kFieldRho0, "R");
}

}  // namespace csl::cli
