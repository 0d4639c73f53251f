// Fuzz target: the CLI's command line for `check` and `plan`, run in-process through run_cli().
//
// Input: the first line's first byte picks the command (bit 0: check or plan) and a bundled
// scene (the other bits, over assets/scenes/*.json sorted by name); every further line is one
// argv token ('\n' or '\0' ends a token). The scene's path is always the first argument, so it
// is the one positional: no fuzzed token is ever opened as a file (/dev/zero would read forever).
//
// Exit 0 must print the command's JSON (or its --help text), exit 2 exactly one line on stderr
// and nothing on stdout. Exit 1 (an internal error: bad input that slipped past the checks), any
// other status, a crash, a sanitizer report, an uncaught exception or a hang (-timeout) is a
// finding.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/cli.hpp"
#include "cli/commands.hpp"

namespace {

std::vector<std::string> g_scenes;  // absolute paths, sorted
bool g_verbose = false;

// --- Cost caps. The parser is what is fuzzed, not the planner: an input asking for 10^6
// samples or grid:1000000 would spend seconds per execution (and min-grid is quadratic in
// --max), so the harness lowers such values before the CLI sees them. Only values inside the
// CLI's own accepted range are lowered; larger, negative or malformed ones pass unchanged, so
// their refusal is still exercised. The CLI tests (tests/cli/) run the real limits.
constexpr long long kMaxSamples = 32;     // plan --samples (the CLI takes up to 10^6)
constexpr long long kMaxMinGrid = 200;    // check --min-grid --max (up to 10^5, ~max^2/2 checks)
constexpr long long kMaxGrid = 200;       // --checker grid:N (up to 10^6 configurations per edge)
constexpr double kMinStep = 0.005;        // --checker step:D (D > 0: up to 10^6 per edge)

// A whole-string integer as strtoll reads it (what the CLI's parsers accept), if any.
bool whole_integer(const std::string& text, long long& v) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  v = std::strtoll(text.c_str(), &end, 10);
  return errno == 0 && end == text.c_str() + text.size();
}

void cap_count(std::string& value, long long cap, long long cli_max) {
  long long v = 0;
  if (whole_integer(value, v) && v > cap && v <= cli_max) value = std::to_string(cap);
}

void cap_checker(std::string& value) {
  if (value.rfind("grid:", 0) == 0) {
    std::string n = value.substr(5);
    cap_count(n, kMaxGrid, 1000000);
    value = "grid:" + n;
  } else if (value.rfind("step:", 0) == 0) {
    const std::string d = value.substr(5);
    char* end = nullptr;
    const double v = d.empty() ? 0.0 : std::strtod(d.c_str(), &end);
    if (!d.empty() && end == d.c_str() + d.size() && v > 0.0 && v < kMinStep) value = "step:0.005";
  }
}

// Applies `cap` to every token that Args::take(name) could return: the rest of any "--name=..."
// and every token after the first "--name". (Not just the next one: options the command takes
// earlier are erased with their values, which can bring a later token next to "--name".)
// Returns whether the option appears at all.
template <class Cap>
bool cap_option(std::vector<std::string>& tokens, const std::string& name, Cap cap) {
  const std::string flag = "--" + name, prefix = flag + "=";
  bool seen = false, after_flag = false;
  for (std::string& t : tokens) {
    if (t.rfind(prefix, 0) == 0) {
      std::string v = t.substr(prefix.size());
      cap(v);
      t = prefix + v;
      seen = true;
    } else if (t == flag) {
      seen = after_flag = true;
    } else if (after_flag) {
      cap(t);
    }
  }
  return seen;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  g_verbose = std::getenv("FUZZ_CLI_VERBOSE") != nullptr;
  for (const auto& entry : std::filesystem::directory_iterator(CSPACELAB_SCENES_DIR))
    if (entry.path().extension() == ".json") g_scenes.push_back(entry.path().string());
  std::sort(g_scenes.begin(), g_scenes.end());
  if (g_scenes.empty()) {
    std::fprintf(stderr, "fuzz_cli: no scenes in %s\n", CSPACELAB_SCENES_DIR);
    std::abort();
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const bool plan = data[0] & 1u;
  const std::string& scene = g_scenes[(data[0] >> 1) % g_scenes.size()];
  std::vector<std::string> tokens;
  std::size_t i = 1;
  while (i < size && data[i] != '\n' && data[i] != '\0') ++i;  // the rest of the first line
  while (i < size) {
    std::size_t j = ++i;
    while (j < size && data[j] != '\n' && data[j] != '\0') ++j;
    tokens.emplace_back(reinterpret_cast<const char*>(data) + i, j - i);
    i = j;
  }

  cap_option(tokens, "checker", cap_checker);
  cap_option(tokens, "max", [](std::string& v) { cap_count(v, kMaxMinGrid, 100000); });
  const bool samples = cap_option(tokens, "samples", [](std::string& v) { cap_count(v, kMaxSamples, 1000000); });
  std::vector<std::string> args{plan ? "plan" : "check", scene};
  // plan's default of 200 samples costs tens of times a capped run (up to a second with
  // --connector potential under the sanitizers); tests/cli/plan.test.mjs covers the default.
  if (plan && !samples) args.push_back("--samples=" + std::to_string(kMaxSamples));
  args.insert(args.end(), tokens.begin(), tokens.end());

  std::ostringstream out, err;
  const int status = csl::cli::run_cli(args, out, err);
  const std::string o = out.str(), e = err.str();
  if (g_verbose) {  // FUZZ_CLI_VERBOSE=1 fuzz_cli INPUT...: what an input ran, for triage
    for (const std::string& a : args) std::fprintf(stderr, "[%s] ", a.c_str());
    std::fprintf(stderr, "-> %d\n%.300s%s", status, o.c_str(), e.c_str());
  }
  if (status == 0) {
    const std::string& usage = plan ? csl::cli::kPlanCommand.usage : csl::cli::kCheckCommand.usage;
    if (!e.empty()) std::abort();
    if (o != usage && !nlohmann::json::parse(o).is_object()) std::abort();  // parse throws on bad JSON
  } else if (status == 2) {
    // One line on stderr, "cspacelab: ..."; nothing on stdout.
    if (!o.empty() || e.rfind("cspacelab: ", 0) != 0 || e.find('\n') != e.size() - 1) std::abort();
  } else {
    std::fprintf(stderr, "fuzz_cli: exit status %d: %s", status, e.c_str());
    std::abort();
  }
  return 0;
}
