// cspacelab distance: the homework's distances (P10 on S^1, P11 segment to disk) and friends.
#include "cli/commands.hpp"
#include "core/base/angles.hpp"
#include "core/geometry/geometry.hpp"
#include "core/scene/scene.hpp"

#include <cmath>

namespace csl::cli {
namespace {

using json = nlohmann::json;

json point_json(const Vec2& p) { return json::array({p.x(), p.y()}); }

int run_distance(Args& args, std::ostream& os) {
  std::string kind;
  auto p1 = args.take("p1"), p2 = args.take("p2"), center = args.take("center"), radius = args.take("radius");
  auto q1 = args.take("q1"), q2 = args.take("q2");
  kind = args.take_positional("KIND (s1, segment-disk or segment-segment)");
  if (kind == "s1") {
    if (p1 || p2 || center || radius || q1 || q2) throw UsageError("distance s1 takes two angles: A B");
    const double a = parse_number(args.take_positional("angle A"), "A");
    const double b = parse_number(args.take_positional("angle B"), "B");
    args.finish();
    // B - A as the homework's modulus takes it; only where that overflows (angles near 1e308),
    // each angle into the chart first. (Wrapping huge angles first would lose what an exact
    // difference keeps: 1e15 and 1e15 + 1 are 1 rad apart.)
    const bool finite = std::isfinite(b - a);
    const double wa = finite ? 0.0 : wrap_angle(a), wb = finite ? b - a : wrap_angle(b);
    print_json(os, {{"distance", s1_distance(wa, wb)},
                    {"modulus", s1_distance(wa, wb)},
                    {"rotation", s1_distance_rotation(a, b)},
                    {"signed_turn", angle_difference(wa, wb)}});
    return 0;
  }
  args.finish();
  auto need = [](const std::optional<std::string>& v, const char* flag) {
    if (!v) throw UsageError(std::string("missing --") + flag);
    return *v;
  };
  // Scenes' limit on coordinates: beyond it the squared distances could overflow.
  const auto parse_point = [](const std::string& text, const std::string& what) {
    const Vec2 v = cli::parse_point(text, what);
    if (!(std::fabs(v.x()) <= kMaxCoordinate && std::fabs(v.y()) <= kMaxCoordinate))
      throw UsageError(what + ": coordinates must be within +-1e6, as in scenes");
    return v;
  };
  if (kind == "segment-disk") {
    if (q1 || q2) throw UsageError("segment-disk takes --p1 --p2 --center --radius");
    const Vec2 a = parse_point(need(p1, "p1"), "--p1"), b = parse_point(need(p2, "p2"), "--p2");
    const Vec2 c = parse_point(need(center, "center"), "--center");
    const double r = parse_number(need(radius, "radius"), "--radius");
    if (r < 0.0 || r > kMaxCoordinate) throw UsageError("--radius: must be in [0, 1e6], as in scenes");
    print_json(os, {{"distance", segment_disk_distance(a, b, c, r)},
                    {"signed", segment_disk_signed_distance(a, b, c, r)},
                    {"closest_point", point_json(closest_point_on_segment(c, a, b))},
                    {"closest_parameter", closest_parameter(c, a, b)}});
    return 0;
  }
  if (kind == "segment-segment") {
    if (center || radius) throw UsageError("segment-segment takes --p1 --p2 --q1 --q2");
    const Vec2 a = parse_point(need(p1, "p1"), "--p1"), b = parse_point(need(p2, "p2"), "--p2");
    const Vec2 c = parse_point(need(q1, "q1"), "--q1"), d = parse_point(need(q2, "q2"), "--q2");
    print_json(os, {{"distance", segment_segment_distance(a, b, c, d)}, {"intersect", segments_intersect(a, b, c, d)}});
    return 0;
  }
  throw UsageError("unknown distance kind '" + kind + "' (s1, segment-disk or segment-segment)");
}

}  // namespace

const Command kDistanceCommand{
    "distance", "distances of the homework: on S^1 (P10), segment to disk (P11), segment to segment",
    "Usage: cspacelab distance s1 A B\n"
    "       cspacelab distance segment-disk --p1 X,Y --p2 X,Y --center X,Y --radius R\n"
    "       cspacelab distance segment-segment --p1 X,Y --p2 X,Y --q1 X,Y --q2 X,Y\n\n"
    "s1: angles A, B in radians (any real numbers) ->\n"
    "  {\"distance\": d, \"modulus\": d, \"rotation\": d, \"signed_turn\": s}\n"
    "  d in [0, pi] computed both ways of P10: by the angle modulus |wrap(B - A)| and from the\n"
    "  rotation matrices R(A)^T R(B) (cosine = dot product of their first columns); they agree to\n"
    "  rounding, which grows with the angles: a double near 1e9 rad is itself only good to 1e-7\n"
    "  rad, and near 1e16 B - A rounds to a multiple of 2 rad, where neither result means much.\n"
    "  signed_turn is the shorter turn from A to B, in [-pi, pi).\n"
    "segment-disk: the segment p1p2 and the closed disk of radius R >= 0 at center (coordinates\n"
    "  and R within 1e6, as in scenes) ->\n"
    "  {\"distance\": d, \"signed\": s, \"closest_point\": [x, y], \"closest_parameter\": u}\n"
    "  d = max(0, s), s = |c - closest point| - R (negative: overlap), the closest point of the\n"
    "  segment to the centre is p1 + u (p2 - p1), u in [0, 1].\n"
    "segment-segment: {\"distance\": d, \"intersect\": bool} (coordinates within 1e6)\n"
    "Negative angles are fine as positionals: cspacelab distance s1 -3 3\n",
    run_distance};

}  // namespace csl::cli
