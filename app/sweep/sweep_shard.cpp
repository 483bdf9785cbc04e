#include "sweep/sweep_shard.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>

#include "io/output_file.hpp"

namespace trirast {

namespace {

constexpr const char* kMagic = "trirast-sweep-result";

uint64_t fnv1a(uint64_t h, const void* data, size_t n) {
  const unsigned char* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= 1099511628211ull;
  }
  return h;
}

uint64_t fnv1a(uint64_t h, const std::string& s) { return fnv1a(h, s.data(), s.size() + 1); }

// The executable's bytes: results of another build are another version.
uint64_t build_hash() {
  static const uint64_t hash = [] {
    uint64_t h = 14695981039346656037ull;
    std::ifstream in("/proc/self/exe", std::ios::binary);
    std::vector<char> buf(1 << 16);
    while (in) {
      in.read(buf.data(), std::streamsize(buf.size()));
      h = fnv1a(h, buf.data(), size_t(in.gcount()));
    }
    return h;
  }();
  return hash;
}

std::string hex(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", v);
  return buf;
}

// One line: newlines become spaces (an error text is one line in the file).
std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

void make_dir(const std::string& d) {
  if (mkdir(d.c_str(), 0777) != 0 && errno != EEXIST)
    throw std::runtime_error("cannot create directory '" + d + "': " + std::strerror(errno));
}

void append_log(const std::string& dir, const std::string& line) {
  const std::string path = dir + "/run.log";
  const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0666);
  if (fd < 0) return;
  const std::string l = line + "\n";
  (void)!write(fd, l.data(), l.size());  // one write: lines of concurrent shards do not mix
  close(fd);
}

}  // namespace

std::vector<SweepTask> sweep_tasks(size_t points, size_t scenes) {
  std::vector<SweepTask> out;
  for (size_t s = 0; s < scenes; ++s)
    for (size_t p = 0; p < points; ++p) out.push_back({out.size(), p, s});
  return out;
}

ShardSpec parse_shard(const std::string& text) {
  const size_t slash = text.find('/');
  auto number = [&](const std::string& s, size_t& v) {
    if (s.empty() || s.size() > 9 || s.find_first_not_of("0123456789") != std::string::npos)
      return false;
    v = size_t(std::stoul(s));
    return true;
  };
  ShardSpec r;
  if (slash == std::string::npos || !number(text.substr(0, slash), r.k) ||
      !number(text.substr(slash + 1), r.n) || r.n == 0 || r.k >= r.n)
    throw std::invalid_argument("'" + text + "' is not K/N with 0 <= K < N");
  return r;
}

std::vector<SweepTask> shard_tasks(const std::vector<SweepTask>& all, const ShardSpec& s) {
  const size_t t = all.size();
  const size_t a = s.k * t / s.n, b = (s.k + 1) * t / s.n;
  return {all.begin() + long(a), all.begin() + long(b)};
}

std::string sweep_fingerprint(const std::vector<SweepPoint>& points,
                              const std::vector<SweepScene>& scenes, const RasterConfig& base) {
  uint64_t h = 14695981039346656037ull;
  h = fnv1a(h, std::string(kMagic) + " " + std::to_string(kSweepResultFormat));
  h = fnv1a(h, std::to_string(base.width) + "x" + std::to_string(base.height));
  for (const SweepPoint& p : points) h = fnv1a(h, p.label() + "|" + p.group);
  for (const SweepScene& s : scenes)
    h = fnv1a(h, s.spec + "|" + cull_mode_name(s.cull) + (s.closed ? "|closed" : ""));
  const uint64_t b = build_hash();
  h = fnv1a(h, &b, sizeof b);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%016" PRIx64, h);
  return buf;
}

std::string task_name(const SweepTask& t, const std::vector<SweepPoint>& points,
                      const std::vector<SweepScene>& scenes) {
  return "task " + std::to_string(t.index) + " (" + points[t.point].label() + " on " +
         scenes[t.scene].spec + ")";
}

std::string task_path(const std::string& dir, size_t index) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "/tasks/sim-%06zu.res", index);
  return dir + buf;
}

