// cspacelab bound: the failure bounds of section 2.1 and P8.
#include <cstdint>
#include <stdexcept>

#include "cli/commands.hpp"
#include "core/teaching/analysis.hpp"

namespace csl::cli {
namespace {

// A count as an integer while a double holds it exactly (2^53), else as the double it is.
nlohmann::json count_json(double m) {
  if (m <= 9007199254740992.0) return static_cast<std::int64_t>(m);
  return m;
}

int run_bound(Args& args, std::ostream& os) {
  const bool tiling = args.take_flag("tiling");
  const auto length = args.take("length"), clearance = args.take("clearance"), dim = args.take("dim");
  const auto volume = args.take("free-volume"), samples = args.take("samples"), target = args.take("target");
  args.finish();
  auto need = [](const std::optional<std::string>& v, const char* flag) {
    if (!v) throw UsageError(std::string("missing --") + flag);
    return *v;
  };
  const double r = parse_number(need(clearance, "clearance"), "--clearance");
  const int d = static_cast<int>(parse_count(need(dim, "dim"), "--dim", 64, 1));
  const double n = parse_number(need(samples, "samples"), "--samples");
  const double goal = target ? parse_number(*target, "--target") : 0.01;
  try {
    if (tiling) {
      if (length || volume) throw UsageError("--tiling is for F = [0,1]^d: no --length or --free-volume");
      const TilingBound t = whole_space_tiling_bound(r, d, n);
      print_json(os, {{"balls", count_json(t.balls)},
                      {"balls_per_axis", count_json(t.per_axis)},
                      {"covering_balls", count_json(t.covering_balls)},
                      {"boundary_balls", count_json(t.boundary_balls)},
                      {"sigma", t.sigma},
                      {"rate", t.rate},
                      {"interior_bound", t.interior_bound},
                      {"interior_samples_for_target", t.interior_samples_for(goal)},
                      {"failure_bound", t.bound},
                      {"vacuous", t.vacuous},
                      {"samples_for_target", t.samples_for(goal)},
                      {"target", goal}});
      return 0;
    }
    const FailureBound b = path_tiling_bound(parse_number(need(length, "length"), "--length"), r, d,
                                             parse_number(need(volume, "free-volume"), "--free-volume"), n);
    print_json(os, {{"balls", count_json(b.balls)},
                    {"sigma", b.sigma},
                    {"failure_bound", b.bound},
                    {"vacuous", b.vacuous},
                    {"exponent", b.exponent},
                    {"samples_for_target", b.samples_for(goal)},
                    {"target", goal}});
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  return 0;
}

}  // namespace

const Command kBoundCommand{
    "bound", "PRM's failure bound (section 2.1), or the whole-space tiling bound (P8)",
    "Usage: cspacelab bound --length L --clearance r --dim d --free-volume V --samples n [--target p]\n"
    "       cspacelab bound --tiling --clearance r --dim d --samples n [--target p]\n\n"
    "Path tiling (section 2.1): a free path of length L and clearance r is covered by\n"
    "m = ceil(L / (r/2)) balls of radius r/2, and\n"
    "  Prob(failure) <= m exp(-sigma r^d n),  sigma = mu(B_1) / (2^d mu(F)), mu(F) = V.\n"
    "  -> {\"balls\": m, \"sigma\": s, \"failure_bound\": p, \"vacuous\": p >= 1, \"exponent\": s r^d n,\n"
    "      \"samples_for_target\": the n at which the bound reaches p (default 0.01), \"target\"}\n"
    "Whole-space tiling (P8), F = [0,1]^d: N = ceil(max(2, sqrt(d)) / r) balls of radius r/2 per\n"
    "axis, 1/N apart (neighbours r/2 apart at most, and every point covered), m = N^d, with\n"
    "sigma = mu(B_1) / 2^d. interior_bound = m exp(-sigma r^d n) is the path bound with m balls, as\n"
    "if every ball lay in F; the balls at the cube's faces stick out and are hit less often, so\n"
    "failure_bound counts a ball reaching out of the cube along j axes as hit at rate\n"
    "sigma min(r,1)^d / 2^j: sum_j C(d,j) E^j (N-E)^(d-j) exp(-sigma min(r,1)^d n / 2^j), E of the\n"
    "N balls per axis within min(r,1)/2 of a face.\n"
    "  -> {\"balls\": m, \"balls_per_axis\": N, \"covering_balls\": ceil(sqrt(d)/r)^d (enough to\n"
    "      cover every point), \"boundary_balls\": those reaching out of the cube, \"sigma\",\n"
    "      \"rate\": sigma r^d, \"interior_bound\", \"interior_samples_for_target\": the handout's\n"
    "      n = ln(m / p) / (sigma r^d) at which interior_bound reaches p, \"failure_bound\",\n"
    "      \"vacuous\", \"samples_for_target\": the n at which failure_bound reaches p, \"target\"}\n"
    "The failure bound is not clamped to 1: a value above 1 is reported as vacuous.\n",
    run_bound};

}  // namespace csl::cli
