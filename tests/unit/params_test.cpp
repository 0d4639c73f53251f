// The parameters described once (core/base/params.hpp): every spec is coherent, its check accepts its
// ends and refuses just past them, and the one error text names the parameter and its range.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "core/base/params.hpp"
#include "core/checking/edge_check.hpp"
#include "core/planning/prm.hpp"

namespace {
// The value just outside an end: the next integer for an integer spec, the next double else.
double below(const csl::ParamSpec& s) { return s.integer ? s.min - 1 : std::nextafter(s.min, -csl::kInf); }
double above(const csl::ParamSpec& s) { return s.integer ? s.max + 1 : std::nextafter(s.max, csl::kInf); }
}  // namespace

TEST_CASE("every spec's default lies in its range, and min <= max") {
  for (const csl::ParamSpec* s : csl::kAllParams) {
    CAPTURE(s->name);
    CHECK(s->min <= s->max);
    CHECK(csl::in_range(*s, s->def));
    CHECK(s->step > 0);
    CHECK(std::string(s->help).size() > 10);
    CHECK(std::string(s->name).size() > 0);
  }
}

TEST_CASE("check() accepts the ends and refuses just outside them, naming the parameter") {
  for (const csl::ParamSpec* s : csl::kAllParams) {
    CAPTURE(s->name);
    if (!s->min_open) CHECK(csl::check(*s, s->min).empty());
    if (std::isfinite(s->max)) {
      CHECK(csl::check(*s, s->max).empty());
      CHECK(csl::check(*s, above(*s)) == csl::param_error(*s));
    }
    CHECK(csl::check(*s, s->min_open ? s->min : below(*s)) == csl::param_error(*s));
    CHECK(csl::param_error(*s).rfind(std::string(s->name) + ": ", 0) == 0);
    CHECK_FALSE(csl::in_range(*s, std::nan("")));
    if (s->integer) CHECK_FALSE(csl::in_range(*s, s->def + 0.5));
  }
}

TEST_CASE("the error texts read as the surfaces say them") {
  CHECK(csl::param_error(csl::kExperimentTrials) == "trials: an integer in [1, 100000]");
  CHECK(csl::param_error(csl::kLabExperimentTrials) == "trials: an integer in [1, 100000]");  // no budget: no "lab"
  CHECK(csl::param_error(csl::kLabPrmSamples) == "samples: an integer in [0, 20000] in the lab");
  CHECK(csl::param_error(csl::kTracedGridN) == "grid_n: an integer in [2, 100000]");
  CHECK(csl::param_error(csl::kMcSeed) == "mc_seed: an integer in [0, 9007199254740991]");
  CHECK(csl::range_text(csl::kCheckerStepD) == "a number > 0");
  CHECK(csl::range_text(csl::kLabCheckerStepD) == "a number >= 0.001");
  CHECK(csl::param_value_text(csl::kCheckerStepD, 0.02) == "0.02");
}

TEST_CASE("a lab budget is narrower than its contract, never wider") {
  const std::pair<const csl::ParamSpec*, const csl::ParamSpec*> pairs[] = {
      {&csl::kLabPrmSamples, &csl::kPrmSamples},
      {&csl::kLabTorusSamples, &csl::kPrmSamples},
      {&csl::kLabExperimentSamples, &csl::kExperimentSamples},
      {&csl::kLabExperimentTrials, &csl::kExperimentTrials},
      {&csl::kLabVisibilityTrials, &csl::kVisibilityTrials},
      {&csl::kLabCheckerStepD, &csl::kCheckerStepD}};
  for (const auto& pair : pairs) {
    const csl::ParamSpec* lab = pair.first;  // no structured binding: clang 14 cannot capture one
    const csl::ParamSpec* contract = pair.second;
    CAPTURE(lab->name);
    CHECK(lab->min >= contract->min);
    CHECK(lab->max <= contract->max);
    CHECK(std::string(lab->name) == contract->name);
  }
}

TEST_CASE("JSON values: integers only for integer specs, the range, the one text") {
  using nlohmann::json;
  const csl::ParamSpec& t = csl::kExperimentTrials;
  CHECK(csl::param_from_json(t, json(1)) == 1);
  CHECK(csl::param_from_json(t, json(100000)) == 100000);
  for (const json& bad : {json(0), json(100001), json(3.0), json("3"), json(nullptr), json(-1)}) {
    CAPTURE(bad.dump());
    CHECK_THROWS_WITH_AS(csl::param_from_json(t, bad), "trials: an integer in [1, 100000]", std::invalid_argument);
  }
  // Past 2^53 a JSON integer must not round onto the seed's max.
  CHECK(csl::param_from_json(csl::kSeed, json(9007199254740991ull)) == 9007199254740991.0);
  CHECK_THROWS(csl::param_from_json(csl::kSeed, json(9007199254740992ull)));
  CHECK_THROWS(csl::param_from_json(csl::kSeed, json(18446744073709551615ull)));
  CHECK(csl::param_from_json(csl::kLabCheckerStepD, json(0.25)) == 0.25);
  CHECK_THROWS(csl::param_from_json(csl::kCheckerStepD, json(0)));
}

TEST_CASE("the parsers of prm.cpp and edge_check.cpp take the specs' ranges") {
  CHECK(csl::NeighborRule::parse("k:1000").k == 1000);
  CHECK_THROWS_WITH(csl::NeighborRule::parse("k:1001"), "k must be an integer in [1, 1000]");
  CHECK(csl::EdgeCheckerSpec::parse("grid:1000000").resolution == csl::kMaxGridResolution);
  CHECK_THROWS_WITH(csl::EdgeCheckerSpec::parse("grid:1"), "checker 'grid:1': N must be an integer in [2, 1000000]");
  CHECK_THROWS_WITH(csl::EdgeCheckerSpec::parse("step:0"), "checker 'step:0': D must be a number > 0");
}
