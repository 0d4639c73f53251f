#include "core/teaching/state_condition.hpp"

#include <cmath>
#include <exception>

#include "core/base/text.hpp"

namespace csl {

using json = nlohmann::json;

namespace {

// A JSON value as a message quotes it: short, one line.
std::string shown(const json& v) { return printable(v.dump(), 40); }

bool finite_number(const json& v) { return v.is_number() && std::isfinite(v.get<double>()); }

// RFC 6901 by hand (nlohmann's json_pointer throws on syntax, and a message should say why).
std::string pointer_problem(const std::string& p) {
  if (p.size() > kMaxPointerLength) return "at most " + std::to_string(kMaxPointerLength) + " characters";
  if (!p.empty() && p[0] != '/') return "a JSON pointer starts with '/' (\"/solved\"), got \"" + printable(p, 40) + "\"";
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p[i] == '~' && (i + 1 == p.size() || (p[i + 1] != '0' && p[i + 1] != '1')))
      return "'~' is written ~0 and '/' inside a name ~1 (RFC 6901), in \"" + printable(p, 40) + "\"";
  return "";
}

void parse_into(const json& j, const std::string& where, int depth, std::vector<std::string>& errors,
                StateCondition& out) {
  const auto error = [&](const std::string& what) { errors.push_back(where + ": " + what); };
  if (!j.is_object()) return error("a condition is an object ({\"pointer\": ...}, {\"all\": [...]} or {\"any\": [...]}), got " + shown(j));
  const bool all = j.contains("all"), any = j.contains("any");
  if (all || any) {
    if (all && any) return error("\"all\" or \"any\", not both");
    const char* key = all ? "all" : "any";
    out.op = all ? StateCondition::Op::All : StateCondition::Op::Any;
    for (auto it = j.begin(); it != j.end(); ++it)
      if (it.key() != key) error("unknown field \"" + printable(it.key(), 40) + "\" beside \"" + key + "\"");
    if (depth >= kMaxConditionDepth)
      return error("at most " + std::to_string(kMaxConditionDepth) + " levels of all/any");
    const json& terms = j[key];
    if (!terms.is_array() || terms.empty() || terms.size() > kMaxConditionTerms)
      return error(std::string(key) + ": a list of 1 to " + std::to_string(kMaxConditionTerms) + " conditions");
    out.terms.resize(terms.size());
    for (std::size_t i = 0; i < terms.size(); ++i)
      parse_into(terms[i], where + "." + key + "[" + std::to_string(i) + "]", depth + 1, errors, out.terms[i]);
    return;
  }
  out.op = StateCondition::Op::Compare;
  for (auto it = j.begin(); it != j.end(); ++it)
    if (it.key() != "pointer" && it.key() != "equals" && it.key() != "min" && it.key() != "max")
      error("unknown field \"" + printable(it.key(), 40) + "\" (pointer, equals, min, max; or all, any)");
  if (!j.contains("pointer") || !j["pointer"].is_string()) {
    error("pointer: a JSON pointer into the lesson's state, e.g. \"/solved\"");
  } else {
    out.pointer = j["pointer"].get<std::string>();
    if (std::string p = pointer_problem(out.pointer); !p.empty()) error("pointer: " + p);
  }
  const bool has_equals = j.contains("equals"), has_min = j.contains("min"), has_max = j.contains("max");
  if (!has_equals && !has_min && !has_max) return error("a comparison: equals, min or max");
  if (has_equals && (has_min || has_max)) return error("equals, or min and max: not both");
  if (has_equals) {
    const json& v = j["equals"];
    if (v.is_object() || v.is_array() || v.is_binary() || (v.is_number() && !finite_number(v)))
      return error("equals: a string, a number, true, false or null, got " + shown(v));
    out.equals = v;
  }
  for (const char* bound : {"min", "max"}) {
    if (!j.contains(bound)) continue;
    const json& v = j[bound];
    if (!finite_number(v)) {
      error(std::string(bound) + ": a finite number, got " + shown(v));
      continue;
    }
    (bound[1] == 'i' ? out.min : out.max) = v.get<double>();
  }
  if (out.min && out.max && *out.min > *out.max)
    error("min " + significant(*out.min, 6) + " is more than max " + significant(*out.max, 6));
}

// A pointer in words for the student who reads the check: "/params/samples" is "the parameter
// samples", "/path_length" "path length", "" "the state" (its segments, so an instructor still
// sees which field).
std::string where_text(const std::string& pointer) {
  if (pointer.empty()) return "the state";
  std::vector<std::string> parts(1);
  for (std::size_t i = 1; i < pointer.size(); ++i) {
    if (pointer[i] == '/') parts.emplace_back();
    else if (pointer[i] == '~' && i + 1 < pointer.size()) parts.back() += pointer[++i] == '1' ? '/' : '~';
    else parts.back() += pointer[i] == '_' ? ' ' : pointer[i];
  }
  for (const std::string& part : parts)
    if (part.empty()) return pointer;  // "/", "/params/": no words for an empty name
  std::string out = parts.size() > 1 && parts[0] == "params" ? "the parameter" : "";
  for (std::size_t i = out.empty() ? 0 : 1; i < parts.size(); ++i) out += (out.empty() ? "" : " ") + parts[i];
  return out;
}

std::string compare_text(const StateCondition& c) {
  const std::string p = where_text(c.pointer);
  if (c.equals) return p + " is " + c.equals->dump();
  if (c.min && c.max) return p + " is in [" + significant(*c.min, 6) + ", " + significant(*c.max, 6) + "]";
  if (c.min) return p + " is at least " + significant(*c.min, 6);
  return p + " is at most " + significant(*c.max, 6);
}

bool evaluate_into(const StateCondition& c, const json& state, std::vector<std::string>& lines) {
  if (c.op != StateCondition::Op::Compare) {
    // Every term is evaluated (no short cut): the explanation lists each comparison.
    bool all = true, any = false;
    for (const StateCondition& t : c.terms) {
      const bool met = evaluate_into(t, state, lines);
      all = all && met;
      any = any || met;
    }
    return c.op == StateCondition::Op::All ? all : any;
  }
  const std::string p = where_text(c.pointer);
  const json* v = nullptr;
  try {
    const json::json_pointer ptr(c.pointer);
    if (state.contains(ptr)) v = &state.at(ptr);
  } catch (const std::exception&) {
    v = nullptr;  // e.g. "/a/01" into an array: not there
  }
  const std::string wanted = compare_text(c);
  if (!v) {
    lines.push_back("no: " + p + " is not in the state (wanted: " + wanted + ")");
    return false;
  }
  bool met = false;
  if (c.equals) {
    met = *v == *c.equals;
  } else if (finite_number(*v)) {
    const double x = v->get<double>();
    met = (!c.min || x >= *c.min) && (!c.max || x <= *c.max);
  }
  lines.push_back(std::string(met ? "yes" : "no") + ": " + p + " is " + shown(*v) + " (wanted: " + wanted + ")");
  return met;
}

}  // namespace

