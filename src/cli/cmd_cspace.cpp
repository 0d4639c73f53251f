// cspacelab cspace: the exact C-space of a scene's robot. The 2-link arm's T^2 as a binary PGM;
// the polygon robot's SE(2) and the 3-link arm's T^3 as a raw byte volume with a JSON header,
// or one exact slice of them as JSON (--slice).
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "core/base/angles.hpp"
#include "core/base/text.hpp"
#include "core/teaching/cspace_volume.hpp"

namespace csl::cli {
namespace {

// The largest 3-D volume written: 2^27 cells, 128 MiB (512^3; 1024 x 1024 x 128).
constexpr long long kMaxVolumeCells = 1LL << 27;
constexpr long long kMaxVolumeSide = 1024;
void write_bytes(const std::string& path, const std::string& header, const std::vector<std::uint8_t>& bytes) {
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (!file) throw UsageError(path + ": cannot write file");
  file << header;
  file.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  file.close();
  if (!file) throw UsageError(path + ": write error");
}

int run_arm2(const ArmRobot& arm, const Scene& scene, int resolution, const std::string& out, std::ostream& os) {
  // The computation alone is timed: building the map and rasterising it, not the file.
  std::vector<std::uint8_t> pixels;
  const auto start = std::chrono::steady_clock::now();
  const ArmCSpaceMap map(arm, scene.obstacles);
  const double free_fraction = map.rasterize(resolution, pixels);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_bytes(out, "P5\n" + std::to_string(resolution) + " " + std::to_string(resolution) + "\n255\n", pixels);
  print_json(os, {{"free_fraction", free_fraction}, {"seconds", seconds}});
  return 0;
}

nlohmann::ordered_json points_json(const Polygon& poly) {
  nlohmann::ordered_json a = nlohmann::ordered_json::array();
  for (const Vec2& p : poly) a.push_back({p.x(), p.y()});
  return a;
}

nlohmann::ordered_json angle_axis(const char* name, int cells) {
  return {{"name", name}, {"min", -kPi}, {"max", kPi}, {"cells", cells}, {"periodic", true}};
}

// One exact slice as JSON (the contract is in the help below).
nlohmann::ordered_json slice_json(const Scene& scene, double value, int resolution) {
  if (const auto* polygon = std::get_if<PolygonRobot>(&scene.robot)) {
    std::vector<RoundedPolygon> pieces;
    Se2CObstacles(*polygon, scene.obstacles).slice(value, pieces);
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const RoundedPolygon& p : pieces) {
      nlohmann::ordered_json piece = {{"obstacle", p.obstacle}, {"hull", points_json(p.hull)}, {"radius", p.radius}};
      if (p.radius > 0.0) piece["outline"] = points_json(rounded_polygon_outline(p, kPi / 16));
      list.push_back(piece);
    }
    return {{"robot", "polygon"},
            {"theta", value},
            {"bounds", {{"min", {scene.workspace_min.x(), scene.workspace_min.y()}},
                        {"max", {scene.workspace_max.x(), scene.workspace_max.y()}}}},
            {"pieces", list}};
  }
  const Arm3Slices::Slice s = Arm3Slices(std::get<ArmRobot>(scene.robot), scene.obstacles).slice(value);
  nlohmann::ordered_json columns = nlohmann::ordered_json::array();
  std::vector<AngleInterval> intervals;
  for (int i = 0; i < resolution; ++i) {
    const double theta2 = cspace_pixel_angle(i, resolution);
    s.blocked_theta3(theta2, intervals);
    nlohmann::ordered_json iv = nlohmann::ordered_json::array();
    for (const AngleInterval& a : intervals) iv.push_back({a.lo, a.hi});
    columns.push_back({{"theta2", theta2}, {"blocked_theta3", iv}});
  }
  return {{"robot", "arm"}, {"theta1", value}, {"link1_blocked", s.all_blocked()}, {"columns", columns}};
}

// Refused past kMaxVolumeWork with the figures (core/teaching/cspace_volume.hpp prices it).
void check_cspace_work(const Scene& scene, int resolution, int slices) {
  const VolumeWork w = cspace_volume_work(scene, resolution, slices);
  if (w.units > kMaxVolumeWork)
    throw UsageError(std::string(slices == 0 ? "the slice's" : "the volume's") + " work is " + w.text + " = " +
                     significant(w.units) + ", more than the limit of " + significant(kMaxVolumeWork) + ": lower " +
                     (slices == 0 ? "--resolution or simplify the scene" : "--resolution or --slices"));
}

int run_volume(const Scene& scene, int resolution, int slices, const std::string& out, std::ostream& os) {
  const bool is_se2 = std::holds_alternative<PolygonRobot>(scene.robot);
  const auto start = std::chrono::steady_clock::now();
  CSpaceVolume volume;
  nlohmann::ordered_json axes;
  if (is_se2) {
    volume = se2_volume(Se2CObstacles(std::get<PolygonRobot>(scene.robot), scene.obstacles), scene.workspace_min,
                        scene.workspace_max, resolution, resolution, slices);
    const auto box_axis = [&](const char* name, double lo, double hi) {
      return nlohmann::ordered_json{{"name", name}, {"min", lo}, {"max", hi}, {"cells", resolution}, {"periodic", false}};
    };
    axes = {box_axis("x", scene.workspace_min.x(), scene.workspace_max.x()),
            box_axis("y", scene.workspace_min.y(), scene.workspace_max.y()), angle_axis("theta", slices)};
  } else {
    volume = arm3_volume(Arm3Slices(std::get<ArmRobot>(scene.robot), scene.obstacles), resolution, slices);
    axes = {angle_axis("theta2", resolution), angle_axis("theta3", resolution), angle_axis("theta1", slices)};
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::size_t slash = out.find_last_of('/');
  const nlohmann::ordered_json header = {{"format", "cspacelab-volume"},
                                         {"version", 1},
                                         {"robot", is_se2 ? "polygon" : "arm"},
                                         {"data", slash == std::string::npos ? out : out.substr(slash + 1)},
                                         {"dims", {volume.nx, volume.ny, volume.nz}},
                                         {"axes", axes},
                                         {"free", 255},
                                         {"blocked", 0},
                                         {"free_fraction", volume.free_fraction}};
  write_bytes(out, "", volume.cells);
  write_bytes(out + ".json", header.dump(2) + "\n", {});
  nlohmann::ordered_json result = header;
  result["header"] = out + ".json";
  result["seconds"] = seconds;
  os << result.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  return 0;
}

int run_cspace(Args& args, std::ostream& os) {
  const auto resolution_text = args.take("resolution");
  const auto slices_text = args.take("slices");
  const auto slice_text = args.take("slice");
  const auto out = args.take("out");
  const std::string path = args.take_positional("SCENE.json");
  args.finish();
  if (!out && !slice_text) throw UsageError("missing --out FILE (or --slice AXIS=VALUE)");
  if (out && slice_text) throw UsageError("--slice prints one slice as JSON: give --out or --slice, not both");

  const Scene scene = load_scene(path);
  const auto* arm = std::get_if<ArmRobot>(&scene.robot);
  const bool is_se2 = std::holds_alternative<PolygonRobot>(scene.robot);
  if (!(is_se2 || (arm && (arm->links() == 2 || arm->links() == 3))))
    throw UsageError(path + ": the C-space map needs an arm2 robot, a 3-link arm or a polygon robot, the scene's robot is '" +
                     robot_type_name(scene.robot) + "'" + (arm ? " with " + std::to_string(arm->links()) + " links" : ""));

  if (arm && arm->links() == 2) {
    if (slices_text) throw UsageError("--slices: the arm2 map is 2-D (T^2), it has no slices");
    if (slice_text) throw UsageError("--slice: the arm2 map is 2-D (T^2); --slice is for polygon robots and 3-link arms");
    const int resolution = static_cast<int>(parse_count(resolution_text.value_or("512"), "--resolution", 8192, 1));
    return run_arm2(*arm, scene, resolution, *out, os);
  }

  const int resolution =
      static_cast<int>(parse_count(resolution_text.value_or(is_se2 ? "128" : "96"), "--resolution", kMaxVolumeSide, 1));
  if (slice_text) {
    if (slices_text) throw UsageError("--slices: a --slice is one slice");
    const std::string axis = is_se2 ? "theta" : "theta1";
    const auto eq = slice_text->find('=');
    if (eq == std::string::npos || slice_text->substr(0, eq) != axis)
      throw UsageError("--slice: expected " + axis + "=VALUE for the scene's " + (is_se2 ? "polygon robot" : "3-link arm") +
                       ", got '" + printable(*slice_text, 60) + "'");
    const double value = wrap_angle(parse_number(slice_text->substr(eq + 1), "--slice " + axis));
    check_cspace_work(scene, resolution, 0);
    os << slice_json(scene, value, resolution).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    return 0;
  }

  const int slices = static_cast<int>(
      parse_count(slices_text.value_or(is_se2 ? "64" : std::to_string(resolution)), "--slices", kMaxVolumeSide, 1));
  const long long cells = static_cast<long long>(resolution) * resolution * slices;
  if (cells > kMaxVolumeCells)
    throw UsageError("--resolution " + std::to_string(resolution) + " --slices " + std::to_string(slices) + ": " +
                     std::to_string(cells) + " cells, more than the limit of " + std::to_string(kMaxVolumeCells) +
                     " (128 MiB)");
  check_cspace_work(scene, resolution, slices);
  return run_volume(scene, resolution, slices, *out, os);
}

}  // namespace

const Command kCspaceCommand{
    "cspace", "the exact C-space of an arm2, 3-link arm or polygon robot scene: PGM, volume or slice",
    "Usage: cspacelab cspace SCENE.json --out FILE [--resolution R] [--slices K]\n"
    "       cspacelab cspace SCENE.json --slice AXIS=VALUE [--resolution R]\n\n"
    "The C-obstacle region of the scene's robot, computed exactly and sampled at cell centres.\n"
    "A cell is in the C-obstacle exactly when the robot there touches an obstacle (obstacles are\n"
    "closed; walls count within 1e-6), as the collision checker decides, up to rounding.\n\n"
    "arm2 (the 2-link arm, T^2 = [-pi, pi)^2): closed-form angle intervals per obstacle (link 1's\n"
    "blocked theta1, then for each theta1 link 2's blocked theta2; where link 1 collides the whole\n"
    "column is blocked), sampled at R x R pixel centres (R in [1, 8192], default 512).\n"
    "FILE is a binary PGM: the header \"P5\\nR R\\n255\\n\", then R rows of R bytes,\n"
    "255 = free, 0 = C-obstacle. Column i (left to right) is theta1 = -pi + (i + 1/2) 2pi/R,\n"
    "row j (first row first) is theta2 = -pi + (j + 1/2) 2pi/R; theta2 is measured relative\n"
    "to link 1 (link 2's absolute angle is theta1 + theta2). --slices and --slice are refused.\n"
    "Output: {\"free_fraction\": x, \"seconds\": t}: the fraction of pixels that are free (255);\n"
    "the time to build the map and rasterise it (not to read the scene or write the file).\n\n"
    "polygon (SE(2)) and arm with 3 links (T^3): a volume of R x R x K cells, R and K in\n"
    "[1, 1024], R*R*K at most 134217728 (128 MiB).\n"
    "  polygon: axes x, y, theta. The reference point's (x, y) over the workspace box (the\n"
    "    checker does not confine the robot to the box: the box only bounds the volume), theta\n"
    "    over [-pi, pi) (periodic: its top and bottom are glued). Defaults R = 128, K = 64.\n"
    "    Exact: each slice is the union of the Minkowski sums of the obstacles' convex pieces\n"
    "    (a concave polygon is triangulated; a disk is its centre grown by its radius, a wall\n"
    "    its two ends grown by 1e-6) and the body's convex pieces turned by theta and reflected\n"
    "    through the reference point.\n"
    "  arm (3 links): axes theta2, theta3, theta1, all over [-pi, pi) and periodic; each theta1\n"
    "    is a (theta2, theta3) slice: all blocked where link 1 collides, else the exact 2-link\n"
    "    map of links 2 and 3 from link 1's end (angles relative, as the arm defines them).\n"
    "    Defaults R = 96, K = R (a cube).\n"
    "  The work is priced first and refused past 4e8 units: (4 x vertex sums + C-obstacle pieces\n"
    "  x R) a slice x K (SE(2); the pieces are the body's convex pieces x the obstacles', and\n"
    "  each piece's hull is taken of |body piece| x |obstacle piece| vertex sums) or obstacle edges x\n"
    "  R^2 x K (T^3; a disk is 1 edge, a wall 6, a polygon its vertices).\n"
    "  FILE holds R*R*K bytes, 255 = free, 0 = C-obstacle, the first axis fastest: the cell\n"
    "  (i, j, k) is byte (k*R + j)*R + i, and its centre on an axis of N cells over [min, max]\n"
    "  is min + (index + 1/2)(max - min)/N. FILE.json is its header:\n"
    "    {\"format\": \"cspacelab-volume\", \"version\": 1, \"robot\": \"polygon\"|\"arm\",\n"
    "     \"data\": FILE's name, \"dims\": [R, R, K], \"axes\": [{\"name\", \"min\", \"max\", \"cells\",\n"
    "     \"periodic\"} x 3, first axis first], \"free\": 255, \"blocked\": 0, \"free_fraction\": x}\n"
    "  Output: the header's fields, then \"header\": FILE.json's path and \"seconds\": the time\n"
    "  to compute the volume.\n\n"
    "--slice theta=V (polygon) or theta1=V (3-link arm), V in radians (wrapped into [-pi, pi)),\n"
    "prints one exact slice as JSON instead of writing a file:\n"
    "  polygon: {\"robot\": \"polygon\", \"theta\": V, \"bounds\": {\"min\": [x, y], \"max\": [x, y]},\n"
    "    \"pieces\": [{\"obstacle\": i, \"hull\": [[x, y], ...], \"radius\": r, \"outline\": [...]}]}:\n"
    "    the C-obstacle is the union of the pieces, each the points within r of the convex\n"
    "    polygon hull (counter-clockwise; one point or a segment where degenerate) made from\n"
    "    obstacles[i]; \"outline\" (only where r > 0) is a closed polyline on its boundary for\n"
    "    drawing (corner arcs in steps of at most pi/16).\n"
    "  arm: {\"robot\": \"arm\", \"theta1\": V, \"link1_blocked\": b, \"columns\": [{\"theta2\": t,\n"
    "    \"blocked_theta3\": [[lo, hi], ...]}]}: for R columns theta2 = -pi + (i + 1/2) 2pi/R,\n"
    "    the exact blocked theta3 as sorted closed intervals in [-pi, pi].\n"
    "  A slice is priced as one slice of the volume (SE(2): 64 units a piece for its outline;\n"
    "  T^3: obstacle edges x R columns) and refused past the same 4e8.\n\n"
    "A robot that is not arm2, a 3-link arm or a polygon, a bad R, K or slice, a volume over a\n"
    "limit (cells or work) or an unwritable FILE is a one-line error with exit status 2.\n",
    run_cspace};

}  // namespace csl::cli
