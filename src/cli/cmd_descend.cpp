// cspacelab descend: gradient descent on the potential field, with random-walk escapes from
// local minima (homework section 2.4; the stepper of core/fields/descent.hpp run to its end).
#include "cli/commands.hpp"
#include "cli/potential_options.hpp"
#include "core/fields/descent.hpp"

namespace csl::cli {
namespace {

using json = nlohmann::json;

constexpr long long kMaxDescentSteps = 100000;  // the trajectory is printed: keep it printable

int run_descend(Args& args, std::ostream& os) {
  const auto from = args.take("from");
  const auto to = args.take("to");
  const PotentialParams field_params = take_potential_options(args);
  DescentParams d;
  d.step = take_param(args, kDescentStep);
  d.tolerance = take_number(args, "tolerance", d.tolerance, false);
  d.walk_step = take_number(args, "walk-step", d.walk_step, true);
  if (const auto v = args.take("max-steps")) d.max_steps = static_cast<int>(parse_count(*v, "--max-steps", kMaxDescentSteps));
  d.escapes = static_cast<int>(take_param(args, kDescentEscapes));
  if (const auto v = args.take("walk-steps")) d.walk_steps = static_cast<int>(parse_count(*v, "--walk-steps", 10000, 1));
  if (const auto v = args.take("window")) d.window = static_cast<int>(parse_count(*v, "--window", 10000, 1));
  if (const auto v = args.take("seed")) d.seed = static_cast<std::uint64_t>(parse_count(*v, "--seed", 9007199254740991LL));
  const bool events = args.take_flag("events");
  const std::string path = args.take_positional("SCENE.json");
  args.finish();

  const Scene scene = load_scene(path);
  const Config start = from ? parse_config(*from, scene, "--from") : scene.start;
  const Config goal = to ? parse_config(*to, scene, "--to") : scene.goal;
  const CollisionWorld world(scene);
  require_free(world, start, "the start");
  require_free(world, goal, "the goal");
  const PotentialField field(world, goal, field_params);
  Descent descent(field, start, d);

  json event_list = json::array();
  while (!descent.done()) {
    const DescentEvent& e = descent.step();
    if (!events) continue;
    json item{{"step", e.step}, {"kind", descent_event_name(e.kind)}, {"q", config_to_json(e.q)},
              {"U", e.U}, {"force", e.force}};
    if (e.kind == DescentEvent::Kind::Descend) item["halvings"] = e.halvings;
    if (e.blocked) item["blocked"] = true;
    event_list.push_back(item);
  }
  json trajectory = json::array();
  for (const Config& q : descent.trajectory()) trajectory.push_back(config_to_json(q));
  json out{{"outcome", outcome_name(descent.outcome())},
           {"trajectory", trajectory},
           {"from", config_to_json(start)},
           {"to", config_to_json(goal)},
           {"final", config_to_json(descent.q())},
           {"distance_to_goal", descent.distance_to_goal()},
           {"U", descent.potential()},
           {"force", descent.force()},
           {"steps", descent.steps()},
           {"descent_steps", descent.descent_steps()},
           {"walk_steps", descent.walk_steps()},
           {"escapes_used", descent.escapes_used()},
           {"local_minima", descent.local_minima()},
           {"evaluations", descent.evaluations()},
           {"params", potential_params_json(field_params)},
           {"descent",
            {{"step", d.step},
             {"tolerance", d.tolerance},
             {"max_steps", d.max_steps},
             {"window", d.window},
             {"escapes", d.escapes},
             {"walk_steps", d.walk_steps},
             {"walk_step", d.walk_step},
             {"seed", d.seed}}}};
  if (events) out["events"] = event_list;
  print_json(os, out);
  return 0;
}

}  // namespace

const Command kDescendCommand{
    "descend", "gradient descent on the potential field, with random-walk escapes from local minima",
    "Usage: cspacelab descend SCENE.json [--from Q] [--to Q] [--step A] [--tolerance T]\n"
    "                         [--max-steps N] [--escapes K] [--walk-steps L] [--walk-step V]\n"
    "                         [--window W] [--seed S] [--zeta Z] [--switch D] [--eta E]\n"
    "                         [--rho0 R] [--events]\n\n"
    "Descends the potential field toward --to (default: the scene's goal) from --from (default:\n"
    "the scene's start). Q is comma-separated numbers: x,y (point), theta1,theta2 (arm2; an\n"
    "N-link arm: N angles), x,y,theta (polygon).\n\n"
    "Each descent step moves a distance A (default 0.01; less within A of the goal) in the\n"
    "configuration space's metric along its steepest-descent direction of U: tau / |tau| for\n"
    "the point and the arm (tau = sum J^T F, the configuration-space force), for the polygon\n"
    "the torque divided by R^2 (R = the robot's radius, the angle's weight in the metric).\n"
    "A step is taken only if the straight piece to it is proven free (exact bisection check);\n"
    "otherwise it is halved, at most 6 times; a step that stays blocked means a local minimum.\n"
    "It stops at the goal (within T, default 0.01), after N motion steps (default 2000, at most\n"
    "100000), or in a local minimum: |tau| <= 1e-9, or the last W descent steps (default 20)\n"
    "moved q less than 2 A in all. With escapes left (K, default 0: plain descent; at most\n"
    "10000) a local minimum starts a random walk of L steps (default 40), each adding to every\n"
    "coordinate a number uniform in [-V, V] (default 0.1; the polygon's angle: [-V/R, V/R]),\n"
    "seeded by S (default 1), redrawn if blocked; then the descent resumes.\n\n" +
    potential_options_help() +
    "\nOutput: {\"outcome\": \"goal\" (reached without random walks) | \"escaped\" (reached after\n"
    "  one or more) | \"local_minimum\" (stuck, no escapes left) | \"max_steps\",\n"
    "  \"trajectory\": [Q, ...] (from the start, every configuration moved to; each straight\n"
    "  piece is free), \"from\", \"to\", \"final\", \"distance_to_goal\", \"U\" and \"force\" (|tau|) at\n"
    "  the end, \"steps\" (all steps: moves and decisions), \"descent_steps\", \"walk_steps\",\n"
    "  \"escapes_used\", \"local_minima\", \"evaluations\", \"params\", \"descent\": the settings}\n"
    "With --events also \"events\": [{\"step\", \"kind\" (descend, random_walk, reached_goal,\n"
    "  local_minimum, gave_up), \"q\", \"U\", \"force\", \"halvings\", \"blocked\"}, ...].\n"
    "A start or goal in collision is an error (exit status 2) naming the obstacle.\n",
    run_descend};

}  // namespace csl::cli
