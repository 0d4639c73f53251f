#include "app/prm_controls.hpp"

#include <cmath>
#include <stdexcept>

#include "app/js_api.hpp"
#include "imgui.h"

namespace csl::app {

bool prm_controls(PrmParams& p, int max_samples) {
  bool changed = false;
  ImGui::PushItemWidth(-90.0f);
  changed |= ImGui::SliderInt("samples n", &p.samples, 0, max_samples, "%d", ImGuiSliderFlags_Logarithmic);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("how many configurations to draw (only free ones are kept)");

  int rule = static_cast<int>(p.neighbors.kind);
  const char* rules[] = {"k nearest", "within radius r", "PRM*: k(n)"};
  if (ImGui::Combo("close =", &rule, rules, 3)) {
    p.neighbors.kind = static_cast<NeighborRule::Kind>(rule);
    changed = true;
  }
  if (p.neighbors.kind == NeighborRule::Kind::Nearest)
    changed |= ImGui::SliderInt("k", &p.neighbors.k, 1, 50);
  if (p.neighbors.kind == NeighborRule::Kind::Radius) {
    float r = static_cast<float>(p.neighbors.radius);
    if (ImGui::SliderFloat("r", &r, 0.01f, 1.0f, "%.3f", ImGuiSliderFlags_Logarithmic)) {
      p.neighbors.radius = static_cast<double>(r);
      changed = true;
    }
  }
  if (p.neighbors.kind == NeighborRule::Kind::PrmStar)
    ImGui::TextDisabled("k(n) = ceil(e (1 + 1/d) ln n)");

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
    changed |= ImGui::SliderInt("N", &p.checker.resolution, 2, 200, "%d", ImGuiSliderFlags_Logarithmic);
  if (p.checker.kind == EdgeCheckerSpec::Kind::Step) {
    float d = static_cast<float>(p.checker.step);
    if (ImGui::SliderFloat("D", &d, 0.001f, 0.5f, "%.4f", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp)) {
      p.checker.step = static_cast<double>(d);
      changed = true;
    }
  }

  int seed = static_cast<int>(p.seed);
  if (ImGui::InputInt("seed", &seed)) {
    p.seed = static_cast<std::uint64_t>(std::max(seed, 0));
    changed = true;
  }
  ImGui::PopItemWidth();
  p.checker.resolution = std::max(p.checker.resolution, 2);
  return changed;
}

nlohmann::json prm_params_json(const PrmParams& p) {
  return {{"samples", p.samples}, {"neighbors", p.neighbors.name()}, {"checker", p.checker.name()}, {"seed", p.seed}};
}

PrmParams prm_params_from_json(const nlohmann::json& j, PrmParams p, int max_samples) {
  if (!j.is_object()) throw ApiError("params must be an object");
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string& key = it.key();
    const nlohmann::json& v = it.value();
    try {
      if (key == "samples") {
        if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() > max_samples)
          throw ApiError("samples: an integer in [0, " + std::to_string(max_samples) + "]");
        p.samples = v.get<int>();
      } else if (key == "neighbors") {
        if (!v.is_string()) throw ApiError("neighbors: \"k:K\", \"radius:R\" or \"prm*\"");
        p.neighbors = NeighborRule::parse(v.get<std::string>());
      } else if (key == "checker") {
        if (!v.is_string()) throw ApiError("checker: \"bisection\" or \"grid:N\"");
        p.checker = EdgeCheckerSpec::parse(v.get<std::string>());
      } else if (key == "seed") {
        if (!v.is_number_integer() || v.get<long long>() < 0) throw ApiError("seed: an integer >= 0");
        p.seed = v.get<std::uint64_t>();
      } else {
        throw ApiError("unknown parameter \"" + key + "\"");
      }
    } catch (const std::invalid_argument& e) {
      throw ApiError(key + ": " + e.what());
    }
  }
  return p;
}

}  // namespace csl::app
