#include "app/shell/param_fields.hpp"

#include <cmath>

namespace csl::app {

using json = nlohmann::json;

namespace {

json bound(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json describe(const std::string& key, const json& value, const ParamField* field) {
  json out{{"name", key},
           {"label", field ? field->label : key},
           {"min", nullptr},
           {"max", nullptr},
           {"step", nullptr},
           {"unit", ""},
           {"help", field ? field->help : ""},
           {"value", value}};
  if (field && field->spec) {
    const ParamSpec& s = *field->spec;
    out["kind"] = s.integer ? "integer" : "number";
    out["min"] = bound(s.min);
    out["max"] = bound(s.max);
    out["step"] = s.step;
    out["unit"] = s.unit;
    out["help"] = std::string(s.help) + " (" + range_text(s) + (*s.where ? std::string(" ") + s.where : "") + ")";
    if (value.is_array()) {  // a list of values of the spec (sample_counts)
      out["kind"] = "text";
      out["list"] = true;
    }
  } else if (field && !field->choices.empty()) {
    out["kind"] = "choice";
    out["choices"] = field->choices;
  } else if (value.is_boolean()) {
    out["kind"] = "boolean";
  } else if (value.is_number_integer()) {
    out["kind"] = "integer";
    out["step"] = 1;
  } else if (value.is_number()) {
    out["kind"] = "number";
  } else {
    out["kind"] = "text";
    if (value.is_array()) out["list"] = true;
  }
  return out;
}

}  // namespace

json param_specs_json(const json& params, const std::vector<ParamField>& fields) {
  json out = json::array();
  if (!params.is_object()) return out;
  for (const ParamField& f : fields)
    if (params.contains(f.name)) out.push_back(describe(f.name, params[f.name], &f));
  for (auto it = params.begin(); it != params.end(); ++it) {
    bool listed = false;
    for (const ParamField& f : fields) listed = listed || it.key() == f.name;
    if (!listed) out.push_back(describe(it.key(), it.value(), nullptr));
  }
  return out;
}

}  // namespace csl::app
