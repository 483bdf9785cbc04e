// trirast sweep / fit (docs/speed-vs-error.md).
// sweep: engines x configurations x scenes, each point against the golden at S = 8 on the same
//        float input; writes sweep.csv (per scene), sweep_configs.csv (per configuration) and
//        sweep.json. --jobs N runs points in N worker processes (the SystemC kernel is one per
//        process, so the workers are forked, not threads).
// fit:   the smallest configuration that is exact on a scene, or within an error budget.
#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <sstream>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/scene_options.hpp"
#include "cli/source_files.hpp"
#include "common/temporary_files.hpp"
#include "common/engine.hpp"
#include "engines.hpp"
#include "io/json.hpp"
#include "io/output_file.hpp"
#include "sweep/sweep.hpp"
#include "sweep/sweep_area.hpp"
#include "sweep/sweep_shard.hpp"
#include "util.hpp"

namespace trirast {

namespace {

// The items of an option's list, empty ones skipped ("a,,b" is a, b).
std::vector<std::string> nonempty_items(const std::string& s, char sep) {
  std::vector<std::string> out = split(s, sep);
  out.erase(std::remove(out.begin(), out.end(), std::string()), out.end());
  return out;
}

// ---- progress ---------------------------------------------------------------------------------

class Progress {
 public:
  Progress(size_t total, bool enabled) : total_(total), enabled_(enabled), tty_(isatty(2)) {}
  void step(size_t done) {
    if (!enabled_ || total_ == 0) return;
    const double t = seconds_since(t0_);
    if (tty_) {
      if (done != total_ && t - last_ < 0.1) return;
      last_ = t;
      const int width = 30, filled = int(width * done / total_);
      const double eta = done ? t * double(total_ - done) / double(done) : 0.0;
      std::fprintf(stderr, "\r  sweep [%s%s] %zu/%zu  %3d%%  %.0f s elapsed, ~%.0f s left  ",
                   std::string(size_t(filled), '#').c_str(),
                   std::string(size_t(width - filled), '.').c_str(), done, total_,
                   int(100 * done / total_), t, eta);
      if (done == total_) std::fprintf(stderr, "\n");
    } else {
      // Not a terminal (a log): one line per tenth.
      const size_t tenth = 10 * done / total_;
      if (tenth == shown_ && done != total_) return;
      shown_ = tenth;
      std::fprintf(stderr, "  sweep: %zu/%zu points (%d%%), %.0f s\n", done, total_,
                   int(100 * done / total_), t);
    }
    std::fflush(stderr);
  }

 private:
  size_t total_;
  bool enabled_, tty_;
  Clock::time_point t0_ = Clock::now();
  double last_ = -1;
  size_t shown_ = 0;
};

// ---- worker processes -------------------------------------------------------------------------

// A PointResult comes back through the pipe as encode_point_result's JSON (a simulation result
// file's "result"); one that does not decode is the point's error.
PointResult decode(const std::string& s) {
  try {
    return decode_point_result(s);
  } catch (const std::exception& e) {
    PointResult r;
    r.error = std::string("worker: malformed result (") + e.what() + ")";
    return r;
  }
}

bool write_all(int fd, const void* data, size_t n) {
  const char* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    p += w;
    n -= size_t(w);
  }
  return true;
}

bool read_all(int fd, void* data, size_t n) {
  char* p = static_cast<char*>(data);
  while (n > 0) {
    const ssize_t r = ::read(fd, p, n);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) return false;
    p += r;
    n -= size_t(r);
  }
  return true;
}

struct Task {
  size_t point, scene;
};

struct Worker {
  pid_t pid = -1;
  int to_child = -1, from_child = -1;
  long task = -1;  // index into the task list, -1 when idle
};

// Forks a worker: it reads task indices, runs them and writes their results back, until its input
// closes. It inherits the loaded scenes and references (copy on write).
Worker spawn_worker(const std::vector<Task>& tasks, const std::vector<SweepPoint>& points,
                    const std::vector<SweepSceneData>& scenes) {
  int down[2], up[2];
  if (pipe(down) != 0 || pipe(up) != 0) throw std::runtime_error("sweep: pipe failed");
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("sweep: fork failed");
  if (pid == 0) {
    close(down[1]);
    close(up[0]);
    uint64_t index;
    while (read_all(down[0], &index, sizeof index)) {
      const Task& t = tasks[size_t(index)];
      const std::string msg = encode_point_result(run_sweep_point(points[t.point], scenes[t.scene]));
      const uint64_t len = msg.size();
      if (!write_all(up[1], &len, sizeof len) || !write_all(up[1], msg.data(), msg.size())) break;
    }
    _exit(0);
  }
  close(down[0]);
  close(up[1]);
  Worker w;
  w.pid = pid;
  w.to_child = down[1];
  w.from_child = up[0];
  return w;
}