std::optional<StateCondition> parse_state_condition(const json& j, const std::string& where,
                                                    std::vector<std::string>& errors) {
  const std::size_t before = errors.size();
  StateCondition c;
  parse_into(j, where, 0, errors, c);
  if (errors.size() != before) return std::nullopt;
  return c;
}

json state_condition_to_json(const StateCondition& c) {
  if (c.op != StateCondition::Op::Compare) {
    json terms = json::array();
    for (const StateCondition& t : c.terms) terms.push_back(state_condition_to_json(t));
    return {{c.op == StateCondition::Op::All ? "all" : "any", terms}};
  }
  json out{{"pointer", c.pointer}};
  if (c.equals) out["equals"] = *c.equals;
  if (c.min) out["min"] = *c.min;
  if (c.max) out["max"] = *c.max;
  return out;
}

std::string state_condition_text(const StateCondition& c) {
  if (c.op == StateCondition::Op::Compare) return compare_text(c);
  std::string out;
  const char* joint = c.op == StateCondition::Op::All ? " and " : " or ";
  for (const StateCondition& t : c.terms) {
    const std::string inner = state_condition_text(t);
    out += (out.empty() ? "" : joint) + (t.op == StateCondition::Op::Compare ? inner : "(" + inner + ")");
  }
  return out;
}

ConditionResult evaluate_state_condition(const StateCondition& c, const json& state) {
  ConditionResult r;
  r.met = evaluate_into(c, state, r.lines);
  return r;
}

}  // namespace csl
