#pragma once
// A lesson's parameters described for the page's native controls (web/lab-access.js, through
// the API's "param_specs"): each key of Lesson::params() with its kind, range, step, unit and
// help. Where the lesson names a ParamSpec (core/base/params.hpp) for the key, everything comes
// from that one description, the one the ImGui slider, set_params' check and the CLI's --help
// read; a key without one gets its kind from its JSON value and no invented range.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "core/base/params.hpp"

namespace csl::app {

struct ParamField {
  const char* name;                      ///< the key of params()/set_params
  const char* label;                     ///< what the control is called ("samples n")
  const ParamSpec* spec = nullptr;       ///< its range, step, unit and help, if it has one
  std::vector<std::string> choices = {}; ///< a string that takes one of these
  const char* help = "";                 ///< without a spec: one line of help (its syntax)
};

/// [{name, label, kind, min, max, step, unit, help, value, choices?}] for every key of `params`
/// (fields' order first, then the rest by name). kind: "integer" or "number" (a spec's, or a
/// JSON number's), "boolean", "choice", "text" (a string, or comma-separated numbers where the
/// value is an array: then "list": true). min, max and step are null where nothing says them; a
/// range bound that is infinite is null too.
nlohmann::json param_specs_json(const nlohmann::json& params, const std::vector<ParamField>& fields);

}  // namespace csl::app
