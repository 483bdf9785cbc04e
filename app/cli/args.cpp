#include "cli/args.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace trirast {

Args::Args(std::string command, std::string synopsis, std::vector<OptionSpec> specs)
    : command_(std::move(command)), synopsis_(std::move(synopsis)), specs_(std::move(specs)) {}

const OptionSpec* Args::find(const std::string& name) const {
  for (const OptionSpec& s : specs_)
    if (s.name == name) return &s;
  return nullptr;
}

void Args::parse(int argc, char** argv, int first) {
  const std::string who = "trirast " + command_;
  for (int i = first; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      help_ = true;
      continue;
    }
    std::string value;
    bool inline_value = false;
    const size_t eq = arg.find('=');
    if (arg.rfind("--", 0) == 0 && eq != std::string::npos) {
      value = arg.substr(eq + 1);
      arg = arg.substr(0, eq);
      inline_value = true;
    }
    const OptionSpec* spec = find(arg);
    if (!spec) {
      if (arg.rfind("-", 0) == 0)
        throw UsageError(who + ": unknown option '" + arg + "' (see trirast " + command_ +
                         " --help)");
      throw UsageError(who + ": unexpected argument '" + arg + "' (see trirast " + command_ +
                       " --help)");
    }
    if (spec->metavar.empty()) {
      if (inline_value) throw UsageError(who + ": option '" + arg + "' takes no value");
      values_[arg] = "1";
      continue;
    }
    if (!inline_value) {
      if (i + 1 >= argc) throw UsageError(who + ": option '" + arg + "' needs a value");
      value = argv[++i];
    }
    if (values_.count(arg)) throw UsageError(who + ": option '" + arg + "' given twice");
    values_[arg] = value;
  }
}

std::string Args::help_text() const {
  std::string text = "usage: trirast " + command_ + " " + synopsis_ + "\n\noptions:\n";
  for (const OptionSpec& s : specs_) {
    std::string left = "  " + s.name + (s.metavar.empty() ? "" : " " + s.metavar);
    if (left.size() < 28) left.resize(28, ' ');
    else left += "\n" + std::string(28, ' ');
    text += left + s.help;
    if (!s.fallback.empty()) text += " (default: " + s.fallback + ")";
    text += "\n";
  }
  text += "  --help                    this text\n";
  return text;
}

std::string Args::get(const std::string& name) const {
  auto it = values_.find(name);
  if (it != values_.end()) return it->second;
  const OptionSpec* spec = find(name);
  return spec ? spec->fallback : std::string();
}

long Args::get_int(const std::string& name, long lo, long hi) const {
  const std::string text = get(name);
  errno = 0;
  char* end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  // strtol skips leading blanks and takes a '+': the option's value is the digits alone.
  const bool digits_first =
      !text.empty() && (std::isdigit((unsigned char)text[0]) ||
                        (text[0] == '-' && text.size() > 1 && std::isdigit((unsigned char)text[1])));
  if (!digits_first || *end != '\0' || errno != 0)
    throw UsageError("trirast " + command_ + ": " + name + ": '" + text + "' is not an integer");
  if (v < lo || v > hi)
    throw UsageError("trirast " + command_ + ": " + name + ": " + text + " is outside " +
                     std::to_string(lo) + ".." + std::to_string(hi));
  return v;
}

double Args::get_double(const std::string& name) const {
  const std::string text = get(name);
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  // strtod skips leading blanks: a value that starts with one is refused like trailing ones.
  if (text.empty() || std::isspace((unsigned char)text[0]) || *end != '\0' || !std::isfinite(v))
    throw UsageError("trirast " + command_ + ": " + name + ": '" + text + "' is not a number");
  return v;
}

}  // namespace trirast
