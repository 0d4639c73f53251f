#include "app/lessons/sampler_controls.hpp"

#include <stdexcept>

#include "app/shell/instructor.hpp"
#include "app/shell/js_api.hpp"
#include "app/shell/param_widgets.hpp"
#include "imgui.h"

namespace csl::app {
namespace {

using Kind = SamplerSpec::Kind;

bool spreads(Kind k) { return k == Kind::Gaussian || k == Kind::Bridge; }

// The slider's practical end: half the unit square's side (a link may set up to the spec's 1).
constexpr double kSliderMaxSigma = 0.5;

}  // namespace

bool sampler_rejects_free_draws(const SamplerSpec& spec) { return spreads(spec.kind); }

bool sampler_controls(SamplerSpec& spec, const char* key) {
  instructor::FixedParam fixed(key);
  bool changed = false;
  int kind = static_cast<int>(spec.kind);
  const char* kinds[] = {"uniform", "Gaussian", "bridge test", "Halton"};
  if (ImGui::Combo("sampler", &kind, kinds, 4) && kind != static_cast<int>(spec.kind)) {
    spec.kind = static_cast<Kind>(kind);
    // Gaussian and bridge keep the sigma the other had; from uniform or Halton, the default.
    if (spreads(spec.kind) && !in_range(kLabSamplerSigma, spec.sigma)) spec.sigma = kLabSamplerSigma.def;
    if (!spreads(spec.kind)) spec.sigma = 0.0;
    // A bridge alone rarely connects start and goal (sampler.hpp): it starts as Hsu et al.'s
    // hybrid, and the student can slide the uniform share to 0 to see why.
    spec.uniform_share = spec.kind == Kind::Bridge ? kLabSamplerUniformShare.def : 0.0;
    changed = true;
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", sampler_summary(spec));
  if (spreads(spec.kind)) {
    changed |= param_slider(kLabSamplerSigma, "σ", spec.sigma, kLabSamplerSigma.min, kSliderMaxSigma, "%.3f");
    changed |= param_slider(kLabSamplerUniformShare, "uniform share", spec.uniform_share, kLabSamplerUniformShare.min,
                            kLabSamplerUniformShare.max, "%.2f");
  }
  return changed;
}

SamplerSpec sampler_from_json(const std::string& key, const nlohmann::json& v) {
  if (!v.is_string())
    throw ApiError(key + ": \"uniform\", \"gaussian:S\", \"bridge:S\" or \"halton\" (a hybrid adds a uniform share: \"bridge:S,uniform:W\")");
  SamplerSpec spec;
  try {
    spec = SamplerSpec::parse(v.get<std::string>());
  } catch (const std::invalid_argument& e) {
    throw ApiError(key + ": " + e.what());
  }
  if (spreads(spec.kind) && !in_range(kLabSamplerSigma, spec.sigma))
    throw ApiError(key + ": " + param_error(kLabSamplerSigma));
  if (!in_range(kLabSamplerUniformShare, spec.uniform_share))
    throw ApiError(key + ": " + param_error(kLabSamplerUniformShare));
  return spec;
}

ParamField sampler_field(const char* key, const char* label) {
  static const std::string help =
      "uniform, gaussian:S, bridge:S or halton (S, sigma: " + range_text(kLabSamplerSigma) +
      " in the lab); a hybrid adds a uniform share, gaussian:S,uniform:W or bridge:S,uniform:W (W: " +
      range_text(kLabSamplerUniformShare) + ")";
  return {key, label, nullptr, {}, help.c_str()};
}

const char* sampler_summary(const SamplerSpec& spec) {
  switch (spec.kind) {
    case Kind::Uniform:
      return "Uniform: every point of the square is as likely as any other, so a narrow passage gets "
             "samples only in proportion to its small area.";
    case Kind::Gaussian:
      return "Gaussian: a uniform point and a second one about σ from it; when exactly one of the two is "
             "free, that one is kept, so samples gather along the obstacles' edges.";
    case Kind::Bridge:
      return spec.uniform_share > 0.0
                 ? "Bridge test: two points about σ apart that both lie in obstacles; their midpoint is kept if "
                   "it is free, which happens mostly in narrow passages. A share of the draws are uniform ones, "
                   "which cover the open space where start and goal are."
                 : "Bridge test alone: its points lie in narrow passages only, so start and goal, out in the "
                   "open, rarely see one and the roadmap stays in pieces. Give it a uniform share.";
    case Kind::Halton:
      return "Halton: a fixed sequence that spreads its points evenly over the square, without the clumps "
             "and holes of random draws; the seed does not change it.";
  }
  return "";
}

}  // namespace csl::app
