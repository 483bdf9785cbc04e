#include "cli/slowest.hpp"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <map>

#include "common/span_downstream.hpp"
#include "io/output_file.hpp"
#include "units.hpp"

namespace trirast {

std::string timing_unit(const std::string& engine) {
  const UnitDescriptor* unit = unit_of(engine);
  if (unit && std::find(unit->timed_pair.begin(), unit->timed_pair.end(), engine) !=
                  unit->timed_pair.end())
    return unit->name;
  return engine;
}

std::vector<size_t> slowest_triangles(const std::vector<TriangleCycles>& cycles, size_t n) {
  std::vector<size_t> pos(cycles.size());
  for (size_t i = 0; i < pos.size(); ++i) pos[i] = i;
  n = std::min(n, pos.size());
  std::partial_sort(pos.begin(), pos.begin() + std::ptrdiff_t(n), pos.end(), [&](size_t a, size_t b) {
    const uint64_t la = latency(cycles[a]), lb = latency(cycles[b]);
    return la != lb ? la > lb : a < b;
  });
  pos.resize(n);
  return pos;
}

namespace {

std::string u(uint64_t v) { return std::to_string(v); }
std::string plural(uint64_t v, const char* one, const char* many) {
  return u(v) + " " + (v == 1 ? one : many);
}

// What the sink was doing while the FIFO stayed full: a pattern stalls (its ready is low); a queue
// downstream (queue:RATE:CAPACITY) is not ready while its queue holds CAPACITY pixels or more.
std::string sink_stalled(const std::string& sink_stall) {
  return is_cycle_pattern(sink_stall) ? "sink stalled, --sink-stall " + sink_stall
                                      : "sink's queue full, --sink-stall " + sink_stall;
}

// A triangle that went through the walk stage (not retired in the setup stage).
bool walked(const TriangleCycles& c) { return c.walk_start_cycle == c.handoff_cycle + 1; }

}  // namespace

std::string explain_triangle(const std::vector<TriangleCycles>& cycles, size_t pos,
                             const std::string& sink_stall, const CycleWords& words) {
  const TriangleCycles& c = cycles[pos];
  std::string s = "triangle " + u(c.tri) + ": " + plural(latency(c), "cycle", "cycles") +
                  " (accept " + u(c.accept_cycle) + ", done " + u(c.done_cycle) + ", " +
                  plural(c.spans, "span", "spans") + ", " + plural(c.pixels, "pixel", "pixels") +
                  ")";
  // The triangle before it that went through the walk stage: the walk stage (and in a unit with
  // a job stage, the job stage) held it before this one.
  const TriangleCycles* previous = nullptr;
  for (size_t q = pos; q-- > 0;)
    if (walked(cycles[q])) {
      previous = &cycles[q];
      break;
    }
  // The waits, each with what it waited for; the largest is named first.
  std::vector<std::pair<uint64_t, std::string>> waits;
  // On the port: the stage that takes a triangle from the port was busy with the previous one.
  const uint64_t port = pos == 0 ? c.accept_cycle : c.accept_cycle - (cycles[pos - 1].accept_cycle + 1);
  if (pos > 0 && port > 0)
    waits.push_back({port, plural(port, "cycle", "cycles") + " on the port before its accept: " +
                               words.port_stage + " busy with triangle " +
                               u(cycles[pos - 1].tri) + " until cycle " + u(c.accept_cycle - 1)});
  // A unit with a job stage: its box stage hands a triangle to the corner stage in the cycle the
  // port accepts the next one, so the next accept ends its wait in the box stage.
  if (words.job_stage && walked(c) && previous && pos + 1 < cycles.size()) {
    const uint64_t to_corner = cycles[pos + 1].accept_cycle;
    const uint64_t in_box = to_corner - (c.accept_cycle + 1);
    if (in_box > 0)
      waits.push_back({in_box, plural(in_box, "cycle", "cycles") +
                                   " in the box stage (B): corner stage busy with triangle " +
                                   u(previous->tri) + " until cycle " + u(to_corner - 1)});
  }
  if (walked(c)) {
    const uint64_t hold = c.handoff_cycle - c.setup_done_cycle;
    if (hold > 0) {
      // The walk stage's previous triangle ended its walk in handoff - 1.
      const std::string who = previous ? "triangle " + u(previous->tri) : "an earlier triangle";
      waits.push_back({hold, plural(hold, "cycle", "cycles") + " " + words.ready_wait +
                                 ": walk stage busy with " + who + " until cycle " +
                                 u(c.handoff_cycle - 1)});
    }
    if (c.stall_cycles > 0) {
      const bool sink_stalls = !sink_stall.empty() && sink_stall != "none";
      waits.push_back({c.stall_cycles,
                       plural(c.stall_cycles, "stall cycle", "stall cycles") + " " + words.stall +
                           " (" +
                           (sink_stalls ? sink_stalled(sink_stall)
                                        : std::string("the sink takes one span a cycle")) +
                           ")"});
    }
    // Its last span leaves the cycle after its push at the earliest.
    if (c.spans > 0 && c.done_cycle > c.walk_end_cycle + 1) {
      const uint64_t drain = c.done_cycle - (c.walk_end_cycle + 1);
      const bool sink_stalls = !sink_stall.empty() && sink_stall != "none";
      waits.push_back({drain, plural(drain, "cycle", "cycles") + " after its walk for its spans to leave the FIFO (" +
                                  (sink_stalls ? std::string("sink stalled") : std::string("earlier spans ahead")) + ")"});
    }
  }
  std::stable_sort(waits.begin(), waits.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  if (waits.empty()) {
    s += "; waited for nothing";
  } else {
    s += "; waited ";
    for (size_t i = 0; i < waits.size(); ++i) s += (i ? "; and " : "") + waits[i].second;
  }
  // The stage breakdown.
  if (!walked(c)) {
    s += "; " + words.retire + " in cycle " + u(c.setup_done_cycle) + " (no box to walk)";
    return s;
  }
  const uint64_t setup = c.setup_done_cycle - c.setup_start_cycle;
  s += "; " + words.setup_span + " " + plural(setup, "cycle", "cycles") + " (" +
       u(c.setup_start_cycle) + ".." + u(c.setup_done_cycle - 1);
  if (!words.setup_span_note.empty()) s += ", " + words.setup_span_note;
  // The job stage takes a job in the cycle its previous one leaves for the walk stage.
  if (words.job_stage && previous && previous->handoff_cycle > c.setup_start_cycle)
    s += "; the job stage took it in cycle " + u(previous->handoff_cycle) +
         " at the earliest, when triangle " + u(previous->tri) + " left it";
  if (c.divider_iterations + c.boundary_steps > 0)
    s += "; divider: " + plural(c.divider_iterations, "iteration", "iterations") +
         ", boundary: " + plural(c.boundary_steps, "step", "steps") + ", summed over the three lanes";
  s += ")";
  const uint64_t walk = c.walk_end_cycle + 1 - c.walk_start_cycle;
  s += "; hand-off " + u(c.handoff_cycle) + "; walk " + plural(walk, "cycle", "cycles") + " (" +
       u(c.walk_start_cycle) + ".." + u(c.walk_end_cycle) + ", box " + u(c.box_width) + "x" +
       u(c.box_height) + ")";
  return s;
}

namespace {

const char* const kColumns[] = {"accept_cycle",     "first_span_cycle", "done_cycle",
                                "spans",            "pixels",           "stall_cycles",
                                "setup_start_cycle", "setup_done_cycle", "handoff_cycle",
                                "walk_start_cycle", "walk_end_cycle",   "divider_iterations",
                                "boundary_steps",   "box_width",        "box_height"};

std::vector<uint64_t> columns(const TriangleCycles& c) {
  return {c.accept_cycle,      c.first_span_cycle, c.done_cycle,       c.spans,
          c.pixels,            c.stall_cycles,     c.setup_start_cycle, c.setup_done_cycle,
          c.handoff_cycle,     c.walk_start_cycle, c.walk_end_cycle,   c.divider_iterations,
          c.boundary_steps,    c.box_width,        c.box_height};
}

// For each run, the run its rows must equal (the first of its unit), or -1.
std::vector<int> unit_leaders(const std::vector<TimedCycles>& runs) {
  std::vector<int> leader(runs.size(), -1);
  std::map<std::string, int> first;
  for (size_t i = 0; i < runs.size(); ++i) {
    auto [it, fresh] = first.emplace(timing_unit(runs[i].engine), int(i));
    if (!fresh) leader[i] = it->second;
  }
  return leader;
}

}  // namespace

std::string joined_cycles_csv(const std::vector<TimedCycles>& runs) {
  std::string text = "tri";
  for (const TimedCycles& r : runs)
    for (const char* col : kColumns) text += "," + r.engine + "." + col;
  text += ",mismatch\n";
  const std::vector<int> leader = unit_leaders(runs);
  const size_t n = runs.empty() ? 0 : runs[0].cycles->size();
  for (size_t p = 0; p < n; ++p) {
    text += u((*runs[0].cycles)[p].tri);
    std::string mismatch;
    for (size_t i = 0; i < runs.size(); ++i) {
      const TriangleCycles& c = (*runs[i].cycles)[p];
      for (uint64_t v : columns(c)) text += "," + u(v);
      if (leader[i] >= 0 && columns(c) != columns((*runs[size_t(leader[i])].cycles)[p]))
        mismatch += (mismatch.empty() ? "" : " ") + runs[i].engine + "!=" + runs[size_t(leader[i])].engine;
    }
    text += "," + mismatch + "\n";
  }
  return text;
}

size_t count_cycle_mismatches(const std::vector<TimedCycles>& runs, std::string& first) {
  const std::vector<int> leader = unit_leaders(runs);
  size_t count = 0;
  const size_t n = runs.empty() ? 0 : runs[0].cycles->size();
  for (size_t p = 0; p < n; ++p) {
    bool differs = false;
    for (size_t i = 0; i < runs.size(); ++i) {
      if (leader[i] < 0) continue;
      const TimedCycles& b = runs[size_t(leader[i])];
      const std::vector<uint64_t> x = columns((*runs[i].cycles)[p]), y = columns((*b.cycles)[p]);
      for (size_t k = 0; k < x.size(); ++k)
        if (x[k] != y[k]) {
          if (!differs && count == 0)
            first = "triangle " + u((*b.cycles)[p].tri) + " " + kColumns[k] + ": " + runs[i].engine +
                    " " + u(x[k]) + ", " + b.engine + " " + u(y[k]);
          differs = true;
          break;
        }
    }
    if (differs) ++count;
  }
  return count;
}

void print_timed_cycles(const std::vector<std::pair<std::string, std::vector<TriangleCycles>>>& timed,
                        const DiagOptions& diag, const std::string& cycles_path,
                        const std::string& sink_stall) {
  if (timed.empty()) {
    for (const char* opt : {"--cycles", "--slowest", "--explain"})
      if ((opt[2] == 'c' && !cycles_path.empty()) || (opt[2] == 's' && diag.slowest) ||
          (opt[2] == 'e' && diag.explain))
        throw UsageError(std::string("trirast compare: ") + opt + ": none of --engines is timed");
    return;
  }
  std::vector<TimedCycles> runs;
  for (const auto& [name, cycles] : timed) runs.push_back({name, &cycles});
  for (const TimedCycles& r : runs)
    if (r.cycles->size() != runs[0].cycles->size())
      throw std::runtime_error("trirast compare: engines " + runs[0].engine + " and " + r.engine +
                               " report cycles of different triangle counts");
  // Engines of one unit must agree on every column.
  std::map<std::string, std::vector<std::string>> units;
  for (const TimedCycles& r : runs) units[timing_unit(r.engine)].push_back(r.engine);
  bool pairs = false;
  for (const auto& kv : units) pairs = pairs || kv.second.size() > 1;
  if (pairs) {
    std::string first;
    const size_t bad = count_cycle_mismatches(runs, first);
    std::string names;
    for (const auto& kv : units)
      if (kv.second.size() > 1) {
        for (size_t i = 0; i < kv.second.size(); ++i)
          names += (names.empty() || i == 0 ? (names.empty() ? "" : "; ") : " = ") + kv.second[i];
      }
    if (bad == 0)
      std::printf("  per-triangle cycles: %s agree on all 16 columns of %zu triangles\n",
                  names.c_str(), runs[0].cycles->size());
    else
      std::printf("  per-triangle cycles: MISMATCH: %zu triangles differ (%s); first: %s\n", bad,
                  names.c_str(), first.c_str());
  }
  if (!cycles_path.empty()) {
    OutputFile out(cycles_path, "--cycles");
    out.write(joined_cycles_csv(runs));
    out.commit();
    std::printf("  wrote %s (per-triangle cycles of", cycles_path.c_str());
    for (const TimedCycles& r : runs) std::printf(" %s", r.engine.c_str());
    std::printf(" side by side)\n");
  }
  for (const TimedCycles& r : runs) {
    const CycleWords& words = cycle_words(r.engine);
    if (diag.slowest) {
      const std::vector<size_t> slow = slowest_triangles(*r.cycles, diag.slowest);
      std::printf("  slowest %zu triangles of %s (cycles from accept to done):\n", slow.size(),
                  r.engine.c_str());
      for (size_t p : slow)
        std::printf("    %s\n", explain_triangle(*r.cycles, p, sink_stall, words).c_str());
    }
    if (diag.explain) {
      std::printf("  triangles %lld..%lld of %s:\n", (long long)diag.explain_first,
                  (long long)diag.explain_last, r.engine.c_str());
      size_t shown = 0;
      for (size_t p = 0; p < r.cycles->size(); ++p) {
        const int64_t idx = (*r.cycles)[p].tri;
        if (idx < diag.explain_first || idx > diag.explain_last) continue;
        std::printf("    %s\n", explain_triangle(*r.cycles, p, sink_stall, words).c_str());
        ++shown;
      }
      if (shown == 0) std::printf("    (none of them was set up: degenerate, culled or not in the scene)\n");
    }
  }
}

// ---- options ----

void add_diag_options(std::vector<OptionSpec>& specs, bool compare) {
  specs.push_back({"--export-tris", "A:B:FILE.tri",
                   "write set-up triangles A..B (scene indices) as a .tri file for a focused rerun", ""});
  specs.push_back({"--heatmap", "cycles|stalls|setup:FILE.png",
                   "timed engines: PNG of each triangle's cycles, stall cycles or set-up cycles" +
                       std::string(compare ? " (the first timed engine)" : ""),
                   ""});
  if (!compare) return;
  specs.push_back({"--cycles", "FILE.csv",
                   "the timed engines' per-triangle cycles side by side, mismatches flagged", ""});
  specs.push_back({"--slowest", "N", "name the N slowest triangles of each timed engine and what they waited for", ""});
  specs.push_back({"--explain", "A[:B]", "the same for triangles A..B (scene indices)", ""});
}

namespace {

bool parse_window(const std::string& text, int64_t& a, int64_t& b, size_t& used) {
  long long x = -1, y = -1;
  int n1 = 0, n2 = 0;
  if (std::sscanf(text.c_str(), "%lld%n:%lld%n", &x, &n1, &y, &n2) < 1 || x < 0) return false;
  if (n2 > 0) {
    if (y < x) return false;
    used = size_t(n2);
  } else {
    y = x;
    used = size_t(n1);
  }
  a = x;
  b = y;
  return true;
}

}  // namespace

DiagOptions diag_options_from(const Args& a, bool compare) {
  DiagOptions d;
  const std::string cmd = "trirast " + a.command() + ": ";
  if (a.has("--export-tris")) {
    const std::string v = a.get("--export-tris");
    size_t used = 0;
    if (!parse_window(v, d.export_first, d.export_last, used) || used >= v.size() || v[used] != ':' ||
        v.find(':') == used || used + 1 == v.size())
      throw UsageError(cmd + "--export-tris: expected A:B:FILE.tri with 0 <= A <= B, got '" + v + "'");
    d.export_path = v.substr(used + 1);
    d.export_tris = true;
    check_output_path(d.export_path, "--export-tris");
  }
  if (a.has("--heatmap")) {
    const std::string v = a.get("--heatmap");
    const size_t colon = v.find(':');
    d.heatmap_metric = v.substr(0, colon);
    if (colon == std::string::npos || colon + 1 == v.size() ||
        (d.heatmap_metric != "cycles" && d.heatmap_metric != "stalls" && d.heatmap_metric != "setup"))
      throw UsageError(cmd + "--heatmap: expected cycles:FILE.png, stalls:FILE.png or setup:FILE.png, got '" +
                       v + "'");
    d.heatmap_path = v.substr(colon + 1);
    check_output_path(d.heatmap_path, "--heatmap");
  }
  if (!compare) return d;
  if (a.has("--cycles")) check_output_path(a.get("--cycles"), "--cycles");
  if (a.has("--slowest")) d.slowest = size_t(a.get_int("--slowest", 1, 1000000));
  if (a.has("--explain")) {
    const std::string v = a.get("--explain");
    size_t used = 0;
    if (!parse_window(v, d.explain_first, d.explain_last, used) || used != v.size())
      throw UsageError(cmd + "--explain: expected A or A:B with 0 <= A <= B, got '" + v + "'");
    d.explain = true;
  }
  return d;
}

size_t export_tri_window(const SetupResult& setup, const RasterConfig& cfg, int64_t first,
                         int64_t last, const std::string& path, const std::string& option,
                         const std::string& scene_name) {
  OutputFile out(path, option);
  std::string text = "# trirast --export-tris " + std::to_string(first) + ":" + std::to_string(last) +
                     " of " + scene_name + ": the snapped vertices in pixels; rerun with --width " +
                     std::to_string(cfg.width) + " --height " + std::to_string(cfg.height) +
                     " --subpixel-bits " + std::to_string(cfg.subpixel_bits) + "\n";
  size_t count = 0;
  char line[256];
  for (const TriangleSetup& t : setup.tris) {
    if (int64_t(t.index) < first || int64_t(t.index) > last) continue;
    // The input's winding: setup swapped v1 and v2 of a counter-clockwise input.
    const int order[3] = {0, t.swapped ? 2 : 1, t.swapped ? 1 : 2};
    double xy[6];
    for (int k = 0; k < 3; ++k) {
      // v / 2^frac_bits is exact in a double and %.17g prints it back to the same double.
      xy[2 * k] = std::ldexp(double(t.v[order[k]].x), -cfg.frac_bits());
      xy[2 * k + 1] = std::ldexp(double(t.v[order[k]].y), -cfg.frac_bits());
    }
    const int n = std::snprintf(line, sizeof line, "%.17g %.17g %.17g %.17g %.17g %.17g  # tri %" PRIu32 "\n",
                                xy[0], xy[1], xy[2], xy[3], xy[4], xy[5], t.index);
    text.append(line, size_t(n));
    ++count;
  }
  out.write(text);
  out.commit();
  return count;
}

}  // namespace trirast
