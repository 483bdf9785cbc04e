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
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "io/output_file.hpp"

namespace trirast {

namespace {

using nlohmann::ordered_json;

constexpr const char* kFormatName = "trirast-sweep-result";
constexpr const char* kSimulationKind = "simulation";
constexpr const char* kSynthesisKind = "synthesis";

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

// One line: newlines become spaces (an error text is one line of run.log or stderr).
std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

// The members every result file starts with.
ordered_json result_file_header(const char* kind) {
  ordered_json j = ordered_json::object();
  j["format"] = kFormatName;
  j["version"] = kSweepResultFormat;
  j["kind"] = kind;
  return j;
}

// Doubles are written with the digits that read back to the same double.
std::string dump_result(const ordered_json& j, int indent) {
  const std::string text = j.dump(indent, ' ', false, ordered_json::error_handler_t::replace);
  return indent >= 0 ? text + "\n" : text;
}

// nlohmann's parse error without its "[json.exception.parse_error.101] " tag.
std::string parse_error_text(const nlohmann::json::parse_error& e) {
  const std::string what = e.what();
  const size_t tag = what.find("] ");
  return tag == std::string::npos ? what : what.substr(tag + 2);
}

// The typed members of an object of a result file: a member that is missing or of another type
// is an error naming the file and the member ("FILE: malformed 'result.pixels'").
class Fields {
 public:
  Fields(const nlohmann::json& j, std::string path, std::string prefix = "")
      : j_(j), path_(std::move(path)), prefix_(std::move(prefix)) {}

  std::runtime_error fail(const std::string& why) const {
    return std::runtime_error(path_.empty() ? why : path_ + ": " + why);
  }
  bool has(const char* key) const { return j_.is_object() && j_.contains(key); }
  bool is_null(const char* key) const { return at(key).is_null(); }
  uint64_t u64(const char* key) const {
    const nlohmann::json& v = at(key);
    if (!v.is_number_unsigned()) throw malformed(key);
    return v.get<uint64_t>();
  }
  int64_t i64(const char* key) const {
    const nlohmann::json& v = at(key);
    if (v.is_number_unsigned() && v.get<uint64_t>() > uint64_t(INT64_MAX)) throw malformed(key);
    if (!v.is_number_integer()) throw malformed(key);
    return v.get<int64_t>();
  }
  int i32(const char* key) const {
    const int64_t v = i64(key);
    if (v < INT32_MIN || v > INT32_MAX) throw malformed(key);
    return int(v);
  }
  double dbl(const char* key) const {
    const nlohmann::json& v = at(key);
    if (!v.is_number()) throw malformed(key);
    return v.get<double>();
  }
  std::string str(const char* key) const {
    const nlohmann::json& v = at(key);
    if (!v.is_string()) throw malformed(key);
    return v.get<std::string>();
  }
  // The member `key` into v, by v's type (point_result_fields).
  void read(const char* key, uint64_t& v) const { v = u64(key); }
  void read(const char* key, int64_t& v) const { v = i64(key); }
  void read(const char* key, double& v) const { v = dbl(key); }
  void read(const char* key, std::string& v) const { v = str(key); }
  Fields object(const char* key) const {
    const nlohmann::json& v = at(key);
    if (!v.is_object()) throw malformed(key);
    return Fields(v, path_, prefix_ + key + ".");
  }
  const nlohmann::json& array(const char* key) const {
    const nlohmann::json& v = at(key);
    if (!v.is_array()) throw malformed(key);
    return v;
  }
  Fields element(const char* key, size_t i) const {
    const nlohmann::json& v = array(key)[i];
    const std::string name = prefix_ + key + "[" + std::to_string(i) + "]";
    if (!v.is_object()) throw fail("malformed '" + name + "'");
    return Fields(v, path_, name + ".");
  }

 private:
  const nlohmann::json& at(const char* key) const {
    if (!has(key)) throw fail("no '" + prefix_ + key + "'");
    return j_.at(key);
  }
  std::runtime_error malformed(const char* key) const {
    return fail("malformed '" + prefix_ + key + "'");
  }
  const nlohmann::json& j_;
  std::string path_, prefix_;
};

// Reads a result file of `kind` and checks what every result file holds: complete JSON (a file
// cut short ends before its last brace), this format and version, this kind.
nlohmann::json read_result_file(const std::string& path, const char* kind) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot read result file");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  auto fail = [&](const std::string& why) { return std::runtime_error(path + ": " + why); };
  auto mixed = [&](const std::string& version) {
    return fail("result format " + version + ", this trirast reads " +
                std::to_string(kSweepResultFormat) + ": mixed versions are not merged");
  };
  // The text formats before this one began with a line naming the format and its version.
  for (const std::string old : {"trirast-sweep-result ", "# trirast-synth-result "})
    if (text.rfind(old, 0) == 0)
      throw mixed(text.substr(old.size(), text.find('\n') - old.size()) + " (text)");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    if (e.byte > text.size()) throw fail("cut short (the JSON ends early): rerun its task");
    throw fail("not a sweep result file (" + parse_error_text(e) + ")");
  }
  const auto format = j.is_object() ? j.find("format") : j.end();
  if (format == j.end() || *format != kFormatName)
    throw fail(std::string("not a sweep result file (no \"format\": \"") + kFormatName + "\")");
  const Fields f(j, path);
  const int64_t version = f.i64("version");
  if (version != kSweepResultFormat) throw mixed(std::to_string(version));
  const std::string k = f.str("kind");
  if (k != kind) throw fail("holds a " + k + " result, not a " + kind + " result");
  return j;
}