void write_task_result(const std::string& path, const std::string& fingerprint,
                       const SweepTask& t, const std::string& point_label,
                       const std::string& scene_spec, const SceneFigures& sc,
                       const PointResult& r) {
  std::ostringstream o;
  o << kMagic << " " << kSweepResultFormat << "\n"
    << "fingerprint " << fingerprint << "\n"
    << "task " << t.index << "\n"
    << "point " << one_line(point_label) << "\n"
    << "scene " << one_line(scene_spec) << "\n"
    << "scene_triangles " << sc.triangles << "\n"
    << "reference_triangles " << sc.reference_triangles << "\n"
    << "reference_pixels " << sc.reference_pixels << "\n"
    << "reference_cracks " << sc.reference_cracks << "\n"
    << "reference_doubles " << sc.reference_doubles << "\n"
    << "golden_seconds " << hex(sc.golden_seconds) << "\n"
    << "read " << r.read << "\n"
    << "offered " << r.offered << "\n"
    << "degenerate " << r.degenerate << "\n"
    << "culled " << r.culled << "\n"
    << "rejected_range " << r.rejected_range << "\n"
    << "rejected_width " << r.rejected_width << "\n"
    << "spans " << r.spans << "\n"
    << "pixels " << r.pixels << "\n"
    << "missing " << r.missing << "\n"
    << "extra " << r.extra << "\n"
    << "cracks " << r.cracks << "\n"
    << "doubles " << r.doubles << "\n"
    << "total_cycles " << r.total_cycles << "\n"
    << "divider_iterations " << r.divider_iterations << "\n"
    << "wall_seconds " << hex(r.wall_seconds) << "\n"
    << "error " << one_line(r.error) << "\n"
    << "end\n";
  OutputFile out(path, "--out");
  out.write(o.str());
  out.commit();
}

TaskResult read_task_result(const std::string& path, const std::string& fingerprint,
                            size_t index) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read result file");
  auto fail = [&](const std::string& why) -> std::runtime_error {
    return std::runtime_error(path + ": " + why);
  };
  std::string line;
  if (!std::getline(in, line) || line.rfind(kMagic, 0) != 0)
    throw fail("not a sweep result file (no '" + std::string(kMagic) + "' line)");
  const std::string version = line.substr(std::strlen(kMagic));
  if (version != " " + std::to_string(kSweepResultFormat))
    throw fail("result format" + version + ", this trirast reads " +
               std::to_string(kSweepResultFormat) + ": mixed versions are not merged");
  std::map<std::string, std::string> kv;
  bool ended = false;
  while (std::getline(in, line)) {
    if (line == "end") {
      ended = true;
      break;
    }
    const size_t sp = line.find(' ');
    kv[line.substr(0, sp)] = sp == std::string::npos ? "" : line.substr(sp + 1);
  }
  if (!ended) throw fail("cut short (no 'end' line): rerun its task");
  if (kv["fingerprint"] != fingerprint)
    throw fail("fingerprint " + kv["fingerprint"] + " is not this task list's and build's (" +
               fingerprint + "): mixed versions are not merged");
  if (kv["task"] != std::to_string(index))
    throw fail("holds task '" + kv["task"] + "', not task " + std::to_string(index));
  auto u64 = [&](const char* k) -> uint64_t {
    const std::string& v = kv[k];
    char* end = nullptr;
    errno = 0;
    const unsigned long long x = std::strtoull(v.c_str(), &end, 10);
    if (v.empty() || *end || errno) throw fail(std::string("malformed '") + k + "'");
    return x;
  };
  auto i64 = [&](const char* k) -> int64_t {
    const std::string& v = kv[k];
    char* end = nullptr;
    errno = 0;
    const long long x = std::strtoll(v.c_str(), &end, 10);
    if (v.empty() || *end || errno) throw fail(std::string("malformed '") + k + "'");
    return x;
  };
  auto dbl = [&](const char* k) -> double {
    const std::string& v = kv[k];
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    if (v.empty() || *end) throw fail(std::string("malformed '") + k + "'");
    return x;
  };
  if (!kv.count("error")) throw fail("no 'error' line");
  TaskResult t;
  t.scene.triangles = u64("scene_triangles");
  t.scene.reference_triangles = u64("reference_triangles");
  t.scene.reference_pixels = i64("reference_pixels");
  t.scene.reference_cracks = i64("reference_cracks");
  t.scene.reference_doubles = i64("reference_doubles");
  t.scene.golden_seconds = dbl("golden_seconds");
  PointResult& r = t.result;
  r.read = u64("read");
  r.offered = u64("offered");
  r.degenerate = u64("degenerate");
  r.culled = u64("culled");
  r.rejected_range = u64("rejected_range");
  r.rejected_width = u64("rejected_width");
  r.spans = u64("spans");
  r.pixels = i64("pixels");
  r.missing = i64("missing");
  r.extra = i64("extra");
  r.cracks = i64("cracks");
  r.doubles = i64("doubles");
  r.total_cycles = u64("total_cycles");
  r.divider_iterations = u64("divider_iterations");
  r.wall_seconds = dbl("wall_seconds");
  r.error = kv["error"];
  return t;
}

