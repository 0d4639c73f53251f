#include "app/lessons/prm_controls.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>

#include "app/lessons/sampler_controls.hpp"
#include "app/shell/instructor.hpp"
#include "app/shell/js_api.hpp"
#include "app/shell/param_widgets.hpp"
#include "imgui.h"

namespace csl::app {

namespace {
// The sliders' practical ranges, within the specs' (a link or the API may set more, within the
// budgets below): k up to 50, N up to 200, D up to 0.5.
constexpr int kSliderMaxK = 50;
constexpr int kSliderMaxGridN = 200;
constexpr double kSliderMaxStep = 0.5;

// The pairs budget. A radius rule is held to it by its r (r = max_radius() itself passes, or a
// clamped r would be clamped again each frame); k up to the slider's 50 passes at any n (50 with
// kLabMaxSamples, 20000, is a hair over 1e6), more only where n is small enough (k = 1000 and
// 20000 samples, 2e7 pairs, ran the wasm out of memory; a link could ask for it).
bool over_pairs_budget(const PrmParams& p, const Space& space) {
  if (p.neighbors.kind == NeighborRule::Kind::Nearest && p.neighbors.k <= kSliderMaxK) return false;
  return !within_pairs_budget(space, p.neighbors, p.samples, kLabMaxPairs);
}
}  // namespace

double max_radius(const Space& space, int samples) { return radius_for_pairs(space, samples, kLabMaxPairs); }

bool keep_within_budget(PrmParams& p, const Space& space) {
  if (p.neighbors.kind != NeighborRule::Kind::Radius || !over_pairs_budget(p, space)) return false;
  p.neighbors.radius = max_radius(space, p.samples);
  return true;
}

std::string prm_budget_problem(const PrmParams& p, const CollisionWorld& world) {
  const Space& space = world.space();
  char text[400];
  if (over_pairs_budget(p, space)) {
    if (p.neighbors.kind == NeighborRule::Kind::Radius) {
      std::snprintf(text, sizeof text,
                    "neighbors: radius:%g with %d samples means about %.0f candidate pairs; the lab checks at most "
                    "%.0f (r at most %s with this n)",
                    p.neighbors.radius, p.samples, expected_candidate_pairs(space, p.neighbors, p.samples), kLabMaxPairs,
                    radius_for_pairs_text(space, p.samples, kLabMaxPairs).c_str());
    } else {
      std::snprintf(text, sizeof text,
                    "neighbors: %s with %d samples means about %.0f candidate pairs; the lab checks at most %.0f "
                    "(take fewer samples or at most k:%d)",
                    p.neighbors.name().c_str(), p.samples, expected_candidate_pairs(space, p.neighbors, p.samples),
                    kLabMaxPairs, kSliderMaxK);
    }
    return text;
  }
  const WorkEstimate w = expected_prm_work(world, p);
  // One edge check is one step of the planner, which runs within a frame (PlannerSession).
  if (w.per_edge > kLabFrameWork) {
    std::snprintf(text, sizeof text,
                  "checker: one edge check with %s means about %s in this scene (one configuration costs %.0f); "
                  "the lab does at most %s at once: take a coarser checker",
                  p.checker.name().c_str(), work_text(w.per_edge).c_str(), world.evaluation_cost(),
                  work_text(kLabFrameWork).c_str());
    return text;
  }
  if (w.total() <= kLabMaxWork) return "";
  std::snprintf(text, sizeof text,
                "%d samples with %s and %s mean about %s of work in this scene (one configuration costs %.0f); the "
                "lab takes at most %s: take fewer samples, fewer neighbours or a coarser checker",
                p.samples, p.neighbors.name().c_str(), p.checker.name().c_str(), work_text(w.total()).c_str(),
                world.evaluation_cost(), work_text(kLabMaxWork).c_str());
  return text;
}

std::string scene_budget_problem(PrmParams params, const Scene& scene) {
  const CollisionWorld world(scene);
  keep_within_budget(params, world.space());
  const std::string why = prm_budget_problem(params, world);
  return why.empty() ? why : "with these parameters this scene is too much for the lab: " + why;
}

bool prm_controls(PrmParams& p, const CollisionWorld& world, LabContext& ctx, const ParamSpec& samples,
                  bool with_sampler, bool with_neighbors) {
  const Space& space = world.space();
  const PrmParams before = p;
  bool changed = false;
  ImGui::PushItemWidth(-90.0f);
  {
    instructor::FixedParam fixed("samples");
    changed |= param_slider(samples, "samples n", p.samples, static_cast<int>(samples.min), static_cast<int>(samples.max));
  }
  // Where the n samples come from (a bridge draw tests up to three configurations: priced below).
  if (with_sampler) changed |= sampler_controls(p.sampler, "sampler");
  // Each parameter's widgets disabled while the instructor fixed it (instructor.hpp).
  std::optional<instructor::FixedParam> fixed;
  if (with_neighbors) {
    fixed.emplace("neighbors");
    int rule = static_cast<int>(p.neighbors.kind);
    const char* rules[] = {"k nearest", "within radius r", "PRM*: k(n)"};
    if (ImGui::Combo("close =", &rule, rules, 3)) {
      p.neighbors.kind = static_cast<NeighborRule::Kind>(rule);
      changed = true;
    }
    if (p.neighbors.kind == NeighborRule::Kind::Nearest)
      changed |= param_slider(kNeighborK, "k", p.neighbors.k, static_cast<int>(kNeighborK.min), kSliderMaxK);
    if (p.neighbors.kind == NeighborRule::Kind::Radius) {
      // The slider ends where the pairs budget does; a float rounded up must not pass it.
      // (A workspace so small that the float is 0 still gets a slider with a positive range.)
      const float most = std::clamp(std::nextafter(static_cast<float>(max_radius(space, p.samples)), 0.0f),
                                    std::numeric_limits<float>::min(), 1.0f);
      const float least = std::min(0.01f, most / 10.0f);
      float r = static_cast<float>(p.neighbors.radius);
      if (ImGui::SliderFloat("r", &r, least, most, "%.3f", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp)) {
        p.neighbors.radius = static_cast<double>(r);
        changed = true;
      }
      if (most < 1.0f) {
        ImGui::TextDisabled("r ≤ %.3f at n = %d (the lab's limit)", static_cast<double>(most), p.samples);
        if (ImGui::IsItemHovered())
          ImGui::SetTooltip("Pairs within r grow with n^2. The lab checks at most about %.0f pairs per run,\n"
                            "so that a run takes seconds, not minutes and gigabytes.",
                            kLabMaxPairs);
      }
    }
    if (p.neighbors.kind == NeighborRule::Kind::PrmStar)
      ImGui::TextDisabled("k(n) = ceil(e (1 + 1/d) ln n)");
  }
  fixed.emplace("checker");

  // The three checkers of the CLI (a share link or the page's API may set any of them).
  int checker = p.checker.kind == EdgeCheckerSpec::Kind::Bisection ? 0
                : p.checker.kind == EdgeCheckerSpec::Kind::Grid    ? 1
                                                                   : 2;
  const char* checkers[] = {"bisection (exact)", "grid: N configurations", "step: at most D apart"};
  if (ImGui::Combo("edges", &checker, checkers, 3)) {
    p.checker = EdgeCheckerSpec::parse(checker == 0 ? "bisection" : checker == 1 ? "grid:5" : "step:0.02");
    changed = true;
  }
  if (p.checker.kind == EdgeCheckerSpec::Kind::Grid)
    changed |= param_slider(kCheckerGridN, "N", p.checker.resolution, static_cast<int>(kCheckerGridN.min),
                            kSliderMaxGridN);
  if (p.checker.kind == EdgeCheckerSpec::Kind::Step)
    changed |= param_slider(kLabCheckerStepD, "D", p.checker.step, kLabCheckerStepD.min, kSliderMaxStep, "%.4f",
                            ImGuiSliderFlags_AlwaysClamp);
  fixed.emplace("seed");
  changed |= param_input(kSeed, "seed", p.seed);
  fixed.reset();
  ImGui::PopItemWidth();
  p.checker.resolution = std::max(p.checker.resolution, 2);
  changed |= keep_within_budget(p, space);  // more samples may have made r too large
  if (changed) {
    // Past the work budget (many samples, a fine checker, a heavy scene): the change is undone.
    if (const std::string why = prm_budget_problem(p, world); !why.empty()) {
      p = before;
      ctx.notify(why, 8);
      return false;
    }
  }
  return changed;
}

nlohmann::json prm_params_json(const PrmParams& p) {
  return {{"samples", p.samples}, {"neighbors", p.neighbors.name()}, {"checker", p.checker.name()}, {"seed", p.seed}};
}

nlohmann::json take_prm_params(nlohmann::json& j) {
  nlohmann::json out = nlohmann::json::object();
  for (const char* key : {"samples", "neighbors", "checker", "seed"})
    if (j.contains(key)) {
      out[key] = j.at(key);
      j.erase(key);
    }
  return out;
}

PrmParams prm_params_from_json(const nlohmann::json& j, PrmParams p, const CollisionWorld& world,
                               const ParamSpec& samples) {
  if (!j.is_object()) throw ApiError("params must be an object");
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string& key = it.key();
    const nlohmann::json& v = it.value();
    try {
      if (key == "samples") {
        // The lesson's budget alone (within the CLI's range): one error, the bound that holds here.
        p.samples = static_cast<int>(api_param(samples, v));
      } else if (key == "neighbors") {
        if (!v.is_string()) throw ApiError("neighbors: \"k:K\", \"radius:R\" or \"prm*\"");
        p.neighbors = NeighborRule::parse(v.get<std::string>());
      } else if (key == "checker") {
        if (!v.is_string()) throw ApiError("checker: \"bisection\", \"grid:N\" or \"step:D\"");
        p.checker = EdgeCheckerSpec::parse(v.get<std::string>());
        if (p.checker.kind == EdgeCheckerSpec::Kind::Step && !in_range(kLabCheckerStepD, p.checker.step))
          throw ApiError("checker: D must be at least " + param_value_text(kLabCheckerStepD, kLabCheckerStepD.min) +
                         " in the lab");
      } else if (key == "seed") {
        // Wider than kSeed (any 64-bit integer >= 0): the API took these before the spec, and a
        // contract is not narrowed. Past 2^53 a seed does not survive JavaScript's numbers.
        if (!v.is_number_integer() || v.get<long long>() < 0) throw ApiError("seed: an integer >= 0");
        p.seed = v.get<std::uint64_t>();
      } else {
        throw ApiError("unknown parameter \"" + key + "\"");
      }
    } catch (const std::invalid_argument& e) {
      throw ApiError(key + ": " + e.what());
    }
  }
  if (const std::string why = prm_budget_problem(p, world); !why.empty()) throw ApiError(why);
  return p;
}

std::vector<ParamField> prm_param_fields(const ParamSpec& samples) {
  return {{"samples", "samples n", &samples},
          {"neighbors", "neighbour rule", nullptr, {}, "k:K (the K nearest), radius:R (all within R) or prm*"},
          {"checker", "edge checker", nullptr, {}, "bisection, grid:N (N configurations) or step:D (spacing D)"},
          {"seed", "seed", &kSeed}};
}

}  // namespace csl::app
