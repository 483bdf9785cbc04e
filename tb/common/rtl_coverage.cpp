#include "common/rtl_coverage.hpp"

#include <verilated.h>
#if VM_COVERAGE
#include <verilated_cov.h>
#endif

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <sstream>
#include <utility>
#include <stdexcept>

namespace trirast::rtl {

namespace {
std::mutex g_mutex;
std::map<std::string, std::map<std::string, uint64_t>> g_counts;
}  // namespace

bool rtl_coverage_built() { return VM_COVERAGE != 0; }

std::map<std::string, uint64_t> parse_coverage_dat(const std::string& text, const std::string& what) {
  std::map<std::string, uint64_t> points;
  std::istringstream in(text);
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    const auto bad = [&](const char* why) {
      return std::runtime_error(what + ":" + std::to_string(number) + ": " + why);
    };
    // C '<keys>' <count>
    const size_t open = line.find('\'');
    const size_t close = line.rfind('\'');
    if (line.compare(0, 2, "C ") != 0 || open == std::string::npos || close <= open)
      throw bad("not a coverage line (C '<keys>' <count>)");
    const std::string keys = line.substr(open + 1, close - open - 1);
    char* end = nullptr;
    const unsigned long long count = std::strtoull(line.c_str() + close + 1, &end, 10);
    if (end == line.c_str() + close + 1) throw bad("no count after the keys");
    // \001 starts a key, \002 separates it from its value.
    std::map<std::string, std::string> kv;
    size_t p = 0;
    while ((p = keys.find('\001', p)) != std::string::npos) {
      const size_t sep = keys.find('\002', p + 1);
      const size_t next = keys.find('\001', p + 1);
      if (sep == std::string::npos || (next != std::string::npos && sep > next))
        throw bad("a key without a value");
      kv[keys.substr(p + 1, sep - p - 1)] =
          keys.substr(sep + 1, next == std::string::npos ? std::string::npos : next - sep - 1);
      p = sep;
    }
    auto page = kv.find("page");
    if (page == kv.end() || page->second.compare(0, 6, "v_user") != 0) continue;  // user points only
    std::string hier = kv.count("h") ? kv["h"] : "";
    const size_t dut = hier.find("u_dut");
    if (dut != std::string::npos) hier = hier.substr(dut + 5);
    if (!hier.empty() && hier[0] == '.') hier = hier.substr(1);
    // Verilator spells a generate block's index brackets __BRA__, __KET__ in some names.
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"__BRA__", "["}, {"__KET__", "]"}})
      for (size_t at = hier.find(from); at != std::string::npos; at = hier.find(from, at))
        hier.replace(at, from.size(), to);
    const std::string label = kv.count("o") ? kv["o"] : "";
    if (label.empty()) throw bad("a user cover point without a label ('o')");
    // Verilator's 'h' is the point's full name (its scope and label); the label once otherwise.
    const bool named = hier.size() >= label.size() &&
                       hier.compare(hier.size() - label.size(), label.size(), label) == 0;
    points[named ? hier : hier.empty() ? label : hier + "." + label] += count;
  }
  return points;
}

void collect_rtl_coverage(const std::string& engine, VerilatedContext& ctx) {
#if VM_COVERAGE
  // The database's one output is a file (VerilatedCovContext::write): a temporary one per run.
  const char* dir = std::getenv("TMPDIR");
  std::string path = std::string(dir && *dir ? dir : "/tmp") + "/trirast-cov-XXXXXX";
  const int fd = ::mkstemp(path.data());
  if (fd < 0) throw std::runtime_error(engine + ": cannot create a temporary file for the coverage");
  ::close(fd);
  ctx.coveragep()->write(path.c_str());
  std::ifstream f(path);
  std::stringstream text;
  text << f.rdbuf();
  f.close();
  std::remove(path.c_str());
  const std::map<std::string, uint64_t> run = parse_coverage_dat(text.str(), engine + " coverage");
  std::lock_guard<std::mutex> lock(g_mutex);
  std::map<std::string, uint64_t>& into = g_counts[engine];
  for (const auto& [name, count] : run) into[name] += count;
#else
  (void)engine;
  (void)ctx;
#endif
}

std::map<std::string, std::map<std::string, uint64_t>> rtl_coverage_counts() {
  std::lock_guard<std::mutex> lock(g_mutex);
  return g_counts;
}

void reset_rtl_coverage() {
  std::lock_guard<std::mutex> lock(g_mutex);
  g_counts.clear();
}

std::string rtl_coverage_report(const std::vector<std::string>& engines, const std::string& title,
                                uint64_t& hit, uint64_t& total) {
  const auto counts = rtl_coverage_counts();
  hit = total = 0;
  std::string table, never;
  for (const std::string& engine : engines) {
    auto it = counts.find(engine);
    if (it == counts.end()) continue;
    for (const auto& [name, count] : it->second) {
      ++total;
      hit += count > 0;
      table += "| " + engine + " | `" + name + "` | " + std::to_string(count) + " |\n";
      if (count == 0) never += "- " + engine + " `" + name + "`\n";
    }
  }
  std::string r = "# RTL coverage: " + title + "\n\ncoverage: " + std::to_string(hit) + " of " +
                  std::to_string(total) + " cover points hit\n\n| engine | cover point | count |\n" +
                  "|---|---|---:|\n" + table + "\nNever hit: " +
                  (never.empty() ? "none\n" : "\n" + never);
  return r;
}

}  // namespace trirast::rtl
