// Command-line options of one trirast subcommand: declared once as OptionSpecs, parsed by CLI11
// (CLI::App) and printed by --help through CLI11's formatter from the same declarations, so the
// help cannot drift from what is accepted.
#pragma once
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace trirast {

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An integer option's accepted values, lo..hi inclusive.
struct IntRange {
  long lo, hi;
};

struct OptionSpec {
  std::string name;      // "--width"
  std::string metavar;   // "W"; empty for a flag
  std::string help;      // one line
  std::string fallback;  // default shown in --help; empty when none
  // When set, the value must be an integer in the range: checked while parsing and shown in
  // --help after the metavar ("W:1..16384").
  std::optional<IntRange> range = std::nullopt;
};

class Args {
 public:
  Args(std::string command, std::string synopsis, std::vector<OptionSpec> specs);
  ~Args();
  Args(Args&&) noexcept;
  Args& operator=(Args&&) noexcept;

  // Parses argv[first..argc). Throws UsageError("trirast CMD: ...") naming the bad option.
  void parse(int argc, char** argv, int first);
  bool help_requested() const { return help_; }
  std::string help_text() const;

  bool has(const std::string& name) const { return values_.count(name) != 0; }
  std::string get(const std::string& name) const;  // value or the declared default
  // Strict integer in [lo, hi]; UsageError naming the option otherwise.
  long get_int(const std::string& name, long lo, long hi) const;
  double get_double(const std::string& name) const;
  const std::string& command() const { return command_; }

 private:
  const OptionSpec* find(const std::string& name) const;
  [[noreturn]] void usage_error(const std::string& what) const;
  std::string command_, synopsis_;
  std::vector<OptionSpec> specs_;
  std::unique_ptr<CLI::App> app_;               // the declarations; parses and formats --help
  std::map<std::string, std::string> values_;  // the options given, by name ("1" for a flag)
  bool help_ = false;
};

}  // namespace trirast
