#pragma once
// A small strict argument parser: every option a command does not take is an error.
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/base/params.hpp"

namespace csl::cli {

/// Bad command line or bad input: printed as one line on stderr, exit status 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The arguments after the command name. Options are `--name value`, `--name=value` or `--flag`.
class Args {
 public:
  explicit Args(std::vector<std::string> args) : args_(std::move(args)) {}

  /// Removes and returns the value of option --name, if given (at most once).
  std::optional<std::string> take(const std::string& name);
  /// Removes --name if given and returns whether it was there.
  bool take_flag(const std::string& name);
  /// Removes and returns the next positional argument; UsageError naming `what` if there is none.
  std::string take_positional(const std::string& what);
  /// UsageError if anything was not taken (an unknown option or an extra argument).
  void finish() const;

 private:
  std::vector<std::string> args_;
};

/// A finite number, or UsageError naming `what`.
double parse_number(const std::string& text, const std::string& what);
/// An integer in [min, max], or UsageError naming `what` and that range.
long long parse_count(const std::string& text, const std::string& what, long long max, long long min = 0);
/// A value of `spec` given as --FLAG's text: "--trials: '0' is not an integer in [1, 100000]"
/// otherwise (the spec's range, as its API error says it).
double parse_param(const std::string& text, const ParamSpec& spec);
/// The value of --FLAG if given, else the spec's default.
double take_param(Args& args, const ParamSpec& spec);
/// A --help line for the spec's option, from its help, range and default:
/// "  --trials T          PRM runs for each n: an integer in [1, 100000], default 20".
/// `shows_default` off where the default is not a number ("max(2000, ...)": said in the help).
std::string option_help(const ParamSpec& spec, const std::string& metavar, bool shows_default = true);
/// Comma-separated finite numbers ("0.5,-1,2"), or UsageError naming `what`.
std::vector<double> parse_numbers(const std::string& text, const std::string& what);

}  // namespace csl::cli
