#include "app/shell/param_widgets.hpp"

#include <algorithm>
#include <stdexcept>

#include "app/shell/js_api.hpp"

namespace csl::app {

namespace {
ImGuiSliderFlags flags_of(const ParamSpec& spec, ImGuiSliderFlags extra) {
  return extra | (spec.logarithmic ? ImGuiSliderFlags_Logarithmic : 0);
}
void tooltip(const ParamSpec& spec) {
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s (%s)", spec.help, range_text(spec).c_str());
}
template <class T>
T within_spec(const ParamSpec& spec, T v) {
  return static_cast<T>(std::clamp(static_cast<double>(v), spec.min, spec.max));
}
}  // namespace

bool param_slider(const ParamSpec& spec, const char* label, int& v, int lo, int hi, ImGuiSliderFlags flags) {
  const bool changed = ImGui::SliderInt(label, &v, lo, hi, "%d", flags_of(spec, flags));
  tooltip(spec);
  if (changed) v = within_spec(spec, v);  // only what the user typed: a value set elsewhere stays
  return changed;
}

bool param_slider(const ParamSpec& spec, const char* label, long long& v, long long lo, long long hi,
                  ImGuiSliderFlags flags) {
  const bool changed = ImGui::SliderScalar(label, ImGuiDataType_S64, &v, &lo, &hi, "%lld", flags_of(spec, flags));
  tooltip(spec);
  if (changed) v = within_spec(spec, v);
  return changed;
}

bool param_slider(const ParamSpec& spec, const char* label, double& v, double lo, double hi, const char* format,
                  ImGuiSliderFlags flags) {
  // A float slider, as before: a double's would show digits no one drags to.
  float f = static_cast<float>(v);
  const bool changed =
      ImGui::SliderFloat(label, &f, static_cast<float>(lo), static_cast<float>(hi), format, flags_of(spec, flags));
  tooltip(spec);
  if (changed) v = within_spec(spec, static_cast<double>(f));
  return changed;
}

bool param_input(const ParamSpec& spec, const char* label, std::uint64_t& v) {
  const auto step = static_cast<std::uint64_t>(spec.step);
  std::uint64_t typed = v;
  const bool changed = ImGui::InputScalar(label, ImGuiDataType_U64, &typed, &step, nullptr, "%llu");
  tooltip(spec);
  if (!changed) return false;
  // Typed past the spec's max (or wrapped below 0 by "-"): its nearest end. A value already
  // past it (a PRM seed above 2^53 from a link: the API takes any 64-bit seed) moves by the
  // step from where it is, instead of dropping to the max and changing the roadmap.
  const auto max = static_cast<std::uint64_t>(spec.max);
  if (typed > max && v <= max) typed = v == 0 && typed == ~std::uint64_t{0} ? 0 : max;
  if (typed == v) return false;
  v = typed;
  return true;
}

double api_param(const ParamSpec& spec, const nlohmann::json& v) {
  try {
    return param_from_json(spec, v);
  } catch (const std::invalid_argument& e) {
    throw ApiError(e.what());
  }
}

}  // namespace csl::app
