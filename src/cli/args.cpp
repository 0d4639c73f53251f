#include "cli/args.hpp"

#include <algorithm>

#include "core/base/text.hpp"

namespace csl::cli {

std::optional<std::string> Args::take(const std::string& name) {
  const std::string flag = "--" + name, prefix = flag + "=";
  std::optional<std::string> value;
  for (std::size_t i = 0; i < args_.size();) {
    std::optional<std::string> found;
    if (args_[i] == flag) {
      if (i + 1 >= args_.size()) throw UsageError(flag + " needs a value");
      found = args_[i + 1];
      args_.erase(args_.begin() + static_cast<long>(i), args_.begin() + static_cast<long>(i) + 2);
    } else if (args_[i].rfind(prefix, 0) == 0) {
      found = args_[i].substr(prefix.size());
      args_.erase(args_.begin() + static_cast<long>(i));
    } else {
      ++i;
      continue;
    }
    if (value) throw UsageError(flag + " given twice");
    value = found;
  }
  return value;
}

bool Args::take_flag(const std::string& name) {
  const std::string flag = "--" + name;
  bool seen = false;
  for (std::size_t i = 0; i < args_.size();) {
    if (args_[i] == flag) {
      if (seen) throw UsageError(flag + " given twice");  // as for options with values
      seen = true;
      args_.erase(args_.begin() + static_cast<long>(i));
    } else if (args_[i].rfind(flag + "=", 0) == 0) {
      throw UsageError(flag + " takes no value");
    } else {
      ++i;
    }
  }
  return seen;
}

std::string Args::take_positional(const std::string& what) {
  for (std::size_t i = 0; i < args_.size(); ++i) {
    // A lone "-" and negative numbers are positionals; anything else starting with "--" is not.
    if (args_[i].rfind("--", 0) == 0) continue;
    std::string v = args_[i];
    args_.erase(args_.begin() + static_cast<long>(i));
    return v;
  }
  throw UsageError("missing " + what);
}

void Args::finish() const {
  if (args_.empty()) return;
  const std::string& a = args_.front();
  throw UsageError(a.rfind("--", 0) == 0 ? "unknown option " + printable(a, 60)
                                         : "unexpected argument '" + printable(a, 60) + "'");
}

double parse_number(const std::string& text, const std::string& what) {
  // The one number syntax of core/base/text.hpp: what a link or a scene's scripts pass means the
  // same here.
  if (const auto v = parse_decimal(text)) return *v;
  throw UsageError(what + ": '" + printable(text, 60) + "' is not a finite number");
}

long long parse_count(const std::string& text, const std::string& what, long long max, long long min) {
  const auto v = parse_integer(text);
  if (!v || *v < min || *v > max)
    throw UsageError(what + ": '" + printable(text, 60) + "' is not an integer in [" + std::to_string(min) + ", " +
                     std::to_string(max) + "]");
  return *v;
}

double parse_param(const std::string& text, const ParamSpec& spec) {
  const std::string what = std::string("--") + spec.flag;
  if (spec.integer) {
    const auto v = parse_integer(text);
    if (!v || !in_range(spec, static_cast<double>(*v)))
      throw UsageError(what + ": '" + printable(text, 60) + "' is not " + range_text(spec));
    return static_cast<double>(*v);
  }
  const double v = parse_number(text, what);
  if (!in_range(spec, v)) throw UsageError(what + ": '" + printable(text, 60) + "' is not " + range_text(spec));
  return v;
}

double take_param(Args& args, const ParamSpec& spec) {
  const auto text = args.take(spec.flag);
  return text ? parse_param(*text, spec) : spec.def;
}

std::string option_help(const ParamSpec& spec, const std::string& metavar, bool shows_default) {
  std::string head = "  --" + std::string(spec.flag) + " " + metavar;
  head.resize(std::max<std::size_t>(head.size() + 2, 25), ' ');
  std::string range = range_text(spec);
  if (shows_default) range += ", default " + param_value_text(spec, spec.def);
  // Within the help's 95 columns: the range under the help when both do not fit on one line.
  if (head.size() + std::string(spec.help).size() + 2 + range.size() <= 95) return head + spec.help + ": " + range + "\n";
  return head + spec.help + ":\n" + std::string(head.size(), ' ') + range + "\n";
}

std::vector<double> parse_numbers(const std::string& text, const std::string& what) {
  std::vector<double> out;
  std::size_t pos = 0;
  while (true) {
    std::size_t comma = text.find(',', pos);
    // Spaces around an item are fine in a list ("0.1, 0.2"), as scripts write them.
    std::string item = text.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
    const std::size_t first = item.find_first_not_of(" \t"), last = item.find_last_not_of(" \t");
    item = first == std::string::npos ? std::string() : item.substr(first, last - first + 1);
    out.push_back(parse_number(item, what));
    if (comma == std::string::npos) break;
    pos = comma + 1;
  }
  return out;
}

}  // namespace csl::cli
