#pragma once
// C-space notation: the configuration space Q of a robot described in a few words, written as a
// product of R^n, S^1, T^n, SE(2), SE(3) and SO(3), and a checker for students' answers.
//
// Robot description (parse_robot_description): `key=value` tokens separated by spaces or commas,
// each key at most once, in any order:
//   base=fixed|planar-translating|planar|spatial-translating|spatial   default fixed
//        (planar: slides and turns in the plane; spatial: moves and turns freely in space;
//         *-translating: slides only, never turns)
//   joints=RRP             joint letters from base to tip, R revolute, P prismatic; default none
//   wrist=spherical|none   a spherical wrist is three more revolute joints; default none
// Examples: "joints=RRR", "base=planar", "joints=RRR wrist=spherical",
//           "base=planar, joints=RRR, wrist=spherical".
#include <stdexcept>
#include <string>
#include <vector>

namespace csl {

/// What the notation depends on: how the base moves, and which joints the arm has.
struct RobotDescription {
  enum class Base {
    Fixed,               ///< bolted down: contributes nothing
    PlanarTranslating,   ///< slides in the plane without turning: R^2
    PlanarMobile,        ///< slides and turns in the plane: SE(2)
    SpatialTranslating,  ///< slides in space without turning: R^3
    SpatialMobile,       ///< moves and turns freely in space: SE(3)
  };
  Base base = Base::Fixed;
  std::string joints;            ///< 'R' (revolute) and 'P' (prismatic), from base to tip
  bool spherical_wrist = false;  ///< three more revolute joints whose axes meet in one point
};

/// The longest description or written space the parsers read (bytes): far more than any
/// robot needs, and a bound on what an error message may quote.
inline constexpr std::size_t kMaxNotationText = 1000;

/// Thrown for a bad robot description or space expression; what() names the problem.
class NotationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Parses the description format above. Throws NotationError.
RobotDescription parse_robot_description(const std::string& text);

/// One factor of the product, e.g. {"T^6", 6, "six revolute joints: ..."}.
struct NotationFactor {
  std::string notation;
  int dimension = 0;
  std::string reason;  ///< one line: which part of the robot gives this factor, and why
};

/// Q in canonical notation: base first, then the revolute joints as one torus, then the
/// prismatic joints; factors joined by " x ".
struct ConfigSpaceInfo {
  std::string notation;  ///< e.g. "SE(2) x T^6"; "a single point" when nothing moves
  int dimension = 0;     ///< number of numbers that fix a configuration
  std::vector<NotationFactor> factors;
  std::vector<std::string> equivalent;  ///< other correct spellings, e.g. "R^2 x T^7"
};

/// The configuration space of a described robot. Throws NotationError for joint letters other
/// than R and P (possible only for a description built in code).
ConfigSpaceInfo configuration_space(const RobotDescription& robot);

/// A product space up to reordering, by what it is made of once SE(n), SO(2) and T^n are
/// expanded: SE(2) = R^2 x S^1, SE(3) = R^3 x SO(3), SO(2) = S^1, T^n = (S^1)^n.
struct SpaceSignature {
  int real_dimensions = 0;  ///< total n over the R^n factors (lines)
  int circles = 0;          ///< S^1 factors (circles)
  int spheres = 0;          ///< S^2 factors (spheres)
  int rotations = 0;        ///< SO(3) factors (rotations in space)

  /// Total dimension: R and S^1 count 1, S^2 counts 2, SO(3) counts 3.
  int dimension() const { return real_dimensions + circles + 2 * spheres + 3 * rotations; }
  bool operator==(const SpaceSignature& o) const {
    return real_dimensions == o.real_dimensions && circles == o.circles && spheres == o.spheres &&
           rotations == o.rotations;
  }
  bool operator!=(const SpaceSignature& o) const { return !(*this == o); }
};

/// Reads a written space such as "Q = SE(2) x T^6", "R² × S¹", "(S^1)^3 * R": product signs
/// x, ×, *; factors R, R^n, S^1, S^2, T^n, SO(2), SO(3), SE(2), SE(3), (...)^n, or "a point".
/// Throws NotationError saying what could not be read.
SpaceSignature parse_space_expression(const std::string& text);

/// The signature of a described robot's configuration space. Throws like configuration_space.
SpaceSignature signature_of(const RobotDescription& robot);

/// The verdict on a student's answer.
struct AnswerCheck {
  bool correct = false;
  std::string explanation;  ///< what is wrong in plain words, or which equality makes it right
  bool readable = true;     ///< false: the answer could not be read as a space
  int dimension = -1;       ///< the dimension of the space the student wrote; -1 if unreadable
};

/// Checks a student's written Q for the robot. Never throws for the answer: an unreadable one
/// comes back as incorrect, saying what could not be read. Throws like configuration_space.
AnswerCheck check_answer(const std::string& student, const RobotDescription& robot);

}  // namespace csl
