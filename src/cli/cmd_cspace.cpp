// cspacelab cspace: the exact C-space map of a scene's 2-link arm, written as a binary PGM.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "core/teaching/cspace_map.hpp"

namespace csl::cli {
namespace {

int run_cspace(Args& args, std::ostream& os) {
  const auto resolution_text = args.take("resolution");
  const auto out = args.take("out");
  const std::string path = args.take_positional("SCENE.json");
  args.finish();
  if (!out) throw UsageError("missing --out FILE.pgm");
  const std::string text = resolution_text.value_or("512");
  const int resolution = static_cast<int>(parse_count(text, "--resolution", 8192, 1));

  const Scene scene = load_scene(path);
  const auto* arm = std::get_if<ArmRobot>(&scene.robot);
  if (!arm || arm->links() != 2)
    throw UsageError(path + ": the C-space map needs an arm2 robot, the scene's robot is '" +
                     robot_type_name(scene.robot) + "'" +
                     (arm ? " with " + std::to_string(arm->links()) + " links (the map is of T^2)" : ""));

  // The computation alone is timed: building the map and rasterising it, not the file.
  std::vector<std::uint8_t> pixels;
  const auto start = std::chrono::steady_clock::now();
  const ArmCSpaceMap map(*arm, scene.obstacles);
  const double free_fraction = map.rasterize(resolution, pixels);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::ofstream file(*out, std::ios::binary | std::ios::trunc);
  if (!file) throw UsageError(*out + ": cannot write file");
  file << "P5\n" << resolution << " " << resolution << "\n255\n";
  file.write(reinterpret_cast<const char*>(pixels.data()), static_cast<std::streamsize>(pixels.size()));
  file.close();
  if (!file) throw UsageError(*out + ": write error");

  print_json(os, {{"free_fraction", free_fraction}, {"seconds", seconds}});
  return 0;
}

}  // namespace

const Command kCspaceCommand{
    "cspace", "the exact C-space map of a 2-link arm scene, as a PGM image",
    "Usage: cspacelab cspace SCENE.json --out FILE.pgm [--resolution R]\n\n"
    "Computes the C-obstacle region of the scene's arm2 robot in T^2 = [-pi, pi)^2 exactly\n"
    "(closed-form angle intervals per obstacle: link 1's blocked theta1, then for each theta1\n"
    "link 2's blocked theta2; where link 1 collides the whole column is blocked) and samples it\n"
    "at R x R pixel centres (R in [1, 8192], default 512). A pixel is in the C-obstacle exactly\n"
    "when the arm there touches an obstacle (obstacles are closed; walls count within 1e-6).\n\n"
    "FILE.pgm is a binary PGM: the header \"P5\\nR R\\n255\\n\", then R rows of R bytes,\n"
    "255 = free, 0 = C-obstacle. Column i (left to right) is theta1 = -pi + (i + 1/2) 2pi/R,\n"
    "row j (first row first) is theta2 = -pi + (j + 1/2) 2pi/R; theta2 is measured relative\n"
    "to link 1 (link 2's absolute angle is theta1 + theta2).\n\n"
    "Output:\n"
    "  {\"free_fraction\": x, \"seconds\": t}\n"
    "  free_fraction: the fraction of pixels that are free (255); seconds: the time to build\n"
    "  the map and rasterise it (not to read the scene or write the file).\n\n"
    "A scene whose robot is not arm2, a bad R or an unwritable FILE is a one-line error with\n"
    "exit status 2.\n",
    run_cspace};

}  // namespace csl::cli
