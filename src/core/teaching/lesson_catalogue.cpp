#include "core/teaching/lesson_catalogue.hpp"

#include <cmath>
#include <iterator>
#include <stdexcept>

#include "core/base/text.hpp"
#include "core/checking/edge_check.hpp"
#include "core/planning/planner_choice.hpp"
#include "core/planning/prm.hpp"
#include "core/scene/narrow_passage.hpp"
#include "core/teaching/notation.hpp"

namespace csl {

using json = nlohmann::json;
using K = LessonParamKind;

namespace {

// The notation lesson's nine practice exercises (kExercises in lesson_notation.cpp).
constexpr int kNotationExercises = 9;

// (Each lesson as data: the PRM lessons' four come first in the torus's and Step PRM's lists, as
// app/lessons/prm_controls.cpp makes them; a seed there is any 64-bit integer >= 0, wider than
// kSeed's 2^53 - 1.)
const CataloguedLesson kLessons[] = {
    {"torus",
     "2-link arm and the torus",
     {{"samples", K::Integer, &kLabTorusSamples},
      {"neighbors", K::Text, nullptr, {}, -kInf, kInf, LessonParamSyntax::NeighborRule},
      {"checker", K::Text, nullptr, {}, -kInf, kInf, LessonParamSyntax::EdgeChecker},
      {"seed", K::Integer, nullptr, {}, 0, kInf},
      {"q", K::Pair},
      {"view", K::Choice, nullptr, {"square", "torus", "both"}}},
     {"arm2"}},
    {"notation",
     "C-space notation",
     {{"description", K::Text, nullptr, {}, -kInf, kInf, LessonParamSyntax::RobotDescription},
      {"mode", K::Choice, nullptr, {"build", "practice"}},
      {"exercise", K::Integer, nullptr, {}, 0, kNotationExercises - 1}},
     {}},
    {"cspace-3d",
     "C-spaces in 3-D",
     {{"samples", K::Integer, &kLabTorusSamples},
      {"neighbors", K::Text, nullptr, {}, -kInf, kInf, LessonParamSyntax::NeighborRule},
      {"checker", K::Text, nullptr, {}, -kInf, kInf, LessonParamSyntax::EdgeChecker},
      {"seed", K::Integer, nullptr, {}, 0, kInf},
      {"planner", K::Text, nullptr, {}, -kInf, kInf, LessonParamSyntax::Planner},
      // Both of its robots have three coordinates; their ranges depend on the scene (the lab checks).
      {"q", K::NumberList, nullptr, {}, -kInf, kInf, LessonParamSyntax::None, 3},
      {"cut", K::Number, nullptr, {}, -1000, 1000},
      {"question", K::Choice, nullptr, {"name", "dimension", "glued", "seam", "free"}}},
     {"polygon", "arm"}},
    {"collision",
     "Collision checking",
     {{"grid_n", K::Integer, &kTracedGridN}, {"p", K::Pair}, {"q", K::Pair}},
     {"point", "arm2"}},
    {"compare",
     "Compare planners",
     {{"planner_a", K::Text, nullptr, {}, -kInf, kInf, LessonParamSyntax::Planner},
      {"samples_a", K::Integer, &kLabPrmSamples},
      {"goal_bias_a", K::Number, &kGoalBias},
      {"step_a", K::Number, &kTreeStep},
      {"sampler_a", K::Text, nullptr, {}, -kInf, kInf, LessonParamSyntax::Sampler},
      {"planner_b", K::Text, nullptr, {}, -kInf, kInf, LessonParamSyntax::Planner},
      {"samples_b", K::Integer, &kLabPrmSamples},
      {"goal_bias_b", K::Number, &kGoalBias},
      {"step_b", K::Number, &kTreeStep},
      {"sampler_b", K::Text, nullptr, {}, -kInf, kInf, LessonParamSyntax::Sampler},
      {"seed", K::Integer, &kSeed},
      {"passage", K::Number, &kPassageWidth},
      {"mode", K::Choice, nullptr, {"step", "experiment"}},
      {"axis", K::Choice, nullptr, {"samples", "checks"}},
      {"trials", K::Integer, nullptr, {}, 1, 100},
      {"budgets", K::IntegerList, &kLabExperimentSamples, {}, -kInf, kInf, LessonParamSyntax::None, 6}},
     {"point"}},
    {"distances",
     "Distances",
     {{"tool", K::Choice, nullptr, {"s1", "segment"}},
      {"q1", K::Number, nullptr, {}, -1000, 1000},
      {"q2", K::Number, nullptr, {}, -1000, 1000},
      {"p1", K::Pair, nullptr, {}, -1000, 1000},
      {"p2", K::Pair, nullptr, {}, -1000, 1000},
      {"q", K::Pair, nullptr, {}, -1000, 1000},
      {"r", K::Number, nullptr, {}, 0, 1000}},
     {}},
    {"analysis",
     "PRM analysis",
     {{"sample_counts", K::IntegerList, &kLabExperimentSamples, {}, -kInf, kInf, LessonParamSyntax::None,
       kLabMaxSampleCounts},
      {"trials", K::Integer, &kLabExperimentTrials},
      {"tab", K::Choice, nullptr, {"bound", "tiling", "visibility"}},
      {"point", K::Pair, nullptr, {}, 0, 1},
      {"gap", K::Number, nullptr, {}, 0, 1},
      {"mc_trials", K::Integer, &kLabVisibilityTrials},
      {"mc_seed", K::Integer, &kMcSeed},
      {"target", K::Number, nullptr, {}, 0, 1}},
     {"point", "polygon"}},
    {"potential",
     "Potential fields",
     {{"rho0", K::Number, &kFieldRho0},
      {"eta", K::Number, &kFieldEta},
      {"zeta", K::Number, &kFieldZeta},
      {"switch", K::Number, &kFieldSwitch},
      {"step", K::Number, &kDescentStep},
      {"escapes", K::Integer, &kDescentEscapes},
      {"seed", K::Integer, nullptr, {}, 0, kInf},
      {"from", K::NumberList},
      {"point", K::Integer, nullptr, {}, -1, 100000}},
     {"point", "arm2", "polygon"}},
    {"step-prm",
     "Step PRM",
     {{"samples", K::Integer, &kLabPrmSamples},
      {"neighbors", K::Text, nullptr, {}, -kInf, kInf, LessonParamSyntax::NeighborRule},
      {"checker", K::Text, nullptr, {}, -kInf, kInf, LessonParamSyntax::EdgeChecker},
      {"seed", K::Integer, nullptr, {}, 0, kInf},
      {"sampler", K::Text, nullptr, {}, -kInf, kInf, LessonParamSyntax::Sampler}},
     {"point"}},
};

// A bound as help texts print it ("0.5", "1000"): param_value_text of any real spec.
std::string plain(double v) { return param_value_text(kFieldZeta, v); }

std::string range_words(double lo, double hi, bool integer) {
  const std::string kind = integer ? "an integer" : "a number";
  const auto text = plain;
  if (std::isinf(lo) && std::isinf(hi)) return kind;
  if (std::isinf(hi)) return kind + " >= " + text(lo);
  return kind + " in [" + text(lo) + ", " + text(hi) + "]";
}

bool finite_number(const json& v) { return v.is_number() && std::isfinite(v.get<double>()); }

std::string number_problem(const LessonParam& p, const json& v, bool integer) {
  if (p.spec) {
    try {
      param_from_json(*p.spec, v);
      return "";
    } catch (const std::invalid_argument&) {
      return std::string(p.name) + ": " + range_text(*p.spec) + (*p.spec->where ? std::string(" ") + p.spec->where : "");
    }
  }
  const bool ok = (integer ? v.is_number_integer() : finite_number(v)) && v.get<double>() >= p.lo &&
                  v.get<double>() <= p.hi;
  return ok ? "" : std::string(p.name) + ": " + range_words(p.lo, p.hi, integer);
}

}  // namespace

const std::vector<CataloguedLesson>& lesson_catalogue() {
  static const std::vector<CataloguedLesson> catalogue(std::begin(kLessons), std::end(kLessons));
  return catalogue;
}

const CataloguedLesson* find_catalogued_lesson(const std::string& id) {
  for (const CataloguedLesson& l : lesson_catalogue())
    if (l.id == id) return &l;
  return nullptr;
}

std::string lesson_ids_text() {
  std::string out;
  for (const CataloguedLesson& l : lesson_catalogue()) out += (out.empty() ? "" : ", ") + std::string(l.id);
  return out;
}

std::string lesson_param_names_text(const CataloguedLesson& lesson) {
  std::string out;
  for (const LessonParam& p : lesson.params) out += (out.empty() ? "" : ", ") + std::string(p.name);
  return out;
}

std::string lesson_param_problem(const LessonParam& p, const json& v) {
  const std::string name(p.name);
  switch (p.kind) {
    case K::Integer: return number_problem(p, v, true);
    case K::Number: return number_problem(p, v, false);
    case K::Choice: {
      std::string list;
      for (const std::string_view c : p.choices) list += (list.empty() ? "" : ", ") + std::string(c);
      if (v.is_string())
        for (const std::string_view c : p.choices)
          if (v.get<std::string>() == c) return "";
      return name + ": one of " + list;
    }
    case K::Text: {
      if (!v.is_string()) return name + ": a string";
      const std::string text = v.get<std::string>();
      try {
        switch (p.syntax) {
          case LessonParamSyntax::NeighborRule: NeighborRule::parse(text); break;
          case LessonParamSyntax::EdgeChecker: {
            const EdgeCheckerSpec spec = EdgeCheckerSpec::parse(text);
            if (spec.kind == EdgeCheckerSpec::Kind::Step && !in_range(kLabCheckerStepD, spec.step))
              return name + ": D must be at least " + param_value_text(kLabCheckerStepD, kLabCheckerStepD.min) + " in the lab";
            break;
          }
          case LessonParamSyntax::RobotDescription: parse_robot_description(text); break;
          // The planners of planner_choice's table, whichever it lists (the lesson's menu too).
          case LessonParamSyntax::Planner: parse_planner_kind(text); break;
          case LessonParamSyntax::Sampler: {
            const SamplerSpec spec = SamplerSpec::parse(text);
            const bool spread = spec.kind == SamplerSpec::Kind::Gaussian || spec.kind == SamplerSpec::Kind::Bridge;
            if (spread && !in_range(kLabSamplerSigma, spec.sigma)) return name + ": " + param_error(kLabSamplerSigma);
            // The lab's slider and set_params stop at 0.9 (sampler_controls.cpp): a link must too.
            if (!in_range(kLabSamplerUniformShare, spec.uniform_share))
              return name + ": " + param_error(kLabSamplerUniformShare);
            break;
          }
          case LessonParamSyntax::None: break;
        }
      } catch (const std::exception& e) {
        return name + ": " + printable(e.what(), 200);
      }
      return "";
    }
    case K::Pair: {
      const bool ok = v.is_array() && v.size() == 2 && finite_number(v[0]) && finite_number(v[1]) &&
                      v[0].get<double>() >= p.lo && v[0].get<double>() <= p.hi && v[1].get<double>() >= p.lo &&
                      v[1].get<double>() <= p.hi;
      if (ok) return "";
      if (std::isinf(p.lo)) return name + ": [a, b], two numbers";
      return name + ": [a, b], two numbers, each in [" + plain(p.lo) + ", " + plain(p.hi) + "]";
    }
    case K::NumberList: {
      const std::size_t n = static_cast<std::size_t>(p.max_items);
      bool ok = v.is_array() && !v.empty() && v.size() <= 64 && (n == 0 || v.size() == n);
      for (std::size_t i = 0; ok && i < v.size(); ++i) ok = finite_number(v[i]);
      if (ok) return "";
      return n == 0 ? name + ": [a, b, ...], numbers" : name + ": " + std::to_string(n) + " numbers [a, b, ...]";
    }
    case K::IntegerList: {
      const std::string what = name + ": 1 to " + std::to_string(p.max_items) + " integers, each " +
                               (p.spec ? range_text(*p.spec) : range_words(p.lo, p.hi, true));
      if (!v.is_array() || v.empty() || v.size() > static_cast<std::size_t>(p.max_items)) return what;
      for (const json& item : v) {
        LessonParam one = p;
        one.kind = K::Integer;
        if (!number_problem(one, item, true).empty()) return what;
      }
      return "";
    }
  }
  return name + ": cannot be set";
}

std::string lesson_params_problem(const CataloguedLesson& lesson, const json& params) {
  if (!params.is_object()) return "the parameters must be a JSON object";
  for (auto it = params.begin(); it != params.end(); ++it) {
    const LessonParam* found = nullptr;
    for (const LessonParam& p : lesson.params)
      if (it.key() == p.name) found = &p;
    if (!found)
      return "\"" + printable(it.key(), 40) + "\" is not a parameter of " + std::string(lesson.id) + " (" +
             lesson_param_names_text(lesson) + ")";
    if (std::string problem = lesson_param_problem(*found, it.value()); !problem.empty()) return problem;
  }
  return "";
}

std::string lesson_scene_problem(const CataloguedLesson& lesson, const Scene& scene) {
  const std::string id(lesson.id);
  if (lesson.robots.size() == 0) return "the " + id + " lesson has no scene";
  const std::string type = robot_type_name(scene.robot);
  std::string list;
  for (const std::string_view r : lesson.robots) {
    if (r == type) return "";
    list += (list.empty() ? "" : ", ") + std::string(r);
  }
  return "the " + id + " lesson takes scenes with robot " + list + "; this one has '" + type + "'";
}

}  // namespace csl
