#include "core/teaching/answer_descriptions.hpp"

namespace csl {

namespace {
struct Description {
  std::string_view lesson, name, what;
};
// (In their own file: the app, which never shows them, links none of them into the wasm.)
const Description kDescriptions[] = {
    {"torus", "path_length",
     "the length of the path PRM found on the torus (the path itself is drawn)"},
    {"notation", "q_notation",
     "Q of the robot built (or of the practice exercise before it is checked): its notation, dimension, "
     "factors and other spellings"},
    {"collision", "min_n",
     "the smallest N whose N configurations (p and q counted) see the collision, and the same N counted with "
     "one end or neither"},
    {"distances", "s1_distance",
     "the distance between the two angles on S^1, and the steps that give it away: the difference mod 2 pi, the "
     "other way round, the dot product and its arccos, the case"},
    {"distances", "segment_distance",
     "the distance from the segment to the disk, and the steps that give it away: the projection parameter t "
     "(raw and clamped), the closest point, the centre's distance, the case"},
    {"analysis", "p8_n",
     "P8's n: the samples at which the whole-cube bound reaches the target p, as the handout has it and refined"},
    {"analysis", "p9_probability",
     "P9's visibility probability: exact (the areas under the rays, by cases) and its Monte Carlo estimate with "
     "its interval (the region in sight stays drawn)"},
    {"potential", "p13_forces",
     "at each control point rho, its gradient, the attractive and repulsive forces, the repulsive potential and "
     "the torque J^T F, and their sums: the numbers of the forces table (the arrows stay drawn)"},
    {"step-prm", "path_length",
     "the length of the path PRM found (the path itself is drawn)"},
    {"cspace-3d", "path_length",
     "the length of the path PRM found in the 3-D C-space (the path itself is drawn)"},
    {"compare", "path_length",
     "the lengths of the paths the two planners found (the paths themselves are drawn)"},
};
}  // namespace

std::string_view answer_description(std::string_view lesson, std::string_view name) {
  for (const Description& d : kDescriptions)
    if (d.lesson == lesson && d.name == name) return d.what;
  return {};
}

}  // namespace csl
