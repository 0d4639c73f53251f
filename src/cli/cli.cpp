// cspacelab's dispatch: the command table, --help, and the exit statuses.
// Output contract: JSON on stdout; errors are one line on stderr with exit status 2
// (bad input or usage) or 1 (internal error).
#include "cli/cli.hpp"

#include <exception>

#include "cli/commands.hpp"
#include "core/base/text.hpp"
#include "core/base/version.hpp"

namespace csl::cli {

namespace {

const Command* const kCommands[] = {&kValidateCommand, &kCheckCommand,      &kDistanceCommand,   &kCspaceOfCommand,
                                    &kPlanCommand,     &kBoundCommand,      &kVisibilityCommand, &kExperimentCommand,
                                    &kCspaceCommand,   &kPotentialCommand,  &kDescendCommand,    &kHomeworkCommand,
                                    &kExerciseCommand, &kLinkCommand,       &kAssignmentCommand};

const Command* find_command(const std::string& name) {
  for (const Command* c : kCommands)
    if (name == c->name) return c;
  return nullptr;
}

void print_help(std::ostream& out) {
  out << "cspacelab " << kVersion << " - C-Space Lab on the command line\n\n"
      << "Usage: cspacelab COMMAND [ARGS...]\n"
      << "       cspacelab help COMMAND    (or: cspacelab COMMAND --help)\n\n"
      << "Commands:\n";
  for (const Command* c : kCommands) {
    std::string name = c->name;
    name.resize(14, ' ');
    out << "  " << name << c->summary << "\n";
  }
  out << "\nOptions:\n"
      << "  --help        this text\n"
      << "  --version     the version, as {\"version\": \"X.Y.Z\"}\n\n"
      << "Output is JSON on stdout. Errors are one line on stderr, exit status 2 for bad\n"
      << "input or usage, 1 for internal errors. Configurations Q are comma-separated\n"
      << "numbers, e.g. --from 0,0. Scenes are JSON files (schema: cspacelab help validate).\n";
}

int run(const std::vector<std::string>& argv, std::ostream& out) {
  // No command is a usage error like any other: one line on stderr, nothing on stdout.
  if (argv.empty()) throw UsageError("no command given (see cspacelab --help)");
  const auto nothing_after = [&](std::size_t used) {
    if (argv.size() > used) throw UsageError("unexpected argument '" + printable(argv[used], 60) + "'");
  };
  if (argv[0] == "--help" || argv[0] == "-h") {
    nothing_after(1);
    print_help(out);
    return 0;
  }
  if (argv[0] == "--version") {
    nothing_after(1);
    out << "{\"version\": \"" << kVersion << "\"}\n";
    return 0;
  }
  if (argv[0] == "help") {
    nothing_after(2);
    if (argv.size() < 2) {
      print_help(out);
      return 0;
    }
    const Command* c = find_command(argv[1]);
    if (!c) throw UsageError("unknown command '" + printable(argv[1], 60) + "' (see cspacelab --help)");
    out << c->usage;
    return 0;
  }
  const Command* c = find_command(argv[0]);
  if (!c) throw UsageError("unknown command '" + printable(argv[0], 60) + "' (see cspacelab --help)");
  Args args(std::vector<std::string>(argv.begin() + 1, argv.end()));
  if (args.take_flag("help")) {
    out << c->usage;
    return 0;
  }
  return c->run(args, out);
}

}  // namespace

int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  try {
    return run(args, out);
  } catch (const UsageError& e) {
    // One line whatever the message quotes (file names, keys, arguments with newlines or
    // escape sequences): control characters are escaped here, the last place they pass.
    err << "cspacelab: " << printable(e.what()) << "\n";
    return 2;
  } catch (const std::exception& e) {
    err << "cspacelab: internal error: " << printable(e.what()) << "\n";
    return 1;
  }
}

}  // namespace csl::cli