// A point's result record, member by member in file order with its key: the one list the writer
// (point_result_record) and the reader (point_result_from) go through. Result is PointResult,
// const or not.
template <class Result, class Visit>
void point_result_fields(Result& r, Visit visit) {
  visit("read", r.read);
  visit("offered", r.offered);
  visit("degenerate", r.degenerate);
  visit("culled", r.culled);
  visit("rejected_range", r.rejected_range);
  visit("rejected_width", r.rejected_width);
  visit("spans", r.spans);
  visit("pixels", r.pixels);
  visit("missing", r.missing);
  visit("extra", r.extra);
  visit("cracks", r.cracks);
  visit("doubles", r.doubles);
  visit("total_cycles", r.total_cycles);
  visit("divider_iterations", r.divider_iterations);
  visit("wall_seconds", r.wall_seconds);
  visit("error", r.error);
}

ordered_json point_result_record(const PointResult& r) {
  ordered_json j = ordered_json::object();
  point_result_fields(r, [&](const char* key, const auto& v) { j[key] = v; });
  return j;
}

PointResult point_result_from(const Fields& f) {
  PointResult r;
  point_result_fields(r, [&](const char* key, auto& v) { f.read(key, v); });
  return r;
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
  h = fnv1a(h, std::string(kFormatName) + " " + std::to_string(kSweepResultFormat));
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
  ordered_json j = result_file_header(kSimulationKind);
  j["fingerprint"] = fingerprint;
  j["task"] = t.index;
  j["point"] = point_label;
  j["scene"] = scene_spec;
  j["scene_figures"] = {{"triangles", sc.triangles},
                        {"reference_triangles", sc.reference_triangles},
                        {"reference_pixels", sc.reference_pixels},
                        {"reference_cracks", sc.reference_cracks},
                        {"reference_doubles", sc.reference_doubles},
                        {"golden_seconds", sc.golden_seconds}};
  j["result"] = point_result_record(r);
  OutputFile out(path, "--out");
  out.write(dump_result(j, 2));
  out.commit();
}

std::string encode_point_result(const PointResult& r) {
  return dump_result(point_result_record(r), -1);
}

PointResult decode_point_result(const std::string& text) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::runtime_error("not JSON: " + parse_error_text(e));
  }
  return point_result_from(Fields(j, ""));
}

TaskResult read_task_result(const std::string& path, const std::string& fingerprint,
                            size_t index) {
  const nlohmann::json j = read_result_file(path, kSimulationKind);
  const Fields f(j, path);
  const std::string fp = f.str("fingerprint");
  if (fp != fingerprint)
    throw f.fail("fingerprint " + fp + " is not this task list's and build's (" + fingerprint +
                 "): mixed versions are not merged");
  const uint64_t task = f.u64("task");
  if (task != index)
    throw f.fail("holds task " + std::to_string(task) + ", not task " + std::to_string(index));
  TaskResult t;
  const Fields sc = f.object("scene_figures");
  t.scene.triangles = sc.u64("triangles");
  t.scene.reference_triangles = sc.u64("reference_triangles");
  t.scene.reference_pixels = sc.i64("reference_pixels");
  t.scene.reference_cracks = sc.i64("reference_cracks");
  t.scene.reference_doubles = sc.i64("reference_doubles");
  t.scene.golden_seconds = sc.dbl("golden_seconds");
  t.result = point_result_from(f.object("result"));
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
    const nlohmann::json j = read_result_file(path, kSynthesisKind);
    const Fields f(j, path);
    const size_t n = f.array("rows").size();
    if (n == 0) throw f.fail("no result row");
    for (size_t i = 0; i < n; ++i) {
      const Fields row = f.element("rows", i);
      SynthRow r;
      r.unit = row.str("unit");
      r.config = row.str("config");
      r.target = row.str("target");
      r.origin = path;
      r.luts = row.dbl("luts");
      r.ffs = row.dbl("ffs");
      r.subpixel_bits = row.i32("subpixel_bits");
      r.coord_bits = row.i32("coord_bits");
      r.box_bits = row.i32("box_bits");
      r.endpoints = row.i32("endpoints");
      // null: no place and route (Fmax unknown).
      if (row.has("fmax_mhz") && !row.is_null("fmax_mhz")) r.fmax_mhz = row.dbl("fmax_mhz");
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
