#pragma once
// A parameter of core/base/params.hpp as the lab shows and takes it: an ImGui control whose range,
// scale and tooltip come from its ParamSpec, and its value from the API's JSON with the spec's
// one error text. A control may show a practical part of the range ([lo, hi]); what a link or
// the API may set is the spec's range (the lab's budget specs are ParamSpec::in_lab copies).
#include <cstdint>
#include <nlohmann/json.hpp>

#include "core/base/params.hpp"
#include "imgui.h"

namespace csl::app {

/// A slider over [lo, hi] within the spec's range (logarithmic if the spec says, the spec's help
/// as its tooltip); a value typed past the slider (Ctrl+click) is kept within the spec's range.
/// `flags` adds ImGui's (AlwaysClamp where hi is a budget). True if v changed.
bool param_slider(const ParamSpec& spec, const char* label, int& v, int lo, int hi, ImGuiSliderFlags flags = 0);
bool param_slider(const ParamSpec& spec, const char* label, long long& v, long long lo, long long hi,
                  ImGuiSliderFlags flags = 0);
bool param_slider(const ParamSpec& spec, const char* label, double& v, double lo, double hi, const char* format,
                  ImGuiSliderFlags flags = 0);
/// A number field with - and + (the spec's step), kept within the spec's range: seeds.
bool param_input(const ParamSpec& spec, const char* label, std::uint64_t& v);

/// The value of `v` for the spec, or ApiError with param_error(spec): "trials: an integer in
/// [1, 100000]".
double api_param(const ParamSpec& spec, const nlohmann::json& v);

}  // namespace csl::app
