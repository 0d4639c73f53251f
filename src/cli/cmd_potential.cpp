// cspacelab potential: the artificial potential field at one configuration, control point by
// control point, and its configuration-space force (homework P13).
#include <string>

#include "cli/commands.hpp"
#include "cli/potential_options.hpp"

namespace csl::cli {
namespace {

using json = nlohmann::json;

json distance_json(const ObstacleDistance& d) {
  return {{"rho", d.rho}, {"grad_rho", vec2_json(d.grad)}, {"nearest_point", vec2_json(d.nearest)}, {"inside", d.inside}};
}

json jacobian_json(const PointJacobian& j) {
  json rows = json::array();
  for (int r = 0; r < 2; ++r) {
    json row = json::array();
    for (Eigen::Index c = 0; c < j.cols(); ++c) row.push_back(j(r, c));
    rows.push_back(row);
  }
  return rows;
}

// tau under the names of the robot's coordinates: forces and a torque, or joint torques.
json named_generalized_force(const Robot& robot, const Config& tau) {
  if (std::holds_alternative<ArmRobot>(robot)) return {{"torques", config_to_json(tau)}};
  json out{{"force", json::array({tau[0], tau[1]})}};
  if (std::holds_alternative<PolygonRobot>(robot)) out["torque"] = tau[2];
  return out;
}

int run_potential(Args& args, std::ostream& os) {
  const auto at = args.take("at");
  const auto goal_text = args.take("goal");
  const PotentialParams params = take_potential_options(args);
  const std::string path = args.take_positional("SCENE.json");
  args.finish();
  if (!at) throw UsageError("missing --at Q (the configuration to evaluate the field at)");

  const Scene scene = load_scene(path);
  const Config q = parse_config(*at, scene, "--at");
  const Config goal = goal_text ? parse_config(*goal_text, scene, "--goal") : scene.goal;
  const CollisionWorld world(scene);
  const PotentialField field(world, goal, params);
  const PotentialReport r = field.evaluate(q);

  json points = json::array();
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const ControlPointReport& p = r.points[i];
    json terms = json::array();
    for (const RepulsiveTerm& t : p.terms) {
      json term = distance_json(t.distance);
      term["obstacle"] = t.obstacle;
      term["U"] = t.field.U;
      term["F"] = vec2_json(t.field.F);
      terms.push_back(term);
    }
    json point{{"name", control_point_name(scene.robot, static_cast<int>(i))},
               {"position", vec2_json(p.position)},
               {"goal_position", vec2_json(p.goal)},
               {"nearest_obstacle", p.nearest_obstacle >= 0 ? json(p.nearest_obstacle) : json(nullptr)}};
    if (p.nearest_obstacle >= 0) {
      point.update(distance_json(p.nearest));
      point["obstacle_type"] = obstacle_type_name(world.obstacles()[static_cast<std::size_t>(p.nearest_obstacle)]);
    } else {
      point.update({{"rho", nullptr}, {"grad_rho", nullptr}, {"nearest_point", nullptr}, {"inside", false}});
    }
    point.update({{"U_att", p.attractive.U},
                  {"F_att", vec2_json(p.attractive.F)},
                  {"U_rep", p.repulsive.U},
                  {"F_rep", vec2_json(p.repulsive.F)},
                  {"repulsive", terms},
                  {"jacobian", jacobian_json(p.jacobian)},
                  {"tau", config_to_json(p.tau)}});
    points.push_back(point);
  }
  json generalized = named_generalized_force(scene.robot, r.tau);
  generalized["tau"] = config_to_json(r.tau);
  generalized["tau_att"] = config_to_json(r.tau_att);
  generalized["tau_rep"] = config_to_json(r.tau_rep);
  print_json(os, {{"robot", robot_type_name(scene.robot)},
                  {"q", config_to_json(q)},
                  {"goal", config_to_json(goal)},
                  {"params", potential_params_json(params)},
                  {"in_collision", !world.is_free(q)},
                  {"contact", r.contact},
                  {"control_points", points},
                  {"totals",
                   {{"U_att", r.U_att},
                    {"U_rep", r.U_rep},
                    {"U", r.U},
                    {"F_att", vec2_json(r.F_att)},
                    {"F_rep", vec2_json(r.F_rep)},
                    {"F", vec2_json(r.F)}}},
                  {"generalized_force", generalized}});
  return 0;
}

}  // namespace

const Command kPotentialCommand{
    "potential", "the artificial potential field at a configuration: forces per control point, tau = J^T F",
    "Usage: cspacelab potential SCENE.json --at Q [--goal Q] [--zeta Z] [--switch D]\n"
    "                           [--eta E] [--rho0 R]\n\n"
    "Evaluates the potential field toward --goal (default: the scene's goal) at --at Q,\n"
    "control point by control point (homework P13). Q is comma-separated numbers: x,y\n"
    "(point), theta1,theta2 (arm2, radians, theta2 relative to link 1; an N-link arm: N angles),\n"
    "x,y,theta (polygon).\n\n" +
    potential_options_help() +
    "\nWhere rho has no gradient: on or inside an obstacle rho = 0 and grad rho points the\n"
    "quickest way out (on the boundary: the outward normal; a wall: its left normal; a disk's\n"
    "centre: +x); on a concave polygon's medial axis, the nearest point of the lowest-index\n"
    "edge. On or inside an obstacle U is infinite: such numbers print as null.\n\n"
    "Output: {\"robot\", \"q\", \"goal\", \"params\": {zeta, switch, eta, rho0},\n"
    "  \"in_collision\": bool, \"contact\": bool (a control point on or inside an obstacle),\n"
    "  \"control_points\": [{\"name\", \"position\", \"goal_position\",\n"
    "     \"nearest_obstacle\": index|null, \"obstacle_type\", \"rho\", \"grad_rho\", \"nearest_point\",\n"
    "     \"inside\", \"U_att\", \"F_att\", \"U_rep\", \"F_rep\" (summed over obstacles within rho0),\n"
    "     \"repulsive\": [{\"obstacle\", \"rho\", \"grad_rho\", \"nearest_point\", \"inside\", \"U\", \"F\"}],\n"
    "     \"jacobian\": [[...], [...]] (d position / d q), \"tau\": J^T (F_att + F_rep)}],\n"
    "  \"totals\": {\"U_att\", \"U_rep\", \"U\", \"F_att\", \"F_rep\", \"F\"} (workspace sums),\n"
    "  \"generalized_force\": {\"tau\", \"tau_att\", \"tau_rep\": sum J^T F, and by name:\n"
    "     point \"force\"; polygon \"force\" [Fx, Fy] and \"torque\" about (x, y);\n"
    "     arm2 \"torques\" [tau1, tau2]}}\n",
    run_potential};

}  // namespace csl::cli
