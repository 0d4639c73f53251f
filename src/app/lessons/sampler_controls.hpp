#pragma once
// PRM's sampler (core/planning/sampler.hpp) as a lesson parameter: a choice of the four samplers
// and, for Gaussian and bridge, a sigma slider; as JSON, the CLI's spelling ("bridge:0.05").
// Shared by Step PRM and each PRM side of Compare planners, so that both take, refuse and say
// the same.
#include <nlohmann/json.hpp>

#include <string>

#include "app/shell/param_fields.hpp"
#include "core/planning/sampler.hpp"

namespace csl::app {

/// The combo and, for gaussian and bridge, the sigma slider (kLabSamplerSigma), disabled while
/// the instructor fixed `key`. True if `spec` changed.
bool sampler_controls(SamplerSpec& spec, const char* key);

/// `v` as a sampler the lab takes: a string SamplerSpec::parse reads, with sigma within
/// kLabSamplerSigma; otherwise ApiError "KEY: ..." in one line.
SamplerSpec sampler_from_json(const std::string& key, const nlohmann::json& v);

/// The field for the page's native controls (a text field with the syntax as its help).
ParamField sampler_field(const char* key, const char* label);

/// What the sampler does, in one sentence for the panel.
const char* sampler_summary(const SamplerSpec& spec);

/// Whether the sampler throws draws away that were not in collision (Gaussian, bridge): the
/// lessons then draw every rejected draw, since those show where the sampler does not keep.
bool sampler_rejects_free_draws(const SamplerSpec& spec);

}  // namespace csl::app
