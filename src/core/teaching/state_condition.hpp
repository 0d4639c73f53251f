#pragma once
// The condition an assignment's task checks a lab's state with: a small language over a
// lesson's state() JSON (what the page's cspacelab.state() and the lessons' API return), so that
// "find a path with at most 50 samples" is data an instructor writes, not code:
//
//   {"all": [{"pointer": "/solved", "equals": true}, {"pointer": "/params/samples", "max": 50}]}
//
// A condition is one of
//   {"pointer": P, "equals": V}            the value at P is V (a string, number, true, false or
//                                          null; numbers compare by value: 4 equals 4.0)
//   {"pointer": P, "min": A, "max": B}     the value at P is a number in [A, B]; either bound
//                                          may be left out (A, B finite numbers, A <= B)
//   {"all": [C, ...]}                      every condition holds (1 to kMaxConditionTerms)
//   {"any": [C, ...]}                      at least one holds
// P is a JSON pointer (RFC 6901: "" or "/a/b/0", "~0" for "~" and "~1" for "/"). A value that
// is not there, or is not a number where min/max ask for one, fails the condition (the
// explanation says which). Nesting is at most kMaxConditionDepth levels of all/any.
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace csl {

inline constexpr int kMaxConditionDepth = 4;
inline constexpr std::size_t kMaxConditionTerms = 20;
inline constexpr std::size_t kMaxPointerLength = 200;

struct StateCondition {
  enum class Op { All, Any, Compare };
  Op op = Op::Compare;
  std::vector<StateCondition> terms;     ///< All, Any
  std::string pointer;                   ///< Compare
  std::optional<nlohmann::json> equals;  ///< Compare: a scalar
  std::optional<double> min, max;        ///< Compare: a number's bounds
};

/// Reads a condition. Every problem goes to `errors` as "WHERE: what" (WHERE: `where` and the
/// path inside the condition, "check.all[1]: max: ..."); nullopt if there was any.
std::optional<StateCondition> parse_state_condition(const nlohmann::json& j, const std::string& where,
                                                    std::vector<std::string>& errors);

/// The condition back as JSON (what parse_state_condition reads).
nlohmann::json state_condition_to_json(const StateCondition& c);
/// The condition in words, as a student reads it: "solved is true and the parameter samples is
/// at most 50" (from {"all": [{"pointer": "/solved", "equals": true}, {"pointer":
/// "/params/samples", "max": 50}]}).
std::string state_condition_text(const StateCondition& c);

struct ConditionResult {
  bool met = false;
  /// One line per comparison, in order: "/params/samples is 80, wanted at most 50".
  std::vector<std::string> lines;
};
/// Whether `state` meets the condition. Never throws for the state (any JSON).
ConditionResult evaluate_state_condition(const StateCondition& c, const nlohmann::json& state);

}  // namespace csl
