#pragma once
// The CLI's commands. Each lives in its own cmd_*.cpp; main.cpp lists them in kCommands.
#include <string>

#include "cli/args.hpp"

namespace csl::cli {

struct Command {
  const char* name;
  const char* summary;  ///< one line for `cspacelab --help`
  const char* usage;    ///< full help for `cspacelab help NAME` / `cspacelab NAME --help`
  int (*run)(Args& args);  ///< prints JSON on stdout; throws UsageError for bad input
};

extern const Command kValidateCommand;
extern const Command kCspaceOfCommand;

/// Reads a whole file; UsageError naming the path if it cannot be read.
std::string read_file(const std::string& path);

}  // namespace csl::cli
