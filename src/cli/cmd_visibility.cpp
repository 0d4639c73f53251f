// cspacelab visibility: P9's probability of seeing a random configuration through the gap.
#include <stdexcept>

#include "cli/commands.hpp"
#include "core/analysis.hpp"

namespace csl::cli {
namespace {

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
  const long long t = parse_count(trials.value_or("100000"), "--trials", 100000000);
  Rng rng(static_cast<std::uint64_t>(parse_count(seed.value_or("1"), "--seed", 9007199254740991LL)));
  try {
    const double exact = visibility_probability(x1, y1, d);
    if (t == 0) {  // the exact value alone: no estimate from no samples
      print_json(os, {{"exact", exact}, {"monte_carlo", nullptr}, {"trials", 0}, {"ci_low", nullptr},
                      {"ci_high", nullptr}, {"within_ci", nullptr}});
      return 0;
    }
    const Proportion mc = visibility_monte_carlo(x1, y1, d, t, rng);
    print_json(os, {{"exact", exact},
                    {"monte_carlo", mc.estimate},
                    {"trials", t},
                    {"ci_low", mc.low},
                    {"ci_high", mc.high},
                    {"within_ci", exact >= mc.low && exact <= mc.high}});
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  return 0;
}

}  // namespace

const Command kVisibilityCommand{
    "visibility", "P9: probability that a random configuration is visible through the gap",
    "Usage: cspacelab visibility --x X --y Y --gap d [--trials T] [--seed S]\n\n"
    "Q = [0,1]^2 with a wall of zero thickness at x = 1/2 and an opening of height d centred at\n"
    "y = 1/2. From (X, Y), X < 1/2, the whole left half is visible, and of the right half the\n"
    "part inside the cone through the opening (clipped to the square, whichever edges it meets).\n"
    "  -> {\"exact\": p, \"monte_carlo\": p^ from T uniform samples (default 100000, seed 1),\n"
    "      \"trials\": T, \"ci_low\", \"ci_high\": its 95% Wilson interval, \"within_ci\": bool}\n"
    "With --trials 0 the exact value alone: the Monte Carlo fields are null.\n",
    run_visibility};

}  // namespace csl::cli
