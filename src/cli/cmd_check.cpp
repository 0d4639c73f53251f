// cspacelab check: one straight-line edge through either checker, with its trace; or the
// smallest grid resolution that sees the collision (homework P12).
#include <algorithm>
#include <stdexcept>

#include "cli/commands.hpp"
#include "core/checking/edge_check_json.hpp"

namespace csl::cli {
namespace {

using json = nlohmann::json;

int run_check(Args& args, std::ostream& os) {
  const auto from = args.take("from");
  const auto to = args.take("to");
  const auto checker_text = args.take("checker");
  const bool trace = args.take_flag("trace");
  const bool min_grid = args.take_flag("min-grid");
  const auto max_text = args.take("max");
  const auto max_work_text = args.take("max-work");
  const std::string path = args.take_positional("SCENE.json");
  args.finish();

  const Scene scene = load_scene(path);
  const Config p = from ? parse_config(*from, scene, "--from") : scene.start;
  const Config q = to ? parse_config(*to, scene, "--to") : scene.goal;
  const CollisionWorld world(scene);
  const double max_work = max_work_text ? parse_max_work(*max_work_text, "--max-work") : kCliMaxWork;

  if (min_grid) {
    if (checker_text || trace) throw UsageError("--min-grid takes neither --checker nor --trace");
    const int max_n = static_cast<int>(max_text ? parse_param(*max_text, kMinGridMax) : kMinGridMax.def);
    const auto limit = static_cast<long long>(std::min(1e15, max_work / world.evaluation_cost()));
    const MinGridResult r = min_grid_search(world, p, q, max_n, std::max(2LL, limit));
    if (r.exhausted)
      throw UsageError("--min-grid: gave up after " + std::to_string(r.evaluations) + " configurations (" +
                       work_text(max_work) + " of work, --max-work) without finding N; the edge grazes an "
                       "obstacle, or take a smaller --max");
    print_json(os, {{"min_grid", r.n ? json(*r.n) : json(nullptr)}, {"max", max_n}, {"evaluations", r.evaluations}});
    return 0;
  }
  if (max_text) throw UsageError("--max only goes with --min-grid");

  EdgeCheckerSpec spec;
  try {
    spec = EdgeCheckerSpec::parse(checker_text.value_or("bisection"));
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--checker: ") + e.what());
  }
  // The collision lesson's grid_n lists its configurations too: one limit for both traces.
  const std::string most = param_value_text(kTracedGridN, kTracedGridN.max);
  if (spec.kind == EdgeCheckerSpec::Kind::Grid && trace && spec.resolution > kTracedGridN.max)
    throw UsageError("--trace: at most grid:" + most + " (the trace would be too long)");
  if (spec.kind == EdgeCheckerSpec::Kind::Step && trace && world.space().distance(p, q) / spec.step > kTracedGridN.max)
    throw UsageError("--trace: at most " + most + " configurations (the trace would be too long)");

  if (const double work = expected_check_work(world, spec, p, q); work > max_work)
    throw UsageError("--checker " + spec.name() + ": this edge means about " + work_text(work) +
                     " of work in this scene, more than the " + work_text(max_work) + " a check may take (--max-work)");
  const EdgeCheckResult r = check_edge(world, spec, p, q, trace);
  json out = edge_check_to_json(r, spec, trace);
  out["from"] = config_to_json(p);
  out["to"] = config_to_json(q);
  print_json(os, out);
  return 0;
}

}  // namespace

const Command kCheckCommand{
    "check", "check one straight-line edge (grid:N, step:D or bisection), or the minimum grid N",
    "Usage: cspacelab check SCENE.json [--from Q] [--to Q] [--checker bisection|grid:N|step:D] [--trace]\n"
    "       cspacelab check SCENE.json [--from Q] [--to Q] --min-grid [--max M]\n"
    "       (either form also takes --max-work W)\n\n" +
    option_help(kMinGridMax, "M") + "\n"
    "Checks the straight line from --from to --to in configuration space (default: the\n"
    "scene's start and goal; angles take the shorter way round). Q is comma-separated numbers:\n"
    "x,y (point robot), theta1,theta2 (arm2, radians; an N-link arm: N angles), x,y,theta\n"
    "(polygon robot).\n\n"
    "Checkers:\n"
    "  grid:N      the N >= 2 equally spaced configurations t = i/(N-1), both endpoints\n"
    "              included, in order; stops at the first in collision (may miss collisions)\n"
    "  step:D      the grid with N = max(2, ceil(|pq|/D) + 1): configurations at most D\n"
    "              apart in the configuration space's metric (N at most 1000000 an edge:\n"
    "              a D below |pq| / 999999 is then coarser than asked)\n"
    "  bisection   exact (Schwarzer, Saha, Latombe 2005): a piece [t0,t1] is free when\n"
    "              lambda < eta(t0) + eta(t1) (strictly, with room for rounding: obstacles are\n"
    "              closed, so a path that touches one collides), else its midpoint is tested;\n"
    "              endpoints first,\n"
    "              then pieces breadth first (coarse before fine, left before right).\n"
    "              (default)\n\n"
    "Output:\n"
    "  {\"collision\": bool, \"evaluations\": int, \"collision_t\": number|null,\n"
    "   \"checker\": \"...\", \"from\": Q, \"to\": Q, \"trace\": [...], \"pieces\": [...]}\n"
    "  trace (with --trace): one entry per configuration evaluated, in order:\n"
    "    {\"t\", \"q\", \"eta\" (clearance; <= 0 is a collision), \"free\"}, and for bisection\n"
    "    \"t0\", \"t1\", \"lambda\", \"depth\": the piece whose midpoint this is (for the two\n"
    "    endpoints t0 = t1 = t and lambda = 0)\n"
    "  pieces (bisection with --trace): the pieces proven free, in order:\n"
    "    {\"t0\", \"t1\", \"lambda\", \"eta0\", \"eta1\", \"depth\", \"unresolved\"}; unresolved = a\n"
    "    piece shorter than 1e-12, or one left after the check's evaluation limit (2^20, fewer\n"
    "    where one configuration costs more than 16 units: at most 2^24 units a check, and at\n"
    "    least 16 configurations), that could not be proven free (the edge grazes an obstacle or\n"
    "    runs along one): a collision\n\n"
    "With --min-grid: {\"min_grid\": N|null, \"max\": M, \"evaluations\": E}, the smallest N in\n"
    "[2, M] for which grid:N finds the collision; null at once\n"
    "when the exact (bisection) check proves the edge free. Grids are tried N = 2, 3, ..., but a\n"
    "configuration is only tested where those tested so far do not prove it free (their\n"
    "clearances' balls cover it): the answer of testing every grid in full, from about one\n"
    "configuration per N near each collision (E counts them, the bisection check's included).\n"
    "A check or search expected to take more than W units of work (default 1e11; see `cspacelab\n"
    "help plan`) is an error: --max-work raises the limit.\n",
    run_check};

}  // namespace csl::cli