void run_parallel(const std::vector<Task>& tasks, const std::vector<SweepPoint>& points,
                  const std::vector<SweepSceneData>& scenes, int jobs,
                  std::vector<std::vector<PointResult>>& results, Progress& progress) {
  struct sigaction ignore {}, old {};
  ignore.sa_handler = SIG_IGN;
  sigaction(SIGPIPE, &ignore, &old);  // a dead worker must not kill the sweep
  std::vector<Worker> workers;
  size_t next = 0, done = 0;
  auto give = [&](Worker& w) {
    if (next >= tasks.size()) {
      close(w.to_child);
      w.to_child = -1;
      return;
    }
    const uint64_t index = next;
    if (!write_all(w.to_child, &index, sizeof index)) return;  // died: found on its pipe
    w.task = long(next++);
  };
  for (int j = 0; j < jobs && size_t(j) < tasks.size(); ++j) {
    workers.push_back(spawn_worker(tasks, points, scenes));
    give(workers.back());
  }
  while (done < tasks.size()) {
    std::vector<pollfd> fds;
    for (const Worker& w : workers) fds.push_back({w.from_child, POLLIN, 0});
    if (poll(fds.data(), fds.size(), -1) < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("sweep: poll failed");
    }
    for (size_t i = 0; i < workers.size(); ++i) {
      if (!(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      Worker& w = workers[i];
      uint64_t len = 0;
      std::string msg;
      bool ok = read_all(w.from_child, &len, sizeof len);
      if (ok) {
        msg.resize(size_t(len));
        ok = read_all(w.from_child, msg.data(), msg.size());
      }
      if (ok && w.task >= 0) {
        const Task& t = tasks[size_t(w.task)];
        results[t.point][t.scene] = decode(msg);
        w.task = -1;
        progress.step(++done);
        give(w);
        continue;
      }
      // The worker died (a crash in an engine): its task fails, a new worker takes over.
      int status = 0;
      if (w.to_child >= 0) close(w.to_child);
      close(w.from_child);
      waitpid(w.pid, &status, 0);
      if (w.task >= 0) {
        const Task& t = tasks[size_t(w.task)];
        results[t.point][t.scene].error =
            WIFSIGNALED(status) ? "worker died of signal " + std::to_string(WTERMSIG(status))
                                : "worker exited";
        progress.step(++done);
      }
      workers[i] = Worker{};
      workers[i].from_child = -1;
      if (next < tasks.size()) {
        workers[i] = spawn_worker(tasks, points, scenes);
        give(workers[i]);
      }
    }
    workers.erase(std::remove_if(workers.begin(), workers.end(),
                                 [](const Worker& w) { return w.from_child < 0; }),
                  workers.end());
    if (workers.empty() && done < tasks.size()) throw std::runtime_error("sweep: no workers left");
  }
  for (Worker& w : workers) {
    if (w.to_child >= 0) close(w.to_child);
    close(w.from_child);
    waitpid(w.pid, nullptr, 0);
  }
  sigaction(SIGPIPE, &old, nullptr);
}

void write_text(const std::string& path, const std::string& text, const std::string& option) {
  OutputFile out(path, option);
  out.write(text);
  out.commit();
}

std::string command_line(int argc, char** argv) {
  std::string s = "trirast";
  for (int i = 1; i < argc; ++i) s += std::string(" ") + argv[i];
  return s;
}

Json area_model_json(const AreaModel& area, const std::string& csv) {
  Json rows = Json::array();
  for (const SynthRow& r : area.rows()) {
    Json row = Json::object()
                   .set("unit", r.unit)
                   .set("config", r.config)
                   .set("target", r.target)
                   .set("subpixel_bits", r.subpixel_bits)
                   .set("coord_bits", r.coord_bits)
                   .set("box_bits", r.box_bits)
                   .set("luts", r.luts)
                   .set("ffs", r.ffs)
                   .set("endpoints", r.endpoints)
                   .set("file", r.origin.empty() ? csv : r.origin)
                   .set("from_run", r.from_run);
    // The width formula's figures for the same widths (the units that have one).
    const bool g2 = r.unit == "improved2" || r.unit == "improved2-products";
    if (r.unit == "improved" || r.unit == "trad" || g2) {
      RasterConfig c;
      c.subpixel_bits = r.subpixel_bits;
      c.coord_int_bits = r.coord_bits;
      c.box_bits = r.box_bits;
      c.endpoints = r.endpoints;
      c.improved2.corner_form = r.unit == "improved2-products" ? 0 : 1;
      const Area e = area.estimate(r.unit == "trad" ? UnitKind::Trad
                                   : g2             ? UnitKind::Improved2
                                                    : UnitKind::Improved,
                                   c);
      if (e.known()) row.set("estimate", Json::object().set("luts", e.luts).set("ffs", e.ffs));
    }
    rows.push(std::move(row));
  }
  const RasterConfig def;
  const Area imp = area.area(UnitKind::Improved, def), trad = area.area(UnitKind::Trad, def);
  const AreaTerms ti = improved_area_terms(def), tt = trad_area_terms(def);
  return Json::object()
      .set("synth_csv", csv)
      .set("have_synth", area.have_synth())
      .set("target", area.target())
      .set("lut_scale", area.lut_scale())
      .set("ff_scale", area.ff_scale())
      .set("formula", area.formula_text())
      .set("synth_rows", rows)
      .set("default_improved", Json::object()
                                   .set("luts", imp.luts)
                                   .set("ffs", imp.ffs)
                                   .set("source", imp.source)
                                   .set("formula_luts", ti.luts)
                                   .set("formula_ffs", ti.ffs))
      .set("default_trad", Json::object()
                               .set("luts", trad.luts)
                               .set("ffs", trad.ffs)
                               .set("source", trad.source)
                               .set("formula_luts", tt.luts)
                               .set("formula_ffs", tt.ffs));
}

// Whether an engine runs at all in this build (an RTL harness without its Verilated model may
// throw): tried on an empty scene in a child process, so the SystemC kernel is not started here.
bool engine_runs(const std::string& name) {
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = fork();
  if (pid < 0) return true;  // cannot tell: let the points fail one by one
  if (pid == 0) {
    try {
      SetupResult empty;
      EngineResult out;
      find_engine(name)->make()->run(empty, RasterConfig{}, out);
    } catch (...) {
      _exit(1);
    }
    _exit(0);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace

// --synth-csv / --synth-script as given, else the file in the source tree (any working folder).
std::string synth_file(const Args& a, const std::string& option, const std::string& relative) {
  return a.has(option) ? a.get(option) : source_file(relative);
}

// ---------------------------------------------------------------------------------------------
int cmd_sweep(int argc, char** argv) {
  Args a("sweep", "[--quick] [--jobs N] [--out DIR] [options]",
         {
             {"--quick", "", "a small sweep (3 small scenes, ~20 configurations) for the test suite", ""},
             {"--jobs", "N", "worker processes running points in parallel, 1..64", "1"},
             {"--out", "DIR", "output directory (created): sweep.csv, sweep_configs.csv, sweep.json; with --shard / --task: the results directory (DIR/tasks, DIR/run.log)", "sweep-out"},
             {"--scenes", "LIST", "';'-separated SPEC[@back|@front][@closed] (closed: count cracks and double hits); default: the built-in list", ""},
             {"--engines", "LIST", "comma-separated engines to sweep: golden,improved-sc,trad-sc,float-scanline,improved-rtl (default) and improved-datapath, halfspace-sc, halfspace-datapath, halfspace-rtl (the half-space unit over its stamp, tile and walk; area where scripts/synth.sh synthesized it), improved2-sc, improved2-datapath (the second-generation unit at the improved unit's widths with N = 1, corner form dsp / radix16; area where scripts/synth.sh or the sweep's synthesis jobs synthesized that form at those widths)", ""},
             {"--width", "W", "viewport width in pixels", "1024"},
             {"--height", "H", "viewport height in pixels", "768"},
             {"--synth-csv", "FILE", "synthesis results (unit,config,target,luts,ffs,...); missing file = estimates only", "docs/synth.csv of the source tree"},
             {"--synth-script", "FILE", "scripts/synth.sh, whose CONFIGS line names the synthesized widths", "scripts/synth.sh of the source tree"},
             {"--no-progress", "", "no progress bar on stderr", ""},
             {"--list-tasks", "", "print the task list (index, configuration, scene) and exit", ""},
             {"--shard", "K/N", "run tasks [K*T/N, (K+1)*T/N) of the T tasks, one result file each in --out DIR/tasks (complete ones are skipped)", ""},
             {"--task", "I", "run task I only (as --shard)", ""},
             {"--merge", "DIR", "build the outputs from DIR/tasks (and DIR/synth) instead of running the points", ""},
             {"--allow-partial", "", "--merge: merge even when tasks have no result file (the output says partial)", ""},
             {"--synth-todo", "FILE", "--merge: write the buildable front configurations (and both default units) whose area is not from DIR/synth (UNIT:S:COORD:BOX:N lines)", ""},
         });
  a.parse(argc, argv, 2);
  if (a.help_requested()) {
    std::cout << "Sweep engines x configurations x scenes: cycles per triangle and per pixel, area\n"
                 "(synthesis or a marked estimate), simulation wall time, and error against the\n"
                 "golden at S = 8 on the same float input (missing / extra pixels in ppm; cracks\n"
                 "and double hits on closed meshes). Writes CSV and JSON (docs/speed-vs-error.md;\n"
                 "scripts/sweep.sh plots them).\n\n"
              << a.help_text();
    return 0;
  }
  const bool quick = a.has("--quick");
  const int jobs = int(a.get_int("--jobs", 1, 64));
  RasterConfig base;
  base.width = int(a.get_int("--width", 1, kMaxViewport));
  base.height = int(a.get_int("--height", 1, kMaxViewport));
  const std::string out_dir = a.get("--out");
  std::vector<std::string> engines = nonempty_items(a.get("--engines"), ',');
  for (const std::string& e : engines)
    if (!find_engine(e))
      throw UsageError("trirast sweep: --engines: unknown engine '" + e + "'");
  std::vector<SweepScene> scene_specs;
  try {
    if (a.has("--scenes"))
      for (const std::string& s : nonempty_items(a.get("--scenes"), ';'))
        scene_specs.push_back(parse_sweep_scene(s));
    else
      scene_specs = sweep_scenes(quick);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("trirast sweep: --scenes: ") + e.what());
  }
  if (scene_specs.empty()) throw UsageError("trirast sweep: --scenes: empty list");
  std::vector<SweepPoint> points = sweep_points(quick, engines);
  // Engines not in this build (rtl without Verilator) are left out, not failed.
  points.erase(std::remove_if(points.begin(), points.end(),
                              [](const SweepPoint& p) { return !find_engine(p.engine); }),
               points.end());
  std::vector<std::string> skipped;
  {
    std::vector<std::string> names;
    for (const SweepPoint& p : points)
      if (std::find(names.begin(), names.end(), p.engine) == names.end()) names.push_back(p.engine);
    for (const std::string& n : names)
      if (!engine_runs(n)) skipped.push_back(n);
    points.erase(std::remove_if(points.begin(), points.end(),
                                [&](const SweepPoint& p) {
                                  return std::find(skipped.begin(), skipped.end(), p.engine) !=
                                         skipped.end();
                                }),
                 points.end());
    for (const std::string& n : skipped)
      std::fprintf(stderr, "trirast sweep: engine %s does not run in this build: left out\n",
                   n.c_str());
  }
  for (SweepPoint& p : points) {
    p.cfg.width = base.width;
    p.cfg.height = base.height;
  }
  if (points.empty()) throw UsageError("trirast sweep: --engines: no configuration to sweep");
  // The distributed sweep (sweep_shard.hpp): task list, shards, merge.
  const std::vector<SweepTask> all_tasks = sweep_tasks(points.size(), scene_specs.size());
  const bool merging = a.has("--merge"), sharded = a.has("--shard") || a.has("--task");
  if (int(merging) + int(sharded) + int(a.has("--list-tasks")) > 1 || (a.has("--shard") && a.has("--task")))
    throw UsageError("trirast sweep: --shard, --task, --merge and --list-tasks exclude each other");
  if ((a.has("--allow-partial") || a.has("--synth-todo")) && !merging)
    throw UsageError(std::string("trirast sweep: ") +
                     (a.has("--allow-partial") ? "--allow-partial" : "--synth-todo") +
                     " needs --merge DIR");
  if (a.has("--list-tasks")) {
    for (const SweepTask& t : all_tasks)
      std::printf("%zu\t%s\t%s\n", t.index, points[t.point].label().c_str(),
                  scene_specs[t.scene].spec.c_str());
    return 0;
  }
  if (sharded) {
    std::vector<SweepTask> mine;
    if (a.has("--shard")) {
      try {
        mine = shard_tasks(all_tasks, parse_shard(a.get("--shard")));
      } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("trirast sweep: --shard: ") + e.what());
      }
    } else {
      const std::string i = a.get("--task");
      if (i.empty() || i.size() > 9 || i.find_first_not_of("0123456789") != std::string::npos ||
          std::stoul(i) >= all_tasks.size())
        throw UsageError("trirast sweep: --task: '" + i + "' is not a task (0.." +
                         std::to_string(all_tasks.size() - 1) + ")");
      mine.push_back(all_tasks[std::stoul(i)]);
    }
    const auto t0 = Clock::now();
    const ShardOutcome o = run_shard(out_dir, sweep_fingerprint(points, scene_specs, base), mine,
                                     points, scene_specs, base);
    std::printf("trirast sweep: %zu of %zu tasks in %s: %zu ran, %zu complete already, %zu "
                "failed, %.1f s\n",
                mine.size(), all_tasks.size(), out_dir.c_str(), o.ran, o.skipped, o.failed,
                seconds_since(t0));
    return 0;
  }
  // A folder this run creates is removed (when still empty) if the run fails or is interrupted.
  TemporaryPath new_out_dir;
  if (mkdir(out_dir.c_str(), 0777) == 0) new_out_dir.reset(out_dir, true);
  else if (errno != EEXIST)
    throw UsageError("trirast sweep: --out: cannot create directory '" + out_dir + "': " +
                     std::strerror(errno));
  const std::string csv_path = out_dir + "/sweep.csv", cfg_path = out_dir + "/sweep_configs.csv",
                    json_path = out_dir + "/sweep.json";
  for (const std::string& p : {csv_path, cfg_path, json_path}) check_output_path(p, "--out");
  const std::string synth_csv = synth_file(a, "--synth-csv", "docs/synth.csv");
  AreaModel area(synth_csv, synth_file(a, "--synth-script", "scripts/synth.sh"));
  if (merging) area.add_rows(read_synth_results(a.get("--merge")));

  const auto t0 = Clock::now();
  std::vector<SweepSceneData> scenes;
  std::vector<std::string> missing;  // --merge --allow-partial: tasks without a result file
  std::vector<std::vector<PointResult>> merged;
  if (merging)
    merge_task_results(a.get("--merge"), sweep_fingerprint(points, scene_specs, base), points,
                       scene_specs, a.has("--allow-partial"), scenes, merged, missing);
  else
    for (const SweepScene& s : scene_specs) scenes.push_back(load_sweep_scene(s, base));
  const double reference_seconds = seconds_since(t0);

  std::vector<Task> tasks;
  for (size_t s = 0; s < scenes.size(); ++s)
    for (size_t p = 0; p < points.size(); ++p) tasks.push_back({p, s});
  std::vector<std::vector<PointResult>> results(points.size(),
                                                std::vector<PointResult>(scenes.size()));
  Progress progress(tasks.size(), !a.has("--no-progress") && !merging);
  if (!merging) std::fprintf(stderr, "trirast sweep: %zu configurations x %zu scenes = %zu points, %d job%s\n",
               points.size(), scenes.size(), tasks.size(), jobs, jobs == 1 ? "" : "s");
  const auto t1 = Clock::now();
  if (merging) {
    results = merged;
  } else if (jobs == 1) {
    size_t done = 0;
    for (const Task& t : tasks) {
      results[t.point][t.scene] = run_sweep_point(points[t.point], scenes[t.scene]);
      progress.step(++done);
    }
  } else {
    run_parallel(tasks, points, scenes, jobs, results, progress);
  }
  const double sweep_seconds = seconds_since(t1);

  std::vector<PointSummary> summaries;
  for (size_t p = 0; p < points.size(); ++p)
    summaries.push_back(summarize(points[p], scenes, results[p], area));
  mark_pareto(summaries);
  std::vector<std::string> no_rtl;  // front configurations the RTL does not realize
  const std::string todo = synth_todo(points, summaries, no_rtl);
  if (a.has("--synth-todo")) write_text(a.get("--synth-todo"), todo, "--synth-todo");

  Json jscenes = Json::array();
  for (const SweepSceneData& s : scenes) {
    Json j = Json::object();
    j.set("spec", s.spec.spec)
        .set("label", s.spec.label)
        .set("cull", cull_mode_name(s.spec.cull))
        .set("closed", s.spec.closed)
        .set("triangles", uint64_t(s.scene.tris.size()))
        .set("reference_triangles", s.reference_triangles)
        .set("reference_pixels", s.reference_pixels)
        .set("golden_seconds", s.golden_seconds);
    if (s.spec.closed)
      j.set("reference_cracks", s.reference_cracks).set("reference_doubles", s.reference_doubles);
    jscenes.push(j);
  }
  Json jpoints = Json::array();
  int failures = 0;
  for (size_t p = 0; p < points.size(); ++p) {
    Json per_scene = Json::array();
    for (const PointResult& r : results[p]) per_scene.push(point_result_json(r));
    failures += summaries[p].failures;
    jpoints.push(sweep_point_json(points[p])
                     .set("summary", point_summary_json(summaries[p]))
                     .set("scenes", per_scene));
  }
  Json doc = Json::object();
  doc.set("command", command_line(argc, argv))
      .set("quick", quick)
      .set("jobs", jobs)
      .set("viewport", Json::object().set("width", base.width).set("height", base.height))
      .set("reference", "golden, S = 8, coord bits 16, same float input and culling")
      .set("engines_in_build", [] {
        Json e = Json::array();
        for (const EngineInfo& i : engine_registry()) e.push(Json::string(i.name));
        return e;
      }())
      .set("skipped_engines", [&] {
        Json e = Json::array();
        for (const std::string& n : skipped) e.push(Json::string(n));
        return e;
      }())
      .set("area_model", area_model_json(area, synth_csv))
      .set("scenes", jscenes)
      .set("points", jpoints)
      .set("failed_points", failures)
      .set("wall_seconds", Json::object()
                               .set("references", reference_seconds)
                               .set("sweep", sweep_seconds)
                               .set("total", seconds_since(t0)));
  {
    Json m = Json::array(), nr = Json::array(), fm = Json::array();
    for (const std::string& n : missing) m.push(Json::string(n));
    for (const std::string& n : no_rtl) nr.push(Json::string(n));
    for (size_t p = 0; p < points.size(); ++p)
      if (const double f = area.fmax_mhz(points[p].kind(), points[p].cfg))
        fm.push(Json::object().set("engine", points[p].engine).set("config", points[p].config_name()).set("fmax_mhz", f));
    doc.set("merged_from", merging ? a.get("--merge") : "")
        .set("partial", !missing.empty())
        .set("missing_tasks", m)
        .set("front_synth_todo", todo)
        .set("front_without_rtl", nr)
        .set("ice40_fmax", fm);
  }
  write_text(csv_path, sweep_csv(points, scenes, results, summaries), "--out");
  write_text(cfg_path, sweep_configs_csv(points, summaries), "--out");
  write_text(json_path, doc.dump(), "--out");
  new_out_dir.release();

  std::printf("trirast sweep: %zu configurations x %zu scenes in %.1f s (%d job%s)%s\n",
              points.size(), scenes.size(), seconds_since(t0), jobs, jobs == 1 ? "" : "s",
              quick ? ", quick" : "");
  std::printf("  area: %s\n", area.have_synth() ? ("synthesis (" + area.target() +
                                                   ") where it covers a configuration, else estimate")
                                                      .c_str()
                                                : "estimates only (no synthesis CSV)");
  std::printf("  %-40s %12s %10s %10s %8s  %s\n", "Pareto, hardware (error, cycles)", "error ppm",
              "cyc/tri", "LUTs", "cracks", "");
  // One row of a front; `no_area` says why a point without a synthesized area has none.
  auto front_row = [&](size_t p, const char* no_area) {
    std::printf("  %-40s %12.3f %10.3f %10s %8s  %s\n", points[p].label().c_str(),
                summaries[p].error_ppm, summaries[p].cycles_per_triangle,
                summaries[p].area.known() ? std::to_string(int64_t(summaries[p].area.luts)).c_str()
                                          : "-",
                summaries[p].cracks < 0 ? "-" : std::to_string(summaries[p].cracks).c_str(),
                summaries[p].area.estimate() ? "(area estimate)"
                : summaries[p].area.known()  ? ""
                                             : no_area);
  };
  for (size_t p = 0; p < points.size(); ++p)
    if (summaries[p].pareto_cycles) front_row(p, "(area not synthesized)");
  // The model-only front (quotient truncation): configurations no other one dominates.
  bool whatif_header = false;
  for (size_t p = 0; p < points.size(); ++p)
    if (summaries[p].whatif_cycles) {
      if (!whatif_header) std::printf("  Pareto, model only (error, cycles)\n");
      whatif_header = true;
      front_row(p, "(area unknown)");
    }
  if (failures) std::printf("  %d point(s) failed: see the error column of sweep.csv\n", failures);
  if (!missing.empty())
    std::printf("  PARTIAL: %zu task(s) had no result file (first: %s); their points are left "
                "off the fronts\n", missing.size(), missing.front().c_str());
  for (const std::string& p : {csv_path, cfg_path, json_path})
    std::printf("  wrote      %s\n", p.c_str());
  return 0;
}

// ---------------------------------------------------------------------------------------------
namespace {

struct FitEval {
  PointResult result;
  double error_ppm = 0;
  bool ok = false;
};

}  // namespace

int cmd_fit(int argc, char** argv) {
  // The scene options are raster's own table (cli/scene_options.hpp): the same scene, camera and
  // viewport; --subpixel-bits fixes S instead of searching it.
  std::vector<OptionSpec> specs = scene_input_options();
  const std::vector<OptionSpec> fit_specs = {
      {"--error-budget", "PPM", "allowed missing + extra pixels, parts per million of the reference's", "0"},
      {"--unit", "UNIT", "improved (the first generation) | improved2 (the second generation: no quotient truncation to search)", "improved"},
      {"--corner-form", "FORM", "improved2: corner values by dsp (products) | radix16; the area's form (the spans do not change)", "radix16"},
      {"--endpoints", "N", "N of the fitted configuration (does not change the output; 1 is the smallest)", "1"},
      {"--report", "FILE.json", "write the search and the result as JSON", ""},
      {"--synth-csv", "FILE", "synthesis results; missing file = estimates only (with a warning)", "docs/synth.csv of the source tree"},
      {"--synth-script", "FILE", "scripts/synth.sh (names the synthesized widths)", "scripts/synth.sh of the source tree"},
  };
  specs.insert(specs.end(), fit_specs.begin(), fit_specs.end());
  Args a("fit", "--scene SCENE [--error-budget PPM] [options]", specs);
  a.parse(argc, argv, 2);
  if (a.help_requested()) {
    std::cout << "Find the smallest configuration of the improved unit (subpixel bits, coordinate\n"
                 "width, box / divider width, quotient truncation, N) whose output on the scene is\n"
                 "exact against the golden at S = 8 (or within --error-budget ppm), by area, and\n"
                 "the cycles (SystemC model) and area it saves against the default. --unit\n"
                 "improved2 fits the second-generation unit (its widths; its area per corner\n"
                 "form, an estimate scaled to its own synthesis at the default widths).\n\n"
              << a.help_text();
    return 0;
  }
  if (!a.has("--scene")) throw UsageError("trirast fit: --scene is required");
  RasterConfig base;
  base.width = int(a.get_int("--width", 1, kMaxViewport));
  base.height = int(a.get_int("--height", 1, kMaxViewport));
  const int endpoints = int(a.get_int("--endpoints", 1, 4));
  if (endpoints == 3) throw UsageError("trirast fit: --endpoints: 3 is not 1, 2 or 4");
  const std::string unit_name = a.get("--unit");
  if (unit_name != "improved" && unit_name != "improved2")
    throw UsageError("trirast fit: --unit: '" + unit_name + "' is not improved or improved2");
  const bool gen2 = unit_name == "improved2";
  const UnitKind kind = gen2 ? UnitKind::Improved2 : UnitKind::Improved;
  int corner_form = 1;
  try {
    corner_form = parse_corner_form(a.get("--corner-form"));
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("trirast fit: --corner-form: ") + e.what());
  }
  if (a.has("--corner-form") && !gen2)
    throw UsageError("trirast fit: --corner-form applies to --unit improved2 only");
  const std::string form_name = !gen2 ? "" : corner_form ? "radix16" : "dsp";
  const double budget = a.get_double("--error-budget");
  if (!(budget >= 0) || !std::isfinite(budget))
    throw UsageError("trirast fit: --error-budget: must be a number >= 0");
  SweepScene spec;
  spec.spec = a.get("--scene");
  spec.label = spec.spec;
  try {
    spec.cull = parse_cull_mode(a.get("--cull"));
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("trirast fit: ") + e.what());
  }
  spec.camera = camera_from(a);
  const int s_first = a.has("--subpixel-bits") ? int(a.get_int("--subpixel-bits", 0, 8)) : 0;
  const int s_last = a.has("--subpixel-bits") ? s_first : 8;
  if (a.has("--report")) check_output_path(a.get("--report"), "--report");
  const std::string synth_csv = synth_file(a, "--synth-csv", "docs/synth.csv");
  AreaModel area(synth_csv, synth_file(a, "--synth-script", "scripts/synth.sh"));
  if (!area.have_synth())
    std::fprintf(stderr, "trirast fit: --synth-csv %s: no synthesis results; areas are the estimate\n",
                 synth_csv.c_str());

  const auto t0 = Clock::now();
  const SweepSceneData scene = load_sweep_scene(spec, base);
  int evaluations = 0;
  Json search = Json::array();
  auto make_point = [&](int S, int coord, int box, int K) {
    SweepPoint p;
    p.engine = gen2 ? "improved2-datapath" : "improved-datapath";
    p.group = "fit";
    p.cfg.improved2.corner_form = corner_form;
    p.cfg.width = base.width;
    p.cfg.height = base.height;
    p.cfg.subpixel_bits = S;
    p.cfg.coord_int_bits = coord;
    p.cfg.box_bits = box;
    p.cfg.divider_quotient_bits = K;
    p.cfg.endpoints = endpoints;
    p.cfg.fifo_depth = std::max(8, endpoints);
    return p;
  };
  auto eval = [&](const SweepPoint& p) {
    FitEval e;
    ++evaluations;
    e.result = run_sweep_point(p, scene);
    const int64_t ref = std::max<int64_t>(scene.reference_pixels, 1);
    e.error_ppm = 1e6 * double(e.result.missing + e.result.extra) / double(ref);
    e.ok = e.result.error.empty() && (e.result.missing + e.result.extra == 0 || e.error_ppm <= budget);
    return e;
  };
  // Smallest v in [lo, hi] with ok(v), given ok(hi) (binary search: the error does not grow with
  // a width; the value returned is always one that was checked).
  auto smallest = [&](int lo, int hi, auto ok) {
    while (lo < hi) {
      const int mid = lo + (hi - lo) / 2;
      if (ok(mid)) hi = mid;
      else lo = mid + 1;
    }
    return hi;
  };
  // The narrowest coordinate width the viewport allows.
  int coord_min = 2;
  while ((int64_t(1) << (coord_min - 1)) < std::max(base.width, base.height)) ++coord_min;
  const RasterConfig def;
  struct Candidate {
    SweepPoint point;
    FitEval eval;
    Area area;
  };
  std::vector<Candidate> candidates;
  for (int S = s_first; S <= s_last; ++S) {
    const int coord_max = std::min(def.coord_int_bits, 30 - (S > 0 ? S : 1));
    SweepPoint p = make_point(S, coord_max, def.box_bits, 0);
    FitEval e = eval(p);
    Json row = Json::object().set("subpixel_bits", S).set("error_ppm_at_full_width", e.error_ppm);
    if (!e.ok) {
      search.push(row.set("feasible", false));
      continue;
    }
    const int coord = smallest(coord_min, coord_max, [&](int c) {
      return eval(make_point(S, c, def.box_bits, 0)).ok;
    });
    const int box = smallest(1, def.box_bits, [&](int b) { return eval(make_point(S, coord, b, 0)).ok; });
    // Quotient truncation: K = box + 1 is the untruncated divider (Q), written as automatic
    // (the second generation has none).
    int K = gen2 ? box + 1 : smallest(1, box + 1, [&](int k) {
      return eval(make_point(S, coord, box, k == box + 1 ? 0 : k)).ok;
    });
    if (K == box + 1) K = 0;
    p = make_point(S, coord, box, K);
    e = eval(p);
    const Area ar = area.area(kind, p.cfg);
    search.push(row.set("feasible", true)
                    .set("coord_bits", coord)
                    .set("box_bits", box)
                    .set("quotient_bits", K)
                    .set("error_ppm", e.error_ppm)
                    .set("luts", ar.luts)
                    .set("ffs", ar.ffs)
                    .set("area_source", ar.source));
    candidates.push_back({p, e, ar});
  }
  if (candidates.empty())
    throw UsageError("trirast fit: no configuration is within " + std::to_string(budget) +
                     " ppm on " + spec.spec);
  const Candidate* best = &candidates.front();
  for (const Candidate& c : candidates)
    if (c.area.luts < best->area.luts ||
        (c.area.luts == best->area.luts && c.area.ffs < best->area.ffs))
      best = &c;

  // Cycles of the default and of the fit on the timed SystemC model.
  auto timed = [&](RasterConfig cfg) {
    SweepPoint p;
    p.engine = gen2 ? "improved2-sc" : "improved-sc";
    p.cfg = cfg;
    return run_sweep_point(p, scene);
  };
  RasterConfig def_cfg;
  def_cfg.width = base.width;
  def_cfg.height = base.height;
  def_cfg.improved2.corner_form = corner_form;
  const PointResult def_run = timed(def_cfg);
  const PointResult fit_run = timed(best->point.cfg);
  // The timed model runs the same datapath as the unit: its spans must agree.
  if (!fit_run.error.empty() || fit_run.missing != best->eval.result.missing ||
      fit_run.extra != best->eval.result.extra)
    throw std::runtime_error("fit: the SystemC model and the unit model disagree on the fitted "
                             "configuration" + (fit_run.error.empty() ? "" : ": " + fit_run.error));
  const Area def_area = area.area(kind, def_cfg);
  auto pct = [](double saved, double of) { return of > 0 ? 100.0 * saved / of : 0.0; };
  const double cyc_saved = double(def_run.total_cycles) - double(fit_run.total_cycles);
  const double lut_saved = def_area.luts - best->area.luts, ff_saved = def_area.ffs - best->area.ffs;
  const RasterConfig& f = best->point.cfg;

  std::printf("trirast fit: unit %s%s, scene %s, cull %s, budget %g ppm, %" PRIu64
              " triangles, %" PRId64 " reference pixels\n",
              unit_name.c_str(), gen2 ? (" (" + form_name + ")").c_str() : "", spec.spec.c_str(),
              cull_mode_name(spec.cull), budget, uint64_t(scene.scene.tris.size()),
              scene.reference_pixels);
  std::printf("  %-3s %-9s %-6s %-5s %-4s %12s %10s %10s  %s\n", "S", "feasible", "coord", "box",
              "K", "error ppm", "LUTs", "FFs", "area");
  for (const Candidate& c : candidates)
    std::printf("  %-3d %-9s %-6d %-5d %-4s %12.3f %10.0f %10.0f  %s%s\n", c.point.cfg.subpixel_bits,
                "yes", c.point.cfg.coord_int_bits, c.point.cfg.box_bits,
                c.point.cfg.divider_quotient_bits ? std::to_string(c.point.cfg.divider_quotient_bits).c_str() : "-",
                c.eval.error_ppm, c.area.luts, c.area.ffs, c.area.source.c_str(),
                &c == best ? "   <-- smallest" : "");
  const std::string divider =
      f.divider_quotient_bits ? std::to_string(f.divider_quotient_bits) + " quotient bits (truncated from Q=" +
                                    std::to_string(f.box_bits + 1) + ")"
                              : "Q=" + std::to_string(f.box_bits + 1) + " quotient bits";
  std::printf("  fit        S=%d coord=%d box=%d divider %s N=%d: %" PRId64
              " missing, %" PRId64 " extra (%.3f ppm), %" PRIu64 " rejected\n",
              f.subpixel_bits, f.coord_int_bits, f.box_bits, divider.c_str(), f.endpoints, best->eval.result.missing, best->eval.result.extra, best->eval.error_ppm,
              best->eval.result.rejected_range + best->eval.result.rejected_width);
  std::printf("  cycles     default %" PRIu64 ", fit %" PRIu64 ": %+.0f saved (%.1f%%)\n",
              def_run.total_cycles, fit_run.total_cycles, cyc_saved, pct(cyc_saved, double(def_run.total_cycles)));
  std::printf("  area       default %.0f LUT / %.0f FF (%s), fit %.0f LUT / %.0f FF (%s): %.0f LUT (%.1f%%), %.0f FF (%.1f%%) saved\n",
              def_area.luts, def_area.ffs, def_area.source.c_str(), best->area.luts,
              best->area.ffs, best->area.source.c_str(), lut_saved, pct(lut_saved, def_area.luts),
              ff_saved, pct(ff_saved, def_area.ffs));
  std::printf("  searched   %d evaluations in %.1f s\n", evaluations, seconds_since(t0));

  if (a.has("--report")) {
    auto cfg_json = [](const RasterConfig& c) {
      return Json::object()
          .set("subpixel_bits", c.subpixel_bits)
          .set("coord_bits", c.coord_int_bits)
          .set("box_bits", c.box_bits)
          .set("divider_q", c.box_bits + 1)
          .set("quotient_bits", c.divider_quotient_bits)
          .set("divider_bits", c.divider_quotient_bits ? c.divider_quotient_bits : c.box_bits + 1)
          .set("endpoints", c.endpoints);
    };
    Json doc = Json::object();
    doc.set("command", command_line(argc, argv))
        .set("unit", unit_name)
        .set("corner_form", form_name)
        .set("scene", spec.spec)
        .set("cull", cull_mode_name(spec.cull))
        .set("error_budget_ppm", budget)
        .set("triangles", uint64_t(scene.scene.tris.size()))
        .set("reference_pixels", scene.reference_pixels)
        .set("fit", cfg_json(f)
                        .set("error_ppm", best->eval.error_ppm)
                        .set("missing", best->eval.result.missing)
                        .set("extra", best->eval.result.extra)
                        .set("rejected", best->eval.result.rejected_range +
                                             best->eval.result.rejected_width)
                        .set("total_cycles", fit_run.total_cycles)
                        .set("luts", best->area.luts)
                        .set("ffs", best->area.ffs)
                        .set("area_source", best->area.source))
        .set("default", cfg_json(def_cfg)
                            .set("total_cycles", def_run.total_cycles)
                            .set("luts", def_area.luts)
                            .set("ffs", def_area.ffs)
                            .set("area_source", def_area.source))
        .set("saved", Json::object()
                          .set("cycles", cyc_saved)
                          .set("cycles_pct", pct(cyc_saved, double(def_run.total_cycles)))
                          .set("luts", lut_saved)
                          .set("luts_pct", pct(lut_saved, def_area.luts))
                          .set("ffs", ff_saved)
                          .set("ffs_pct", pct(ff_saved, def_area.ffs)))
        .set("search", search)
        .set("evaluations", evaluations)
        .set("wall_seconds", seconds_since(t0));
    write_text(a.get("--report"), doc.dump(), "--report");
    std::printf("  wrote      %s (report)\n", a.get("--report").c_str());
  }
  return 0;
}

}  // namespace trirast
