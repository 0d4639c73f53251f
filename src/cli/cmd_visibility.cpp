// cspacelab visibility: P9's probability of seeing a random configuration through the gap.
#include <stdexcept>

#include "cli/commands.hpp"
#include "core/teaching/analysis.hpp"

namespace csl::cli {
namespace {

nlohmann::json ray_json(const P9Ray& r) {
  return {{"start", r.start}, {"slope", r.slope}, {"exit", p9_exit_name(r.exit)},
          {"exit_x", r.exit_x}, {"exit_y", r.exit_y}, {"area_under", r.area_under}};
}

// P9 by cases: which edges the cone's rays leave through, and the areas that make up p.
nlohmann::json breakdown_json(const P9Breakdown& b) {
  return {{"case", b.case_name}, {"upper", ray_json(b.upper)}, {"lower", ray_json(b.lower)},
          {"left_area", b.left_area}, {"right_area", b.right_area}, {"probability", b.probability}};
}

int run_visibility(Args& args, std::ostream& os) {
  const auto x = args.take("x"), y = args.take("y"), gap = args.take("gap");
  const auto trials = args.take("trials"), seed = args.take("seed");
  args.finish();
  auto need = [](const std::optional<std::string>& v, const char* flag) {
    if (!v) throw UsageError(std::string("missing --") + flag);
    return *v;
  };
  const double x1 = parse_number(need(x, "x"), "--x"), y1 = parse_number(need(y, "y"), "--y");
  const double d = parse_number(need(gap, "gap"), "--gap");
  const auto t = static_cast<long long>(trials ? parse_param(*trials, kVisibilityTrials) : kVisibilityTrials.def);
  Rng rng(static_cast<std::uint64_t>(seed ? parse_param(*seed, kSeed) : kSeed.def));
  try {
    const double exact = visibility_probability(x1, y1, d);
    const nlohmann::json cases = breakdown_json(p9_breakdown(x1, y1, d));
    if (t == 0) {  // the exact value alone: no estimate from no samples
      print_json(os, {{"exact", exact}, {"monte_carlo", nullptr}, {"trials", 0}, {"ci_low", nullptr},
                      {"ci_high", nullptr}, {"within_ci", nullptr}, {"breakdown", cases}});
      return 0;
    }
    const Proportion mc = visibility_monte_carlo(x1, y1, d, t, rng);
    print_json(os, {{"exact", exact},
                    {"monte_carlo", mc.estimate},
                    {"trials", t},
                    {"ci_low", mc.low},
                    {"ci_high", mc.high},
                    {"within_ci", exact >= mc.low && exact <= mc.high},
                    {"breakdown", cases}});
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  return 0;
}

}  // namespace

const Command kVisibilityCommand{
    "visibility", "P9: probability that a random configuration is visible through the gap",
    "Usage: cspacelab visibility --x X --y Y --gap d [--trials T] [--seed S]\n\n" +
    option_help(kVisibilityTrials, "T") + option_help(kSeed, "S") + "\n"
    "Q = [0,1]^2 with a wall of zero thickness at x = 1/2 and an opening of height d centred at\n"
    "y = 1/2. From (X, Y), X < 1/2, the whole left half is visible, and of the right half the\n"
    "part inside the cone through the opening (clipped to the square, whichever edges it meets).\n"
    "  -> {\"exact\": p, \"monte_carlo\": p^ from T uniform samples,\n"
    "      \"trials\": T, \"ci_low\", \"ci_high\": its 95% Wilson interval, \"within_ci\": bool}\n"
    "With --trials 0 the exact value alone: the Monte Carlo fields are null.\n"
    "  \"breakdown\": the exact value by cases, {\"case\": \"<upper exit>/<lower exit>\", \"upper\",\n"
    "      \"lower\": the rays from (X, Y) through the opening's ends (1/2, 1/2 +- d/2), each\n"
    "      {\"start\": a, its height at x = 1/2, \"slope\": s, \"exit\": \"top\" | \"right edge\" |\n"
    "      \"bottom\", where it leaves the right half, \"exit_x\", \"exit_y\", \"area_under\": the area\n"
    "      of the right half below it: (a + e)/4 with e = a + s/2 (right edge), 1/2 - (1-a)^2/(2s)\n"
    "      (top), a^2/(2|s|) (bottom)}, \"left_area\": 1/2, \"right_area\": upper minus lower\n"
    "      area_under, \"probability\": their sum, the exact value}\n",
    run_visibility};

}  // namespace csl::cli
