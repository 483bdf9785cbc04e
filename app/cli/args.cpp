#include "cli/args.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace trirast {

namespace {

// Empty when `text` is an integer in [lo, hi] written as digits with an optional leading '-'
// (strtol alone would skip leading blanks and take a '+'); else what is wrong with it.
std::string int_problem(const std::string& text, long lo, long hi) {
  errno = 0;
  char* end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  const bool digits_first =
      !text.empty() && (std::isdigit((unsigned char)text[0]) ||
                        (text[0] == '-' && text.size() > 1 && std::isdigit((unsigned char)text[1])));
  if (!digits_first || *end != '\0' || errno != 0) return "'" + text + "' is not an integer";
  if (v < lo || v > hi)
    return text + " is outside " + std::to_string(lo) + ".." + std::to_string(hi);
  return "";
}

// A CLI11 check of an IntRange; its description ("1..16384") follows the metavar in --help.
CLI::Validator int_range_check(IntRange r) {
  return CLI::Validator([r](std::string& value) { return int_problem(value, r.lo, r.hi); },
                        std::to_string(r.lo) + ".." + std::to_string(r.hi));
}

// CLI11's formatter with trirast's usage line ("usage: trirast CMD SYNOPSIS") and each option's
// default after its help text rather than after its metavar.
class HelpFormatter : public CLI::Formatter {
 public:
  explicit HelpFormatter(std::string usage) : usage_(std::move(usage)) {}
  std::string make_usage(const CLI::App*, std::string) const override { return usage_ + "\n"; }
  std::string make_option_opts(const CLI::Option* opt) const override {
    return opt->get_type_size() == 0 ? std::string() : " " + opt->get_type_name();
  }
  std::string make_option_desc(const CLI::Option* opt) const override {
    std::string desc = opt->get_description();
    if (!opt->get_default_str().empty()) desc += " (default: " + opt->get_default_str() + ")";
    return desc;
  }

 private:
  std::string usage_;
};

const char* const kHelpFlag = "-h,--help";

}  // namespace

Args::Args(std::string command, std::string synopsis, std::vector<OptionSpec> specs)
    : command_(std::move(command)),
      synopsis_(std::move(synopsis)),
      specs_(std::move(specs)),
      app_(std::make_unique<CLI::App>("", "trirast " + command_)) {
  app_->formatter(std::make_shared<HelpFormatter>("usage: trirast " + command_ +
                                                  (synopsis_.empty() ? "" : " " + synopsis_)));
  app_->option_defaults()->group("options");
  // Unknown options and stray arguments are collected (app_->remaining()) and reported by
  // parse() with their own message.
  app_->allow_extras(true);
  app_->set_help_flag();  // re-added after the options, so --help lists it last
  for (const OptionSpec& s : specs_) {
    if (s.metavar.empty()) {
      app_->add_flag(s.name, s.help);  // may be repeated
      continue;
    }
    // One value; a second occurrence is an error (CLI11's MultiOptionPolicy::Throw).
    CLI::Option* opt = app_->add_option(s.name, CLI::callback_t(), s.help);
    opt->type_name(s.metavar)->default_str(s.fallback);
    if (s.range) opt->check(int_range_check(*s.range));
  }
  app_->set_help_flag(kHelpFlag, "this text");
}

Args::~Args() = default;
Args::Args(Args&&) noexcept = default;
Args& Args::operator=(Args&&) noexcept = default;

const OptionSpec* Args::find(const std::string& name) const {
  for (const OptionSpec& s : specs_)
    if (s.name == name) return &s;
  return nullptr;
}

void Args::usage_error(const std::string& what) const {
  std::string line = "trirast " + command_ + ": " + what;
  std::replace(line.begin(), line.end(), '\n', ' ');
  throw UsageError(line);
}

