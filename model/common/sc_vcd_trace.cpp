#include "common/sc_vcd_trace.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <stdexcept>

#include "common/gtkw_save.hpp"
#include "common/temporary_files.hpp"

namespace trirast::sc {

int VcdRecorder::add(const std::string& scope, const std::string& name, int width, uint64_t initial,
                     bool counter) {
  signals_.push_back(Signal{scope, name, width, counter, initial, 0, {}});
  return int(signals_.size()) - 1;
}

void VcdRecorder::name_values(int sig, const std::string& filter,
                              const std::vector<std::pair<uint64_t, std::string>>& labels) {
  signals_[size_t(sig)].filter = filter;
  for (const auto& f : filters_)
    if (f.first == filter) return;
  filters_.emplace_back(filter, labels);
}

void VcdRecorder::set_window(uint64_t first, uint64_t last) {
  first_ = first;
  last_ = last;
}

std::string VcdRecorder::gtkw_path(const std::string& vcd_path) { return gtkw_path_of(vcd_path); }

namespace {

// VCD identifier codes: base 94 over the printable characters '!'..'~'.
std::string vcd_id(int n) {
  std::string s;
  do {
    s += char('!' + n % 94);
    n /= 94;
  } while (n > 0);
  return s;
}

// One value change line: "0!" / "1!" for one bit, "b101 !" for vectors, x for unknown.
void put_value(std::string& buf, int width, uint64_t v, const std::string& id) {
  if (width == 1) {
    buf += v == VcdRecorder::kX ? 'x' : (v ? '1' : '0');
    buf += id;
  } else if (v == VcdRecorder::kX) {
    buf += "bx ";
    buf += id;
  } else {
    buf += 'b';
    int top = width - 1;
    while (top > 0 && !((v >> top) & 1)) --top;  // leading zeros may be dropped in VCD
    for (int b = top; b >= 0; --b) buf += ((v >> b) & 1) ? '1' : '0';
    buf += ' ';
    buf += id;
  }
  buf += '\n';
}

bool is_fst(const std::string& path) {
  return path.size() > 4 && path.compare(path.size() - 4, 4, ".fst") == 0;
}

// Writes text to path through a temporary name (removed on failure and on SIGINT / SIGTERM).
// A .fst path gets the VCD text converted by gtkwave's vcd2fst.
void write_file(const std::string& path, const std::string& text) {
  const std::string tmp = path + (is_fst(path) ? ".tmp.vcd" : ".tmp");
  TemporaryPath guard(tmp);
  FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw std::runtime_error("--trace: cannot write '" + path + "'");
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  if (std::fclose(f) != 0 || !ok ||
      (!is_fst(path) && std::rename(tmp.c_str(), path.c_str()) != 0)) {
    std::remove(tmp.c_str());
    throw std::runtime_error("--trace: cannot write '" + path + "'");
  }
  if (!is_fst(path)) {
    guard.release();
    return;
  }
  const std::string fst_tmp = path + ".tmp.fst";
  TemporaryPath fst_guard(fst_tmp);
  TemporaryPath hier_guard(fst_tmp + ".hier");  // vcd2fst's own scratch file
  const std::string cmd = "vcd2fst '" + tmp + "' '" + fst_tmp + "' >/dev/null 2>&1";
  const int rc = std::system(cmd.c_str());
  // system() ignores SIGINT in this process while vcd2fst runs: a Ctrl-C or SIGTERM to the
  // process group ends vcd2fst only. Pass it on, so the run ends as interrupted (the handler of
  // core/temporary_files removes the temporaries) instead of reporting a failed conversion.
  if (rc != -1 && WIFSIGNALED(rc) && (WTERMSIG(rc) == SIGINT || WTERMSIG(rc) == SIGTERM))
    std::raise(WTERMSIG(rc));
  if (rc != 0 || std::rename(fst_tmp.c_str(), path.c_str()) != 0)
    throw std::runtime_error("--trace " + path + ": vcd2fst (gtkwave) failed" +
                             std::string(rc == 127 * 256 ? " (not installed)" : "") +
                             ": the SystemC engines write VCD; name the trace .vcd");
  fst_guard.release();
}

}  // namespace

void VcdRecorder::write(const std::string& vcd_path, const std::string& top) const {
  std::string out;
  out += "$date trirast SystemC model $end\n$version trirast SystemC model $end\n";
  out += "$comment one cycle = 1 ns; time = cycle number of the run (docs/timing.md) $end\n";
  out += "$timescale 1ns $end\n";
  // Scopes in order of first declaration.
  std::vector<std::string> scopes;
  for (const Signal& s : signals_)
    if (std::find(scopes.begin(), scopes.end(), s.scope) == scopes.end()) scopes.push_back(s.scope);
  out += "$scope module " + top + " $end\n";
  for (const std::string& sc : scopes) {
    out += "$scope module " + sc + " $end\n";
    for (size_t i = 0; i < signals_.size(); ++i) {
      const Signal& s = signals_[i];
      if (s.scope != sc) continue;
      out += "$var wire " + std::to_string(s.width) + " " + vcd_id(int(i)) + " " + s.name;
      if (s.width > 1) out += " [" + std::to_string(s.width - 1) + ":0]";
      out += " $end\n";
    }
    out += "$upscope $end\n";
  }
  out += "$upscope $end\n$enddefinitions $end\n";

  // Initial values at the window's first cycle.
  std::vector<uint64_t> cur(signals_.size());
  for (size_t i = 0; i < signals_.size(); ++i) cur[i] = signals_[i].initial;
  const uint64_t t0 = first_;
  out += "#" + std::to_string(t0) + "\n$dumpvars\n";
  for (size_t i = 0; i < signals_.size(); ++i)
    put_value(out, signals_[i].width, cur[i], vcd_id(int(i)));
  out += "$end\n";

  // Changes in cycle order; within a cycle, the last report of a signal wins.
  std::vector<Change> ch = changes_;
  std::stable_sort(ch.begin(), ch.end(), [](const Change& a, const Change& b) {
    return a.cycle != b.cycle ? a.cycle < b.cycle : a.seq < b.seq;
  });
  std::vector<uint64_t> written = cur;
  std::vector<int> touched;
  std::vector<char> is_touched(signals_.size(), 0);
  size_t i = 0;
  while (i < ch.size()) {
    const uint64_t c = ch[i].cycle;
    for (; i < ch.size() && ch[i].cycle == c; ++i) {
      const Change& x = ch[i];
      if (signals_[x.sig].counter)
        cur[x.sig] += uint64_t(x.v);
      else
        cur[x.sig] = uint64_t(x.v);
      if (!is_touched[x.sig]) {
        is_touched[x.sig] = 1;
        touched.push_back(x.sig);
      }
    }
    std::sort(touched.begin(), touched.end());
    bool stamped = false;
    for (int s : touched) {
      is_touched[s] = 0;
      if (cur[s] == written[s]) continue;
      if (!stamped && c != t0) out += "#" + std::to_string(c) + "\n";
      stamped = true;
      put_value(out, signals_[s].width, cur[s], vcd_id(s));
      written[s] = cur[s];
    }
    touched.clear();
  }
  const uint64_t end = std::max<uint64_t>(t0, last_ == ~uint64_t(0) ? t0 : last_) + 1;
  out += "#" + std::to_string(end) + "\n";
  write_file(vcd_path, out);

  // GTKWave save file: one group per module (scope), buses in decimal, states by name.
  GtkwSave save;
  save.dump_path = vcd_path;
  save.window_start = t0;
  save.window_end = end;
  save.tree_open = {top + "."};
  for (const auto& f : filters_) save.filters.push_back(GtkwSave::Filter{f.first, f.second});
  for (const std::string& sc : scopes) {
    GtkwSave::Group grp{sc, false, {}};
    for (const Signal& s : signals_) {
      if (s.scope != sc) continue;
      std::string name = top + "." + sc + "." + s.name;
      if (s.width > 1) name += "[" + std::to_string(s.width - 1) + ":0]";
      grp.traces.push_back(GtkwSave::Trace{name, s.width, s.filter});
    }
    save.groups.push_back(std::move(grp));
  }
  write_gtkw(gtkw_path(vcd_path), save);
}

}  // namespace trirast::sc
