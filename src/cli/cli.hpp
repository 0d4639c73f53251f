#pragma once
// The CLI's whole behaviour as a function: main() is run_cli(argv, std::cout, std::cerr), and
// the fuzz target (tests/fuzz/fuzz_cli.cpp) calls it in-process with its own streams.
#include <ostream>
#include <string>
#include <vector>

namespace csl::cli {

/// Runs `cspacelab ARGS...` (args without the program name): JSON to `out`, a one-line error to
/// `err`. Returns the exit status: 0, 2 for bad input or usage, 1 for an internal error.
int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace csl::cli
