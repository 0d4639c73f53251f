// cspacelab validate SCENE.json: parse and validate a scene, print it normalised.
#include "cli/commands.hpp"

namespace csl::cli {
namespace {

int run_validate(Args& args, std::ostream& os) {
  const std::string path = args.take_positional("SCENE.json");
  args.finish();
  print_json(os, {{"valid", true}, {"scene", scene_to_json(load_scene(path))}});
  return 0;
}

}  // namespace

const Command kValidateCommand{
    "validate", "check a scene file and print it in normal form",
    "Usage: cspacelab validate SCENE.json\n\n"
    "Parses and validates SCENE.json (schema version 1). On success prints\n"
    "  {\"valid\": true, \"scene\": {...normalised scene...}}\n"
    "On failure prints one line naming the offending field and exits with status 2.\n\n"
    "Scene schema (version 1):\n"
    "  { \"version\": 1, \"name\": \"optional title\",\n"
    "    \"workspace\": { \"min\": [0, 0], \"max\": [1, 1] },\n"
    "    \"robot\": { \"type\": \"point\" }\n"
    "           | { \"type\": \"arm2\", \"base\": [x, y], \"lengths\": [l1, l2] }\n"
    "           | { \"type\": \"arm\", \"base\": [x, y], \"lengths\": [l1, ..., lN] }   (1 <= N <= 6)\n"
    "           | { \"type\": \"polygon\", \"vertices\": [[x, y], ...] }   (robot frame)\n"
    "    \"obstacles\": [ { \"type\": \"disk\", \"center\": [x, y], \"radius\": r },\n"
    "                   { \"type\": \"polygon\", \"vertices\": [[x, y], ...] },\n"
    "                   { \"type\": \"segment\", \"a\": [x, y], \"b\": [x, y] } ],\n"
    "    \"start\": q, \"goal\": q }\n"
    "q is [x, y] (point), [theta1, theta2] in radians with theta2 relative to link 1 (arm2),\n"
    "[theta1, ..., thetaN] each relative to the link before (arm: Q = T^N; a 2-link \"arm\" is\n"
    "the arm2 and is written back as one), or [x, y, theta] (polygon). Segments are walls of zero thickness; a robot within 1e-6\n"
    "of one collides. Limits: 1000 obstacles, 256 vertices per polygon (32 for the robot),\n"
    "|coordinates| <= 1e6, 64 MB of JSON.\n"
    "Only \"version\" is required; the rest default to: no name, the workspace [0,1]^2, the\n"
    "point robot, no obstacles, start and goal at the workspace's min and max corners (angle 0\n"
    "for the polygon robot; the arm: start all 0, goal the same with theta1 = pi/2). The normalised scene spells\n"
    "them all out. A key given twice counts once, the last.\n",
    run_validate};

}  // namespace csl::cli