bool task_result_complete(const std::string& path, const std::string& fingerprint,
                          size_t index) {
  struct stat st;
  if (stat(path.c_str(), &st) != 0) return false;
  try {
    read_task_result(path, fingerprint, index);
    return true;
  } catch (const std::exception&) {
    return false;  // cut short or of another version: the task runs again
  }
}

ShardOutcome run_shard(const std::string& dir, const std::string& fingerprint,
                       const std::vector<SweepTask>& tasks, const std::vector<SweepPoint>& points,
                       const std::vector<SweepScene>& scenes, const RasterConfig& base) {
  make_dir(dir);
  make_dir(dir + "/tasks");
  ShardOutcome o;
  std::unique_ptr<SweepSceneData> loaded;  // one scene at a time (tasks are scene-major)
  size_t loaded_index = size_t(-1);
  for (const SweepTask& t : tasks) {
    const std::string path = task_path(dir, t.index);
    if (task_result_complete(path, fingerprint, t.index)) {
      ++o.skipped;
      append_log(dir, "skipped " + std::to_string(t.index));
      continue;
    }
    if (loaded_index != t.scene) {
      loaded.reset();
      loaded = std::make_unique<SweepSceneData>(load_sweep_scene(scenes[t.scene], base));
      loaded_index = t.scene;
    }
    const PointResult r = run_sweep_point(points[t.point], *loaded);
    SceneFigures f;
    f.triangles = loaded->scene.tris.size();
    f.reference_triangles = loaded->reference_triangles;
    f.reference_pixels = loaded->reference_pixels;
    f.reference_cracks = loaded->reference_cracks;
    f.reference_doubles = loaded->reference_doubles;
    f.golden_seconds = loaded->golden_seconds;
    write_task_result(path, fingerprint, t, points[t.point].label(), scenes[t.scene].spec, f, r);
    ++o.ran;
    if (r.error.empty()) {
      append_log(dir, "ran " + std::to_string(t.index));
    } else {
      ++o.failed;
      append_log(dir, "failed " + std::to_string(t.index) + ": " + one_line(r.error));
      std::fprintf(stderr, "trirast sweep: %s failed: %s\n",
                   task_name(t, points, scenes).c_str(), one_line(r.error).c_str());
    }
  }
  return o;
}

