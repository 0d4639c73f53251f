// The planner choice (core/planning/planner_choice.hpp): names parse to their planners, bad
// options are refused with the parameter's one error text, and a factory makes the planner
// named, with the options given.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/planning/lazy_prm.hpp"
#include "core/planning/planner_choice.hpp"
#include "core/planning/potential_connector.hpp"
#include "core/planning/prm.hpp"

namespace {
csl::CollisionWorld open_square() { return csl::CollisionWorld(csl::PointRobot{}, {csl::Disk{{0.5, 0.5}, 0.1}}, {0, 0}, {1, 1}); }

std::string error_of(const csl::PlannerChoice& c) {
  try {
    csl::validate(c);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("every planner's name parses back to it, and unknown names are refused naming all") {
  for (const csl::PlannerKindInfo& info : csl::planner_kinds()) {
    CAPTURE(info.name);
    CHECK(csl::parse_planner_kind(info.name) == info.kind);
    CHECK(std::string(csl::planner_kind_info(info.kind).name) == info.name);
  }
  CHECK(csl::planner_names().rfind("prm|prm-star", 0) == 0);
  try {
    csl::parse_planner_kind("PRM");
    FAIL("PRM (upper case) parsed");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()) == "unknown planner 'PRM' (" + csl::planner_names(", ") + ")");
  }
  CHECK_THROWS_AS(csl::parse_planner_kind(""), std::invalid_argument);
}

TEST_CASE("the sample budget is params.hpp's range") {
  csl::PlannerChoice c;
  CHECK(error_of(c).empty());
  c.samples = -1;
  CHECK(error_of(c) == csl::param_error(csl::kPrmSamples));
  c.samples = csl::kMaxPrmSamples + 1;
  CHECK(error_of(c) == csl::param_error(csl::kPrmSamples));
  CHECK_THROWS_AS(csl::make_planner_factory(c), std::invalid_argument);
}

TEST_CASE("prm and prm-star factories make PRM with the options given") {
  const auto world = open_square();
  csl::PlannerChoice c;
  c.samples = 50;
  c.neighbors = csl::NeighborRule::parse("k:4");
  c.seed = 9;
  auto planner = csl::make_planner_factory(c)(world, csl::config({0.1, 0.1}), csl::config({0.9, 0.9}));
  auto* prm = dynamic_cast<csl::Prm*>(planner.get());
  REQUIRE(prm != nullptr);
  CHECK(prm->params().samples == 50);
  CHECK(prm->params().neighbors.name() == "k:4");
  CHECK(prm->params().seed == 9);
  c.kind = csl::PlannerChoice::Kind::PrmStar;
  auto star = csl::make_planner_factory(c)(world, csl::config({0.1, 0.1}), csl::config({0.9, 0.9}));
  REQUIRE(dynamic_cast<csl::Prm*>(star.get()) != nullptr);
  CHECK(dynamic_cast<csl::Prm*>(star.get())->params().neighbors.name() == "prm*");
}

TEST_CASE("lazy-prm makes Lazy PRM with the sampler; the tree planners refuse a sampler") {
  const auto world = open_square();
  csl::PlannerChoice c;
  c.kind = csl::parse_planner_kind("lazy-prm");
  c.samples = 40;
  c.sampler = csl::SamplerSpec::parse("halton");
  auto planner = csl::make_planner_factory(c)(world, csl::config({0.1, 0.1}), csl::config({0.9, 0.9}));
  auto* lazy = dynamic_cast<csl::LazyPrm*>(planner.get());
  REQUIRE(lazy != nullptr);
  CHECK(lazy->params().sampler.name() == "halton");
  CHECK(lazy->params().samples == 40);
  // PRM takes the sampler too.
  c.kind = csl::PlannerChoice::Kind::Prm;
  auto prm = csl::make_planner_factory(c)(world, csl::config({0.1, 0.1}), csl::config({0.9, 0.9}));
  CHECK(dynamic_cast<csl::Prm*>(prm.get())->params().sampler.name() == "halton");
  // A tree samples uniformly; another sampler is named in the error.
  c.kind = csl::PlannerChoice::Kind::Rrt;
  CHECK(error_of(c).find("halton") != std::string::npos);
  c.sampler = csl::SamplerSpec{};
  CHECK(error_of(c).empty());
  // Lazy PRM takes no local connector.
  c.kind = csl::PlannerChoice::Kind::LazyPrm;
  c.connector = std::make_shared<const csl::PotentialConnector>();
  CHECK(error_of(c).find("connector") != std::string::npos);
}