void Args::parse(int argc, char** argv, int first) {
  // What CLI11 is given. Two forms are settled here, where CLI11 reads them otherwise:
  // "--opt=" is --opt with the empty value (CLI11 would take the next argument as the value),
  // and a flag takes no value, not even "--flag=true".
  std::vector<std::string> args;
  bool value_next = false;  // the argument is the value of the option before it
  for (int i = first; i < argc; ++i) {
    const std::string arg = argv[i];
    if (value_next) {
      value_next = false;
      args.push_back(arg);
      continue;
    }
    const size_t eq = arg.find('=');
    if (arg.rfind("--", 0) == 0 && eq != std::string::npos) {
      const std::string name = arg.substr(0, eq);
      const OptionSpec* spec = find(name);
      if ((spec && spec->metavar.empty()) || name == "--help")
        usage_error("option '" + name + "' takes no value");
      if (spec && eq + 1 == arg.size()) {
        args.push_back(name);
        args.push_back("");
        continue;
      }
    } else if (const OptionSpec* spec = find(arg)) {
      value_next = !spec->metavar.empty();
    }
    args.push_back(arg);
  }
  std::reverse(args.begin(), args.end());  // CLI11 takes the arguments from the back

  const auto help_given = [this] { return app_->get_help_ptr()->count() > 0; };
  try {
    app_->parse(std::move(args));
  } catch (const CLI::CallForHelp&) {
    help_ = true;
    return;
  } catch (const CLI::ArgumentMismatch& e) {
    if (help_given()) {
      help_ = true;
      return;
    }
    // Which option and what kind: CLI11's messages for a missing value and for a second
    // occurrence of a one-value option, rebuilt for each option and compared.
    const std::string what = e.what();
    for (const OptionSpec& s : specs_) {
      const CLI::Option* opt = app_->get_option_no_throw(s.name);
      if (!opt || s.metavar.empty()) continue;
      if (what == CLI::ArgumentMismatch::TypedAtLeast(opt->get_name(), 1, opt->get_type_name()).what())
        usage_error("option '" + s.name + "' needs a value");
      if (what == CLI::ArgumentMismatch::AtMost(opt->get_name(), 1, opt->count()).what())
        usage_error("option '" + s.name + "' given twice");
    }
    usage_error(what);
  } catch (const CLI::ParseError& e) {
    // ValidationError: "--width: 0 is outside 1..16384", the option's name first.
    if (help_given()) {
      help_ = true;
      return;
    }
    usage_error(e.what());
  }

  const std::vector<std::string> extra = app_->remaining();
  if (!extra.empty()) {
    const std::string& arg = extra.front();
    if (arg.rfind("-", 0) == 0) {
      const std::string name = arg.rfind("--", 0) == 0 ? arg.substr(0, arg.find('=')) : arg;
      usage_error("unknown option '" + name + "' (see trirast " + command_ + " --help)");
    }
    usage_error("unexpected argument '" + arg + "' (see trirast " + command_ + " --help)");
  }

  for (const OptionSpec& s : specs_) {
    const CLI::Option* opt = app_->get_option(s.name);
    if (opt->count() == 0) continue;
    values_[s.name] = s.metavar.empty() ? "1" : opt->results().back();
  }
}

std::string Args::help_text() const {
  std::string text = app_->help();
  while (!text.empty() && text.back() == '\n') text.pop_back();
  return text + "\n";
}

std::string Args::get(const std::string& name) const {
  auto it = values_.find(name);
  if (it != values_.end()) return it->second;
  const OptionSpec* spec = find(name);
  return spec ? spec->fallback : std::string();
}

long Args::get_int(const std::string& name, long lo, long hi) const {
  const std::string text = get(name);
  const std::string problem = int_problem(text, lo, hi);
  if (!problem.empty()) usage_error(name + ": " + problem);
  return std::strtol(text.c_str(), nullptr, 10);
}

double Args::get_double(const std::string& name) const {
  const std::string text = get(name);
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  // strtod skips leading blanks: a value that starts with one is refused like trailing ones.
  if (text.empty() || std::isspace((unsigned char)text[0]) || *end != '\0' || !std::isfinite(v))
    usage_error(name + ": '" + text + "' is not a number");
  return v;
}

}  // namespace trirast
