// cspacelab cspace-of "DESCRIPTION" [--check ANSWER]: a robot's configuration space in the
// course's notation, and optionally a verdict on a written answer.
#include <nlohmann/json.hpp>
#include <optional>

#include "cli/commands.hpp"
#include "core/teaching/notation.hpp"

namespace csl::cli {
namespace {

int run_cspace_of(Args& args, std::ostream& os) {
  // --check first: take_positional would otherwise be free to grab its value.
  const std::optional<std::string> answer = args.take("check");
  const std::string description = args.take_positional("DESCRIPTION (e.g. \"joints=RRR\")");
  args.finish();

  RobotDescription robot;
  ConfigSpaceInfo info;
  try {
    robot = parse_robot_description(description);
    info = configuration_space(robot);
  } catch (const NotationError& e) {
    throw UsageError(std::string("bad robot description: ") + e.what());
  }

  // ordered_json keeps the keys in reading order: notation first, check last.
  using json = nlohmann::ordered_json;
  json factors = json::array();
  for (const NotationFactor& f : info.factors)
    factors.push_back({{"factor", f.notation}, {"dimension", f.dimension}, {"reason", f.reason}});
  json out = {{"notation", info.notation},
              {"dimension", info.dimension},
              {"factors", factors},
              {"equivalent", info.equivalent}};
  if (answer) {
    const AnswerCheck check = check_answer(*answer, robot);
    out["check"] = {{"correct", check.correct}, {"explanation", check.explanation}};
  }
  // Explanations may quote the answer, which may not be valid UTF-8: replace, do not fail.
  // (Not print_json: that takes a json, which would sort this ordered_json's keys.)
  os << out.dump(-1, ' ', false, json::error_handler_t::replace) << "\n";
  return 0;
}

}  // namespace

const Command kCspaceOfCommand{
    "cspace-of", "the configuration space Q of a described robot, in the course's notation",
    "Usage: cspacelab cspace-of \"DESCRIPTION\" [--check \"ANSWER\"]\n\n"
    "Prints the configuration space Q of the described robot:\n"
    "  {\"notation\": \"SE(2) x T^6\", \"dimension\": 9,\n"
    "   \"factors\": [{\"factor\": \"SE(2)\", \"dimension\": 3, \"reason\": \"...\"}, ...],\n"
    "   \"equivalent\": [\"R^2 x S^1 x T^6\", \"R^2 x T^7\", ...]}\n"
    "Canonical order: the base, then all revolute joints as one torus, then the\n"
    "prismatic joints.\n\n"
    "DESCRIPTION is key=value words separated by spaces or commas (quote it):\n"
    "  base=fixed|planar-translating|planar|spatial-translating|spatial   (default fixed)\n"
    "        planar: slides and turns in the plane (SE(2)); spatial: moves and turns\n"
    "        freely in space (SE(3)); *-translating: slides, never turns (R^2, R^3)\n"
    "  joints=RRP            joint letters from base to tip: R revolute, P prismatic\n"
    "                        (default none)\n"
    "  wrist=spherical|none  a spherical wrist is three more revolute joints\n"
    "                        (default none)\n\n"
    "--check \"ANSWER\" also judges a written answer and adds\n"
    "  \"check\": {\"correct\": true|false, \"explanation\": \"...\"}\n"
    "ANSWER may start with \"Q =\", use x, × or * between factors, and the factors\n"
    "R, R^n (or R²), S^1, S^2, T^n, SO(2), SO(3), SE(2), SE(3) and (...)^n.\n\n"
    "Examples:\n"
    "  cspacelab cspace-of \"base=planar\"                      # SE(2)\n"
    "  cspacelab cspace-of \"joints=RRP\"                       # T^2 x R\n"
    "  cspacelab cspace-of \"joints=RRR wrist=spherical\"       # T^6\n"
    "  cspacelab cspace-of \"base=planar, joints=RRR, wrist=spherical\" --check \"R^2 x T^7\"\n\n"
    "A bad DESCRIPTION is a one-line error with exit status 2; an unreadable ANSWER is\n"
    "reported in \"check\" as incorrect, saying what could not be read.\n",
    run_cspace_of};

}  // namespace csl::cli
