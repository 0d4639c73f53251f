#include "core/teaching/notation.hpp"

#include "core/base/text.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <utility>

namespace csl {
namespace {

using Base = RobotDescription::Base;

bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }
char to_upper(char c) { return static_cast<char>(std::toupper(static_cast<unsigned char>(c))); }

std::string join(const std::vector<std::string>& parts, const std::string& sep) {
  std::string out;
  for (const std::string& p : parts) out += (out.empty() ? "" : sep) + p;
  return out;
}

/// "one revolute joint" / "6 revolute joints".
std::string count(int n, const std::string& one, const std::string& many) {
  return n == 1 ? "one " + one : std::to_string(n) + " " + many;
}

std::string power(const std::string& factor, int n) {
  return n == 1 ? factor : factor + "^" + std::to_string(n);
}

/// n revolute joints: S^1 for one, the n-torus T^n for more.
std::string torus(int n) { return n == 1 ? "S^1" : "T^" + std::to_string(n); }

std::string repeated(const std::string& factor, int n) {
  return join(std::vector<std::string>(static_cast<std::size_t>(n), factor), " x ");
}

// ------------------------------------------------------------------------ robot descriptions

/// The counts the notation depends on.
struct Parts {
  Base base = Base::Fixed;
  int revolute = 0;  ///< arm joints plus the wrist's three
  int prismatic = 0;
  bool wrist = false;
};

int base_reals(Base b) {
  switch (b) {
    case Base::PlanarTranslating:
    case Base::PlanarMobile:
      return 2;
    case Base::SpatialTranslating:
    case Base::SpatialMobile:
      return 3;
    case Base::Fixed:
      break;
  }
  return 0;
}

bool turns_in_plane(Base b) { return b == Base::PlanarMobile; }
bool turns_in_space(Base b) { return b == Base::SpatialMobile; }

void check_joint_letters(const std::string& joints) {
  for (char c : joints) {
    if (c == 'R' || c == 'P') continue;
    // Quote the letter only when it is a whole (ASCII) character, so messages stay valid UTF-8.
    const std::string what =
        static_cast<unsigned char>(c) < 0x80 ? "'" + printable(std::string(1, c)) + "'" : "a character";
    throw NotationError("joints: " + what + " in '" + printable(joints, 40) +
                        "' is not a joint letter (R revolute, P prismatic)");
  }
}

Parts parts_of(const RobotDescription& robot) {
  check_joint_letters(robot.joints);
  const auto letters = [&](char c) {
    return static_cast<int>(std::count(robot.joints.begin(), robot.joints.end(), c));
  };
  return {robot.base, letters('R') + (robot.spherical_wrist ? 3 : 0), letters('P'),
          robot.spherical_wrist};
}

struct BaseWord {
  const char* word;
  Base base;
};
constexpr BaseWord kBaseWords[] = {{"fixed", Base::Fixed},
                                   {"planar-translating", Base::PlanarTranslating},
                                   {"planar", Base::PlanarMobile},
                                   {"spatial-translating", Base::SpatialTranslating},
                                   {"spatial", Base::SpatialMobile}};

// ----------------------------------------------------------------------- canonical notation

std::vector<NotationFactor> factors_of(const Parts& p) {
  std::vector<NotationFactor> f;
  switch (p.base) {
    case Base::Fixed:
      break;
    case Base::PlanarTranslating:
      f.push_back({"R^2", 2, "R^2: the base slides in the plane (x, y) but never turns"});
      break;
    case Base::PlanarMobile:
      f.push_back(
          {"SE(2)", 3, "SE(2) = R^2 x S^1: the base moves in the plane (x, y) and turns (θ)"});
      break;
    case Base::SpatialTranslating:
      f.push_back({"R^3", 3, "R^3: the base slides in space (x, y, z) but never turns"});
      break;
    case Base::SpatialMobile:
      f.push_back({"SE(3)", 6,
                   "SE(3) = R^3 x SO(3): the base moves in space (x, y, z) and can be turned "
                   "into any orientation, an element of SO(3)"});
      break;
  }
  if (p.revolute == 1) {
    f.push_back({"S^1", 1, "S^1: one revolute joint, whose angle goes around a circle"});
  } else if (p.revolute > 1) {
    const std::string n = std::to_string(p.revolute);
    f.push_back({torus(p.revolute), p.revolute,
                 torus(p.revolute) + ": " + n + " revolute joints" +
                     (p.wrist ? " (3 of them in the spherical wrist)" : "") +
                     ", each angle on its own circle S^1; " + n + " circles make the " + n +
                     "-torus"});
  }
  if (p.prismatic == 1) {
    f.push_back({"R", 1, "R: one prismatic joint, which slides along a line (one real number)"});
  } else if (p.prismatic > 1) {
    f.push_back({power("R", p.prismatic), p.prismatic,
                 power("R", p.prismatic) + ": " + std::to_string(p.prismatic) +
                     " prismatic joints, each sliding along its own line (one real number each)"});
  }
  if (f.empty())
    f.push_back({"a single point", 0, "nothing moves: the robot has one configuration"});
  return f;
}

std::vector<std::string> base_spelling(Base b, bool expand) {
  switch (b) {
    case Base::PlanarTranslating:
      return {"R^2"};
    case Base::PlanarMobile:
      return expand ? std::vector<std::string>{"R^2", "S^1"} : std::vector<std::string>{"SE(2)"};
    case Base::SpatialTranslating:
      return {"R^3"};
    case Base::SpatialMobile:
      return expand ? std::vector<std::string>{"R^3", "SO(3)"} : std::vector<std::string>{"SE(3)"};
    case Base::Fixed:
      break;
  }
  return {};
}

/// Base, then the revolute joints written as `revolute`, then the prismatic joints.
std::string spell(const Parts& p, bool expand_base, const std::string& revolute) {
  std::vector<std::string> f = base_spelling(p.base, expand_base);
  if (p.revolute > 0) f.push_back(revolute);
  if (p.prismatic > 0) f.push_back(power("R", p.prismatic));
  return f.empty() ? "a single point" : join(f, " x ");
}

/// Other correct ways to write the same product, most instructive first.
std::vector<std::string> equivalents(const Parts& p, const std::string& canonical) {
  const int reals = base_reals(p.base) + p.prismatic;
  const int circles = p.revolute + (turns_in_plane(p.base) ? 1 : 0);
  std::vector<std::string> merged;  // like factors gathered: R^a x SO(3) x T^b
  if (reals > 0) merged.push_back(power("R", reals));
  if (turns_in_space(p.base)) merged.push_back("SO(3)");
  if (circles > 0) merged.push_back(torus(circles));

  std::vector<std::string> all = {spell(p, true, torus(p.revolute)),
                                  merged.empty() ? "R^0" : join(merged, " x ")};
  if (p.revolute >= 2) {
    const std::string n = std::to_string(p.revolute);
    all.push_back(spell(p, false, "(S^1)^" + n));
    all.push_back(spell(p, false, "(SO(2))^" + n));  // the handout's other spelling
  } else if (p.revolute == 1) {
    all.push_back(spell(p, false, "SO(2)"));
  }
  if (reals + circles > 0 && reals + circles <= 4) {  // short enough to write out in full
    std::vector<std::string> f;
    if (reals > 0) f.push_back(repeated("R", reals));
    if (turns_in_space(p.base)) f.push_back("SO(3)");
    if (circles > 0) f.push_back(repeated("S^1", circles));
    all.push_back(join(f, " x "));
  }
  std::vector<std::string> out;
  for (const std::string& s : all)
    if (s != canonical && std::find(out.begin(), out.end(), s) == out.end()) out.push_back(s);
  return out;
}

// --------------------------------------------------------------------- reading written spaces

constexpr int kMaxCount = 1000000;  // far beyond any robot, far below int overflow

/// Rewrites the Unicode and LaTeX spellings students type into the ASCII the reader parses:
/// × and \times become x, ℝ becomes R, a run of superscript digits ²³ becomes ^23.
std::string to_ascii(const std::string& s) {
  static const char* const kSuperscripts[10] = {"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074",
                                                "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
  static const std::pair<const char*, const char*> kRewrites[] = {
      {"\u00d7", "x"}, {"\\times", "x"}, {"\u211d", "R"}, {"\\mathbb{R}", "R"}};
  std::string out;
  bool in_superscript = false;
  for (std::size_t i = 0; i < s.size();) {
    const auto starts = [&](const char* w) { return s.compare(i, std::strlen(w), w) == 0; };
    int digit = -1;
    for (int d = 0; d < 10; ++d)
      if (starts(kSuperscripts[d])) digit = d;
    if (digit >= 0) {
      if (!in_superscript) out += '^';
      out += static_cast<char>('0' + digit);
      i += std::strlen(kSuperscripts[digit]);
      in_superscript = true;
      continue;
    }
    in_superscript = false;
    const auto* r = std::find_if(std::begin(kRewrites), std::end(kRewrites),
                                 [&](const auto& rw) { return starts(rw.first); });
    if (r != std::end(kRewrites)) {
      out += r->second;
      i += std::strlen(r->first);
    } else {
      out += s[i++];
    }
  }
  return out;
}

/// Drops the "Q =" students put in front (the handout asks for answers as "Q = something").
std::string without_q(const std::string& s) {
  std::string t = trim(s);
  if (!t.empty() && to_upper(t[0]) == 'Q') {
    const std::string rest = trim(t.substr(1));
    if (!rest.empty() && rest[0] == '=') return trim(rest.substr(1));
  }
  return t;
}

/// Recursive descent over the ASCII form:
///   product := factor (("x" | "X" | "*") factor)*
///   factor  := "(" product ")" [^n] | R [^n] | SO(2|3) [^n] | SE(2|3) [^n] | S^1 | S^2 | T^n
/// Names are case-insensitive; spaces are allowed between any two symbols.
class SpaceReader {
 public:
  explicit SpaceReader(std::string text) : s_(std::move(text)) {}

  SpaceSignature read() {
    SpaceSignature q = product();
    skip_spaces();
    if (!at_end()) fail(pos_, "')' without a matching '('");  // product() stops only there
    return q;
  }

 private:
  static constexpr const char* kFactors = "expected a factor such as R^2, S^1, T^3, SO(3) or SE(2)";

  SpaceSignature product() {
    SpaceSignature q = factor();
    while (true) {
      skip_spaces();
      if (at_end() || peek() == ')') return q;
      if (peek() != 'x' && peek() != 'X' && peek() != '*')
        fail(pos_, "expected a product sign x, × or *");
      ++pos_;
      q = checked(q, factor(), 1);
    }
  }

  SpaceSignature factor() {
    skip_spaces();
    const std::size_t start = pos_;
    const char c = at_end() ? '\0' : to_upper(peek());
    if (c == '(') {
      // The parser recurses once per '(': without a limit, 65000 of them (10000 on the
      // browser's stack) overflowed the stack. No written space needs more than a few.
      if (++depth_ > kMaxNesting) fail(pos_, "too many nested parentheses (at most " + std::to_string(kMaxNesting) + ")");
      ++pos_;
      SpaceSignature q = product();
      --depth_;
      skip_spaces();
      if (!eat(')')) fail(pos_, "expected ')'");
      return with_power(q);
    }
    if (c == 'R') {
      ++pos_;
      return with_power({1, 0, 0, 0});
    }
    if (c == 'T') {
      ++pos_;
      const int n = exponent("T needs an exponent, as in T^3");
      return without_power({0, n, 0, 0});
    }
    if (c != 'S') fail(pos_, kFactors);
    ++pos_;
    skip_spaces();
    const char group = at_end() ? '\0' : to_upper(peek());
    if (group == 'O' || group == 'E') {  // SO(n) or SE(n)
      ++pos_;
      skip_spaces();
      if (!eat('(')) fail(pos_, "expected '(' as in SO(3) or SE(2)");
      const int n = integer();
      skip_spaces();
      if (!eat(')')) fail(pos_, "expected ')'");
      if (n != 2 && n != 3) fail(start, "only SO(2), SO(3), SE(2) and SE(3) are known");
      if (group == 'O')
        return with_power(n == 2 ? SpaceSignature{0, 1, 0, 0} : SpaceSignature{0, 0, 0, 1});
      return with_power(n == 2 ? SpaceSignature{2, 1, 0, 0} : SpaceSignature{3, 0, 0, 1});
    }
    const int n = exponent("S needs an exponent: S^1 is the circle, S^2 the sphere");
    if (n != 1 && n != 2) fail(start, "only S^1 (the circle) and S^2 (the sphere) are known");
    return without_power(n == 1 ? SpaceSignature{0, 1, 0, 0} : SpaceSignature{0, 0, 1, 0});
  }

  SpaceSignature with_power(const SpaceSignature& q) {
    skip_spaces();
    return eat('^') ? checked({}, q, integer()) : q;
  }

  // S^1^3 would be ambiguous; ask for the parentheses.
  SpaceSignature without_power(const SpaceSignature& q) {
    skip_spaces();
    if (!at_end() && peek() == '^')
      fail(pos_, "a power of S^n or T^n needs parentheses, as in (S^1)^3");
    return q;
  }

  int exponent(const char* missing) {
    skip_spaces();
    if (!eat('^')) fail(pos_, missing);
    return integer();
  }

  /// Digits, optionally in LaTeX braces: 6 or {6}.
  int integer() {
    skip_spaces();
    const bool braced = eat('{');
    skip_spaces();
    const std::size_t start = pos_;
    long long v = 0;
    while (!at_end() && std::isdigit(static_cast<unsigned char>(peek())) != 0) {
      v = v * 10 + (peek() - '0');
      if (v > kMaxCount) fail(start, "number too large");
      ++pos_;
    }
    if (pos_ == start) fail(pos_, "expected a whole number");
    skip_spaces();
    if (braced && !eat('}')) fail(pos_, "expected '}'");
    return static_cast<int>(v);
  }

  /// a + b * n, refusing counts no robot could have (and so any overflow).
  SpaceSignature checked(const SpaceSignature& a, const SpaceSignature& b, int n) {
    const auto f = [&](int x, int y) {
      const long long v = x + static_cast<long long>(y) * n;
      if (v > kMaxCount) fail(pos_, "space too large");
      return static_cast<int>(v);
    };
    return {f(a.real_dimensions, b.real_dimensions), f(a.circles, b.circles),
            f(a.spheres, b.spheres), f(a.rotations, b.rotations)};
  }

  bool at_end() const { return pos_ >= s_.size(); }
  char peek() const { return s_[pos_]; }
  bool eat(char c) {
    if (at_end() || peek() != c) return false;
    ++pos_;
    return true;
  }
  void skip_spaces() {
    while (!at_end() && is_space(peek())) ++pos_;
  }

  /// NotationError "<what> (at '<text from there>')", cut on a UTF-8 character boundary.
  [[noreturn]] void fail(std::size_t at, const std::string& what) const {
    if (at >= s_.size()) throw NotationError(what + " (at the end)");
    std::size_t end = std::min(s_.size(), at + 16);
    while (end < s_.size() && (static_cast<unsigned char>(s_[end]) & 0xC0) == 0x80) ++end;
    throw NotationError(what + " (at '" + printable(s_.substr(at, end - at)) +
                        (end < s_.size() ? "...')" : "')"));
  }

  static constexpr int kMaxNesting = 32;
  std::string s_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

// ------------------------------------------------------------------------- checking answers

std::string circle_sources(const Parts& p) {
  std::vector<std::string> src;
  if (p.revolute > 0) src.push_back(count(p.revolute, "revolute joint", "revolute joints"));
  if (turns_in_plane(p.base)) src.push_back("the base turning in the plane");
  return src.empty() ? "nothing on this robot turns" : join(src, " and ");
}

std::string line_sources(const Parts& p) {
  std::vector<std::string> src;
  if (base_reals(p.base) == 2) src.push_back("the base's position (x, y)");
  if (base_reals(p.base) == 3) src.push_back("the base's position (x, y, z)");
  if (p.prismatic > 0) src.push_back(count(p.prismatic, "prismatic joint", "prismatic joints"));
  return src.empty() ? "nothing on this robot slides" : join(src, " and ");
}

/// Why an angle is S^1, naming what turns on this robot.
std::string angle_note(const Parts& p) {
  const std::string why = "goes around the circle S^1, not along the line R";
  if (p.revolute == 0) return "the base's turning is an angle: it " + why;
  if (!turns_in_plane(p.base)) return "a revolute joint turns: its angle " + why;
  return "an angle (of a revolute joint or of the base's turning) " + why;
}

/// Why a slide is R, naming what slides on this robot.
std::string slide_note(const Parts& p) {
  if (base_reals(p.base) == 0) return "a prismatic joint slides along a line: R, not S^1";
  if (p.prismatic == 0) return "the base's translation runs along lines: R, not S^1";
  return "a slide (of a prismatic joint or of the base) runs along a line: R, not S^1";
}

std::string reals_text(int n) { return n == 0 ? "no R factor" : power("R", n); }

std::string circles_text(int n) {
  return n == 0 ? "no circle factor"
                : std::to_string(n) + (n == 1 ? " circle factor" : " circle factors");
}

/// Names what differs between the student's space `g` and the right one `e`. Known confusions
/// are explained first; each such note also corrects `g` (reading S^2 as the T^2 meant, say),
/// so the counts after it report only what is still off, and say under which reading.
std::string explain_difference(SpaceSignature g, const SpaceSignature& e, const Parts& p) {
  std::vector<std::string> notes, readings;
  const int got_dimension = g.dimension();

  // Orientation in space written as the sphere, or as three angles.
  if (g.rotations < e.rotations && g.spheres > e.spheres) {
    notes.push_back(
        "S^2 is not SO(3): a point on the sphere says where one axis of the base "
        "points, not how the base is turned about that axis");
    readings.push_back("S^2 as SO(3)");
    --g.spheres;
    ++g.rotations;
  } else if (g.rotations < e.rotations && g.circles - e.circles >= 3) {
    notes.push_back(
        "T^3 is not SO(3): the orientations of a body turning freely in space form "
        "SO(3), which is not a torus although both have dimension 3");
    readings.push_back("T^3 as SO(3)");
    g.circles -= 3;
    ++g.rotations;
  }
  // The sphere written for the torus.
  if (const int k = std::min(g.spheres - e.spheres, (e.circles - g.circles) / 2); k > 0) {
    notes.push_back(
        "S^2 is the sphere: S^1 x S^1 is the torus T^2 (a loop through the torus' "
        "hole never shrinks to a point, while on a sphere every loop does)");
    readings.push_back("S^2 as T^2");
    g.spheres -= k;
    g.circles += 2 * k;
  }
  // SO(3) written for three revolute joints: P6's spherical wrist.
  if (const int k = std::min(g.rotations - e.rotations, (e.circles - g.circles) / 3); k > 0) {
    notes.push_back(
        "SO(3) is not T^3: three revolute joints, a spherical wrist too, each turn "
        "through their own angle, giving T^3 = S^1 x S^1 x S^1; SO(3), all "
        "rotations in space, is a different space of the same dimension");
    readings.push_back("SO(3) as T^3");
    g.rotations -= k;
    g.circles += 3 * k;
  }
  // A line for a circle or a circle for a line: only when the student counted the degrees of
  // freedom right, otherwise a missing S^1 next to an extra R is more likely two mistakes.
  if (got_dimension == e.dimension()) {
    if (const int k = std::min(g.real_dimensions - e.real_dimensions, e.circles - g.circles);
        k > 0) {
      notes.push_back(angle_note(p));
      readings.push_back("R as S^1");
      g.real_dimensions -= k;
      g.circles += k;
    }
    if (const int k = std::min(g.circles - e.circles, e.real_dimensions - g.real_dimensions);
        k > 0) {
      notes.push_back(slide_note(p));
      readings.push_back("S^1 as R");
      g.circles -= k;
      g.real_dimensions += k;
    }
  }

  // Whatever is still off, counted.
  std::vector<std::string> counts;
  if (g.circles < e.circles) {
    const int k = e.circles - g.circles;
    counts.push_back(turns_in_plane(p.base)
                         ? count(k, "circle factor is", "circle factors are") +
                               " missing: expected " + circles_text(e.circles) + " (" +
                               circle_sources(p) + "), got " + std::to_string(g.circles)
                         : count(k, "revolute joint is", "revolute joints are") +
                               " missing: expected " + circles_text(e.circles) + ", got " +
                               std::to_string(g.circles));
  } else if (g.circles > e.circles) {
    counts.push_back(count(g.circles - e.circles, "circle factor", "circle factors") +
                     " too many: expected " + circles_text(e.circles) + " (" + circle_sources(p) +
                     "), got " + std::to_string(g.circles));
  }
  if (g.real_dimensions != e.real_dimensions) {
    const int k = std::abs(g.real_dimensions - e.real_dimensions);
    counts.push_back((g.real_dimensions < e.real_dimensions
                          ? count(k, "R dimension is", "R dimensions are") + " missing"
                          : count(k, "R dimension", "R dimensions") + " too many") +
                     ": expected " + reals_text(e.real_dimensions) + " (" + line_sources(p) +
                     "), got " + reals_text(g.real_dimensions));
  }
  if (g.rotations < e.rotations) {
    counts.push_back("SO(3) is missing: the base turns freely in space, SE(3) = R^3 x SO(3)");
  } else if (g.rotations > e.rotations) {
    counts.push_back(e.rotations == 0
                         ? "SO(3) does not belong here: nothing on this robot turns freely in space"
                         : "only one SO(3): the base is the only part that turns freely in space");
  }
  if (g.spheres > e.spheres)
    counts.push_back(
        "S^2 (the sphere) does not belong here: no part of this robot moves on a sphere");
  if (!counts.empty() && !readings.empty())
    counts.front() = "reading " + join(readings, ", ") + ": " + counts.front();
  notes.insert(notes.end(), counts.begin(), counts.end());

  if (got_dimension != e.dimension())
    notes.push_back("dimension: expected " + std::to_string(e.dimension()) + ", got " +
                    std::to_string(got_dimension));
  return join(notes, "; ");
}

std::string squeezed(const std::string& s) {
  std::string out;
  for (char c : s)
    if (!is_space(c)) out += c;
  return out;
}

}  // namespace

RobotDescription parse_robot_description(const std::string& text) {
  if (text.size() > kMaxNotationText)
    throw NotationError("the description is longer than " + std::to_string(kMaxNotationText) + " characters");
  // "base = planar" means base=planar: drop the spaces next to '=' before splitting.
  std::string s;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (!is_space(text[i])) {
      s += text[i];
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && is_space(text[j])) ++j;
    if (!(!s.empty() && s.back() == '=') && !(j < text.size() && text[j] == '=')) s += ' ';
    i = j - 1;
  }

  RobotDescription robot;
  bool seen_base = false, seen_joints = false, seen_wrist = false;
  std::size_t pos = 0;
  while (pos < s.size()) {
    const std::size_t end = std::min(s.find(' ', pos), s.find(',', pos));
    const std::string token = s.substr(pos, end - pos);
    pos = end == std::string::npos ? s.size() : end + 1;
    if (token.empty()) continue;

    const std::size_t eq = token.find('=');
    if (eq == std::string::npos)
      throw NotationError("'" + printable(token, 40) + "' is not key=value (keys: base, joints, wrist)");
    const std::string key = token.substr(0, eq), value = token.substr(eq + 1);
    const auto once = [&](bool& seen) {
      if (seen) throw NotationError(printable(key, 40) + " given twice");
      seen = true;
      if (value.empty()) throw NotationError(printable(key, 40) + ": missing value");
    };
    if (key == "base") {
      once(seen_base);
      const auto* w = std::find_if(std::begin(kBaseWords), std::end(kBaseWords),
                                   [&](const BaseWord& b) { return value == b.word; });
      if (w == std::end(kBaseWords))
        throw NotationError(
            "base: unknown value '" + printable(value, 40) +
            "' (fixed, planar-translating, planar, spatial-translating or spatial)");
      robot.base = w->base;
    } else if (key == "joints") {
      once(seen_joints);
      check_joint_letters(value);
      robot.joints = value;
    } else if (key == "wrist") {
      once(seen_wrist);
      if (value != "spherical" && value != "none")
        throw NotationError("wrist: unknown value '" + printable(value, 40) + "' (spherical or none)");
      robot.spherical_wrist = value == "spherical";
    } else {
      throw NotationError("unknown key '" + printable(key, 40) + "' (keys: base, joints, wrist)");
    }
  }
  return robot;
}

ConfigSpaceInfo configuration_space(const RobotDescription& robot) {
  const Parts p = parts_of(robot);
  ConfigSpaceInfo info;
  info.factors = factors_of(p);
  std::vector<std::string> names;
  for (const NotationFactor& f : info.factors) {
    names.push_back(f.notation);
    info.dimension += f.dimension;
  }
  info.notation = join(names, " x ");
  info.equivalent = equivalents(p, info.notation);
  return info;
}

SpaceSignature signature_of(const RobotDescription& robot) {
  const Parts p = parts_of(robot);
  return {base_reals(p.base) + p.prismatic, p.revolute + (turns_in_plane(p.base) ? 1 : 0), 0,
          turns_in_space(p.base) ? 1 : 0};
}

SpaceSignature parse_space_expression(const std::string& text) {
  if (text.size() > kMaxNotationText)
    throw NotationError("the answer is longer than " + std::to_string(kMaxNotationText) + " characters");
  const std::string ascii = without_q(to_ascii(text));
  if (ascii.empty()) throw NotationError("the answer is empty");
  std::string lower;
  for (char c : ascii) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "point" || lower == "a point" || lower == "a single point") return {};
  return SpaceReader(ascii).read();
}

AnswerCheck check_answer(const std::string& student, const RobotDescription& robot) {
  SpaceSignature got;
  try {
    got = parse_space_expression(student);
  } catch (const NotationError& e) {
    return {false, std::string("could not read the answer: ") + e.what(), false};
  }
  const SpaceSignature want = signature_of(robot);
  if (got != want) return {false, explain_difference(got, want, parts_of(robot)), true, got.dimension()};

  // Confirm with an equality the student can learn from: their spelling = ours, or, when they
  // wrote ours, ours = its expanded form.
  const ConfigSpaceInfo info = configuration_space(robot);
  const std::string written = without_q(student);
  std::string other = written;
  if (squeezed(to_ascii(written)) == squeezed(info.notation))
    other = info.equivalent.empty() ? "" : info.equivalent.front();
  return {true,
          "correct: " + info.notation + (other.empty() ? "" : " = " + other) + " (dimension " +
              std::to_string(info.dimension) + ")",
          true, got.dimension()};
}

}  // namespace csl
