// cspacelab validate SCENE.json: parse and validate a scene, print it normalised.
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "core/scene.hpp"

namespace csl::cli {
namespace {

int run_validate(Args& args) {
  const std::string path = args.take_positional("SCENE.json");
  args.finish();
  try {
    Scene scene = scene_from_string(read_file(path));
    std::cout << nlohmann::json{{"valid", true}, {"scene", scene_to_json(scene)}}.dump() << "\n";
  } catch (const SceneError& e) {
    throw UsageError(path + ": " + e.what());
  }
  return 0;
}

}  // namespace

const Command kValidateCommand{
    "validate", "check a scene file and print it in normal form",
    "Usage: cspacelab validate SCENE.json\n\n"
    "Parses and validates SCENE.json (schema version 1). On success prints\n"
    "  {\"valid\": true, \"scene\": {...normalised scene...}}\n"
    "On failure prints one line naming the offending field and exits with status 2.\n",
    run_validate};

}  // namespace csl::cli
