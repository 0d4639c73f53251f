#pragma once
// The lab's parameters, each described once: its name in JSON and the page's API, its CLI flag,
// its range, default, step, unit and a line of help. The ImGui controls (app/shell/param_widgets.hpp),
// the lessons' set_params, the CLI's parsing and its --help all read these, so a range cannot
// disagree between surfaces again (issue 23: trials were 1..1000 in the lab, 1..100000 in the
// CLI).
//
// A spec's range is the contract: what the CLI and the API accept. The lab's budgets (how much
// it does in a page, core/teaching/work.hpp) are separate, narrower checks: a `ParamSpec::in_lab()` copy
// whose error names the lab, or work estimates refused with their figures. A slider may show a
// narrower practical range than either.
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace csl {

struct ParamSpec {
  const char* name;   ///< as in JSON and the API ("trials"); also the error text's first word
  const char* flag;   ///< the CLI option without "--" ("trials"), "" if the CLI has none
  bool integer;       ///< an integer, or any finite number
  double min, max;    ///< inclusive (max may be infinite for a real)
  double def;         ///< the default
  double step;        ///< a step for +/- inputs
  const char* unit;   ///< "" for a pure count
  const char* help;   ///< one line, lower case, no final stop
  bool logarithmic = false;  ///< sliders spread it on a log scale
  bool min_open = false;     ///< min itself excluded (a radius, a step: > 0)
  const char* where = "";    ///< "in the lab" for a budget's narrower copy: said in its error

  /// The same parameter under a budget of the lab: a narrower [lo, hi] and the lab's default.
  constexpr ParamSpec in_lab(double lo, double hi, double lab_def) const {
    ParamSpec s = *this;
    s.min = lo;
    s.max = hi;
    s.def = lab_def;
    s.min_open = false;
    s.where = lo > min || hi < max ? "in the lab" : "";
    return s;
  }
  /// The same range under another JSON name (mc_seed is a seed).
  constexpr ParamSpec named(const char* json_name) const {
    ParamSpec s = *this;
    s.name = json_name;
    return s;
  }
};

/// "an integer in [1, 100000]", "a number > 0", "a number in [0.001, 0.5]".
std::string range_text(const ParamSpec& spec);
/// "trials: an integer in [1, 100000]" (and " in the lab" for a lab budget): the one error text.
std::string param_error(const ParamSpec& spec);
/// Whether v is in the spec's range (and an integer for an integer spec).
bool in_range(const ParamSpec& spec, double v);
/// "" if v is in range, else param_error().
std::string check(const ParamSpec& spec, double v);
/// The spec's default (or any value) as help text shows it: "200", "0.02".
std::string param_value_text(const ParamSpec& spec, double v);

/// What a JSON value for the spec is refused with: std::invalid_argument holding param_error().
/// Returns the number if it is one the spec takes (an integer spec takes JSON integers only,
/// never 3.0 or "3").
double param_from_json(const ParamSpec& spec, const nlohmann::json& v);

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// --- PRM (core/planning/prm.hpp, the Step PRM and torus lessons, cspacelab plan) ---

/// n. kMaxPrmSamples (prm.hpp) is defined as this max.
inline constexpr ParamSpec kPrmSamples{"samples", "samples", true, 0, 1000000, 200, 1, "samples",
                                       "samples drawn (only free ones are kept)", true};
/// The most samples the lab plans with: kLabMaxPairs (work.hpp) assumes it (k = 50 at 20000
/// samples is about 1e6 pairs); 1e6 samples ran the wasm out of memory.
inline constexpr int kLabMaxSamples = 20000;
inline constexpr ParamSpec kLabPrmSamples = kPrmSamples.in_lab(0, kLabMaxSamples, 200);
/// The torus lesson draws every sample on a 3-D surface each frame: fewer.
inline constexpr ParamSpec kLabTorusSamples = kPrmSamples.in_lab(0, 5000, 200);
/// K of "k:K" (NeighborRule::parse) and --k.
inline constexpr ParamSpec kNeighborK{"k", "k", true, 1, 1000, 10, 1, "vertices",
                                      "nearest vertices each vertex tries to join"};
/// N of "grid:N" (EdgeCheckerSpec::parse); kMaxGridResolution (edge_check.hpp) is defined as this max.
inline constexpr ParamSpec kCheckerGridN{"N", "", true, 2, 1000000, 5, 1, "configurations",
                                         "configurations checked along an edge, its ends included", true};
/// D of "step:D": any D > 0 (a D finer than an edge's length / 1e6 is refused per edge).
inline constexpr ParamSpec kCheckerStepD{"D", "", false, 0, kInf, 0.02, 0.001, "",
                                         "largest distance between configurations checked along an edge",
                                         true, true};
/// The lab's least D: finer steps only cost time (and the panel's slider starts there).
inline constexpr ParamSpec kLabCheckerStepD = kCheckerStepD.in_lab(0.001, kInf, 0.02);
/// Every seed: at most 2^53 - 1, so that it is exact as a JSON number in JavaScript too.
inline constexpr ParamSpec kSeed{"seed", "seed", true, 0, 9007199254740991.0, 1, 1, "",
                                 "the random generator's seed (same seed, same result everywhere)"};

/// S of the samplers gaussian:S and bridge:S (core/planning/sampler.hpp): the standard deviation of
/// the second configuration's offset from the first. The CLI takes any finite S > 0 (its
/// --sampler's contract); the lab a range that makes sense for a workspace of a few units: a
/// spread past it lands nearly every second configuration on the bounds, a finer one gives pairs
/// that are one point twice.
inline constexpr ParamSpec kSamplerSigma{"sigma", "", false, 0, kInf, 0.05, 0.005, "",
                                         "how far the second configuration of a Gaussian or bridge draw lies from "
                                         "the first (one standard deviation, in the space's metric)",
                                         true, true};
inline constexpr ParamSpec kLabSamplerSigma = kSamplerSigma.in_lab(0.001, 1, 0.05);
/// W of the hybrids gaussian:S,uniform:W and bridge:S,uniform:W: the chance that a draw is a
/// uniform one. The text's parser takes [0, 1); the lab's slider stops at 0.9, past which the
/// sampler is nearly uniform. The lab's default is for the bridge test, which alone keeps points
/// in passages only (start and goal rarely see one); Gaussian starts at 0, which works alone.
inline constexpr ParamSpec kLabSamplerUniformShare{"uniform share", "", false, 0, 0.9, 0.3, 0.05, "",
                                                   "the chance that a Gaussian or bridge draw is a uniform one instead"};

// --- tree planners (core/planning/rrt.hpp, rrt_connect.hpp; cspacelab plan --planner rrt) ---

/// B: the chance that RRT extends toward q_final instead of a uniform sample.
inline constexpr ParamSpec kGoalBias{"goal_bias", "goal-bias", false, 0, 1, 0.05, 0.01, "",
                                     "the chance of extending toward the goal instead of a sample (RRT)"};
/// D: how far one extension goes, in the space's metric; 0 picks a fifth of the space's extent
/// (tree_step(), OMPL's default for its RRTs, so that both grow alike on the same scene).
inline constexpr ParamSpec kTreeStep{"tree_step", "step", false, 0, kInf, 0, 0.01, "",
                                     "the longest extension of a tree, in the space's metric (0: a fifth of "
                                     "the space's extent; at least a thousandth of it)"};

// --- experiments (core/teaching/experiment.hpp, the PRM analysis lesson, cspacelab experiment) ---

/// T. One range for the lab and the CLI: the CLI's (a contract); the lab's earlier 1..1000 was
/// no budget, its work estimate (experiment_problem) refuses what it cannot run. The lab starts
/// at 30 runs per n, the CLI at 20 (its output's contract).
inline constexpr ParamSpec kExperimentTrials{"trials", "trials", true, 1, 100000, 20, 1, "runs",
                                             "PRM runs for each n"};
inline constexpr ParamSpec kLabExperimentTrials = kExperimentTrials.in_lab(1, 100000, 30);
/// Each n of an experiment: the CLI's --samples-list, the lesson's sample_counts.
inline constexpr ParamSpec kExperimentSamples{"sample_counts", "samples-list", true, 0, 1000000, 200, 1, "samples",
                                              "the sample counts to test, comma-separated; each n"};
/// The lab's runs are PRM runs in the page: its most samples, as Step PRM's.
inline constexpr ParamSpec kLabExperimentSamples = kExperimentSamples.in_lab(0, kLabMaxSamples, 200);
/// How many n one experiment of the lab tests (its table and plot show each).
inline constexpr int kLabMaxSampleCounts = 20;
/// M, the reference run's samples; 0 picks max(2000, 4 x the largest n).
inline constexpr ParamSpec kReferenceSamples{"reference_samples", "reference-samples", true, 0, 1000000, 0, 1,
                                             "samples", "the reference run's samples (0: max(2000, 4 x the largest n))"};

// --- P9's Monte Carlo (analysis.hpp, the lesson's visibility tab, cspacelab visibility) ---

/// T uniform samples; 0 gives the exact value alone (the CLI). The CLI's range, widened from
/// the lab's 1..1000000; the lab keeps its own budget below.
inline constexpr ParamSpec kVisibilityTrials{"mc_trials", "trials", true, 0, 100000000, 100000, 1, "samples",
                                             "uniform samples for the Monte Carlo estimate (0: the exact value alone)",
                                             true};
/// The lab draws them at once, within a frame, and always shows an estimate: 1 to 10^6.
inline constexpr ParamSpec kLabVisibilityTrials = kVisibilityTrials.in_lab(1, 1000000, 20000);
inline constexpr ParamSpec kMcSeed = kSeed.named("mc_seed");

// --- edge checking (core/checking/edge_check.hpp, the collision lesson, cspacelab check) ---

/// N of the collision lesson's grid, whose every configuration is listed (state, --trace): the
/// CLI's --trace takes at most grid:100000 too. The lab's frame budget (kLabFrameWork) is a
/// separate check: a dense scene takes fewer.
inline constexpr ParamSpec kTracedGridN{"grid_n", "", true, 2, 100000, 4, 1, "configurations",
                                        "configurations checked along the edge, p and q included", true};
/// M of --min-grid: the largest N the search tries.
inline constexpr ParamSpec kMinGridMax{"max", "max", true, 2, 100000, 1000, 1, "configurations",
                                       "the largest N --min-grid tries", true};

// --- potential fields and descent (core/fields/, the potential lesson, cspacelab potential and
// descend). Defaults are PotentialParams' and DescentParams'; the lab's sliders show a practical
// part of each range.

inline constexpr ParamSpec kFieldZeta{"zeta", "zeta", false, 0, kInf, 1.0, 0.1, "", "attractive gain", true};
inline constexpr ParamSpec kFieldSwitch{"switch", "switch", false, 0, kInf, 0.2, 0.01, "",
                                        "d: the attraction is quadratic within d of the goal, conic beyond",
                                        false, true};
inline constexpr ParamSpec kFieldEta{"eta", "eta", false, 0, kInf, 1e-4, 1e-5, "", "repulsive gain", true};
inline constexpr ParamSpec kFieldRho0{"rho0", "rho0", false, 0, kInf, 0.1, 0.01, "",
                                      "rho0: each obstacle's region of influence", false, true};
inline constexpr ParamSpec kDescentStep{"step", "step", false, 0, kInf, 0.01, 0.001, "",
                                        "alpha: the length of one descent step", true, true};
/// Random walks from local minima. One range for the lab and the CLI (the lab took 0..100, the
/// CLI 0..10000): the lab's run is bounded by its steps, not by its walks.
inline constexpr ParamSpec kDescentEscapes{"escapes", "escapes", true, 0, 10000, 0, 1, "walks",
                                           "random walks allowed from local minima (0: plain descent)"};

/// Every spec above, for tests and tools that check them all.
inline constexpr const ParamSpec* kAllParams[] = {
    &kPrmSamples,        &kLabPrmSamples,        &kLabTorusSamples,     &kNeighborK,    &kCheckerGridN,
    &kCheckerStepD,      &kLabCheckerStepD,      &kSeed,                &kExperimentTrials,
    &kLabExperimentTrials, &kExperimentSamples,  &kLabExperimentSamples, &kReferenceSamples,
    &kVisibilityTrials,  &kLabVisibilityTrials,  &kMcSeed,              &kTracedGridN,  &kMinGridMax,
    &kFieldZeta,         &kFieldSwitch,          &kFieldEta,            &kFieldRho0,    &kDescentStep,
    &kDescentEscapes,    &kGoalBias,             &kTreeStep,            &kSamplerSigma, &kLabSamplerSigma,
    &kLabSamplerUniformShare};

}  // namespace csl