void merge_task_results(const std::string& dir, const std::string& fingerprint,
                        const std::vector<SweepPoint>& points,
                        const std::vector<SweepScene>& scene_specs, bool allow_partial,
                        std::vector<SweepSceneData>& scenes,
                        std::vector<std::vector<PointResult>>& results,
                        std::vector<std::string>& missing) {
  struct stat st;
  if (stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    throw std::runtime_error("sweep: --merge: '" + dir + "' is not a directory");
  const std::vector<SweepTask> tasks = sweep_tasks(points.size(), scene_specs.size());
  scenes.assign(scene_specs.size(), SweepSceneData{});
  std::vector<bool> have_scene(scene_specs.size(), false);
  results.assign(points.size(), std::vector<PointResult>(scene_specs.size()));
  missing.clear();
  for (const SweepTask& t : tasks) {
    const std::string path = task_path(dir, t.index);
    if (stat(path.c_str(), &st) != 0) {
      missing.push_back(task_name(t, points, scene_specs));
      results[t.point][t.scene].error = "no result file (task " + std::to_string(t.index) + ")";
      continue;
    }
    const TaskResult r = read_task_result(path, fingerprint, t.index);
    results[t.point][t.scene] = r.result;
    if (!have_scene[t.scene]) {
      SweepSceneData& d = scenes[t.scene];
      d.spec = scene_specs[t.scene];
      d.scene.name = d.spec.spec;
      d.scene.tris.resize(size_t(r.scene.triangles));  // only its size is reported
      d.reference_triangles = r.scene.reference_triangles;
      d.reference_pixels = r.scene.reference_pixels;
      d.reference_cracks = r.scene.reference_cracks;
      d.reference_doubles = r.scene.reference_doubles;
      d.golden_seconds = r.scene.golden_seconds;
      have_scene[t.scene] = true;
    }
  }
  for (size_t s = 0; s < scenes.size(); ++s)
    if (!have_scene[s]) {
      scenes[s].spec = scene_specs[s];
      scenes[s].scene.name = scene_specs[s].spec;
    }
  if (!missing.empty() && !allow_partial) {
    std::string names;
    for (size_t i = 0; i < missing.size() && i < 3; ++i) names += (i ? ", " : "") + missing[i];
    if (missing.size() > 3) names += ", ...";
    throw std::runtime_error("sweep: --merge: " + std::to_string(missing.size()) + " of " +
                             std::to_string(tasks.size()) + " tasks have no result file in " +
                             dir + "/tasks: " + names +
                             " (rerun them, or --allow-partial for a partial merge)");
  }
}

std::vector<SynthRow> read_synth_results(const std::string& dir) {
  std::vector<SynthRow> rows;
  const std::string sd = dir + "/synth";
  DIR* d = opendir(sd.c_str());
  if (!d) return rows;
  std::vector<std::string> files;
  while (dirent* e = readdir(d)) {
    const std::string n = e->d_name;
    if (n.size() > 6 && n.compare(n.size() - 6, 6, ".synth") == 0) files.push_back(sd + "/" + n);
  }
  closedir(d);
  std::sort(files.begin(), files.end());
  for (const std::string& path : files) {
    std::ifstream in(path);
    std::string line;
    std::vector<std::string> lines;
    while (std::getline(in, line)) lines.push_back(line);
    if (lines.empty() || lines.front() != "# trirast-synth-result 1")
      throw std::runtime_error(path + ": not a synthesis result of format 1 "
                               "(scripts/synth.sh --one): mixed versions are not merged");
    if (lines.back() != "# end") throw std::runtime_error(path + ": cut short (no '# end' line)");
    if (lines.size() < 4) throw std::runtime_error(path + ": no result row");
    std::vector<std::string> head;
    {
      std::stringstream ss(lines[1]);
      std::string f;
      while (std::getline(ss, f, ',')) head.push_back(f);
    }
    for (size_t i = 2; i + 1 < lines.size(); ++i) {
      std::map<std::string, std::string> kv;
      std::stringstream ss(lines[i]);
      std::string f;
      for (size_t c = 0; std::getline(ss, f, ','); ++c)
        if (c < head.size()) kv[head[c]] = f;
      SynthRow r;
      r.unit = kv["unit"];
      r.config = kv["config"];
      r.target = kv["target"];
      r.origin = path;
      try {
        r.luts = std::stod(kv["luts"]);
        r.ffs = std::stod(kv["ffs"]);
        r.subpixel_bits = std::stoi(kv["subpixel_bits"]);
        r.coord_bits = std::stoi(kv["coord_bits"]);
        r.box_bits = std::stoi(kv["box_bits"]);
        r.endpoints = std::stoi(kv["endpoints"]);
        if (!kv["fmax_mhz"].empty()) r.fmax_mhz = std::stod(kv["fmax_mhz"]);
      } catch (const std::exception&) {
        throw std::runtime_error(path + ":" + std::to_string(i + 1) +
                                 ": malformed row (a synthesis that failed leaves no file)");
      }
      rows.push_back(r);
    }
  }
  return rows;
}

std::string synth_todo(const std::vector<SweepPoint>& points,
                       const std::vector<PointSummary>& summaries,
                       std::vector<std::string>& no_rtl) {
  std::string out;
  std::set<std::string> seen;
  no_rtl.clear();
  const RasterConfig def;
  for (size_t p = 0; p < points.size(); ++p) {
    const PointSummary& s = summaries[p];
    const RasterConfig& c = points[p].cfg;
    const UnitKind k = points[p].kind();
    if (s.whatif_cycles || s.whatif_area) no_rtl.push_back(points[p].label());
    if (!points[p].rtl() || !s.area.known() || s.area.from_run) continue;
    // The sweep's synthesis jobs build the improved, traditional and second-generation units at
    // given widths; the half-space unit's area comes from docs/synth.csv (scripts/synth.sh, per
    // stamp size).

    if (k == UnitKind::Halfspace) continue;
    // The default configurations of both units: the estimate's calibration point and the
    // improved-vs-traditional area comparison.
    const bool reference = c.subpixel_bits == def.subpixel_bits &&
                           c.coord_int_bits == def.coord_int_bits &&
                           (k == UnitKind::Trad ||
                            (c.box_bits == def.box_bits && c.endpoints == 1)) &&
                           k != UnitKind::Improved2;  // a reference of the first generation
    if (!(s.pareto_cycles || s.pareto_area || reference)) continue;
    const std::string line = synth_unit_name(k, c) + ":" +
                             std::to_string(c.subpixel_bits) + ":" +
                             std::to_string(c.coord_int_bits) + ":" +
                             std::to_string(k == UnitKind::Trad ? 14 : c.box_bits) + ":" +
                             std::to_string(k == UnitKind::Improved ? c.endpoints : 1);
    if (seen.insert(line).second) out += line + "\n";
  }
  return out;
}

}  // namespace trirast
