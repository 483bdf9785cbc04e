// The sweep split into independent tasks: any scheduler (Slurm job arrays, GNU parallel,
// a shell loop) runs `trirast sweep --shard K/N` or `--task I`, each task writes one result file,
// and `trirast sweep --merge DIR` builds the same outputs as a single-process run.
//
// Task list: configuration x scene simulation points, scene-major (task i = scene i / P, point
// i % P for P configurations), so a contiguous shard loads few scenes. Deterministic for the same
// options and build; its fingerprint (format version, viewport, every point and scene, the
// executable's bytes) is written into every result file, and a merge refuses files of another.
//
// Result files hold JSON objects of one format: "format": "trirast-sweep-result", "version"
// (kSweepResultFormat), "kind", then the kind's members; numbers are JSON numbers (doubles written
// with the digits that read back to the same double). A reader refuses, in one line naming the
// file, a file of another format, version or kind, one cut short (incomplete JSON) and a member
// that is missing or of another type.
//
// Simulation results DIR/tasks/sim-IIIIII.res, "kind": "simulation": "fingerprint", "task",
// "point" and "scene" (their names), "scene_figures" (the scene's reference figures) and "result"
// (the PointResult: encode_point_result's object, which also carries a worker process's result
// to the single-process sweep). Written to a temporary name and renamed when complete.
//
// Synthesis results: after the simulation, `--merge DIR --synth-todo FILE` lists the buildable
// configurations on a hardware Pareto front (no quotient truncation) whose area is not from this
// run's synthesis (synth_todo); scripts/sweep_synth_task.sh synthesizes one line with
// scripts/synth.sh --one into DIR/synth/NAME.synth, "kind": "synthesis", "rows": one object per
// target (unit, config, target, luts, ffs, carry, bram, dsp, fmax_mhz or null, subpixel_bits,
// coord_bits, box_bits, endpoints, seconds), which the next merge reads (read_synth_results).
// scripts/synth.sh writes the format name and version itself: change them together.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "sweep/sweep.hpp"
#include "sweep/sweep_area.hpp"

namespace trirast {

constexpr int kSweepResultFormat = 2;

struct SweepTask {
  size_t index = 0, point = 0, scene = 0;
};

// All tasks of P points x S scenes, scene-major.
std::vector<SweepTask> sweep_tasks(size_t points, size_t scenes);

// "K/N" with 0 <= K < N: the tasks [K*T/N, (K+1)*T/N). Throws std::invalid_argument (a phrase
// without the option name) for anything else.
struct ShardSpec {
  size_t k = 0, n = 1;
};
ShardSpec parse_shard(const std::string& text);
std::vector<SweepTask> shard_tasks(const std::vector<SweepTask>& all, const ShardSpec& s);

// Hex fingerprint of the task list and the build (see above).
std::string sweep_fingerprint(const std::vector<SweepPoint>& points,
                              const std::vector<SweepScene>& scenes, const RasterConfig& base);

// "task 12 (model S8 c16 b14 K- N1 on builtin:mixed)"
std::string task_name(const SweepTask& t, const std::vector<SweepPoint>& points,
                      const std::vector<SweepScene>& scenes);
std::string task_path(const std::string& dir, size_t index);

// The scene figures a merge needs (a result file carries its scene's).
struct SceneFigures {
  uint64_t triangles = 0, reference_triangles = 0;
  int64_t reference_pixels = 0, reference_cracks = -1, reference_doubles = -1;
  double golden_seconds = 0;
};

// Writes the result of one task (temporary name, renamed when complete).
void write_task_result(const std::string& path, const std::string& fingerprint,
                       const SweepTask& t, const std::string& point_label,
                       const std::string& scene_spec, const SceneFigures& scene,
                       const PointResult& r);

// Reads a result file; throws std::runtime_error, one line naming the file, when it is cut
// short, malformed, of another format version or fingerprint (mixed versions), or of another task.
struct TaskResult {
  SceneFigures scene;
  PointResult result;
};
TaskResult read_task_result(const std::string& path, const std::string& fingerprint,
                            size_t index);
// A PointResult as one line of JSON (the "result" object of a simulation result file), and back;
// decode_point_result throws std::runtime_error ("malformed 'pixels'", "not JSON: ...").
std::string encode_point_result(const PointResult& r);
PointResult decode_point_result(const std::string& text);

// Whether `path` holds a complete result of this task list (a rerun skips the task).
bool task_result_complete(const std::string& path, const std::string& fingerprint, size_t index);

// Runs `tasks` in this process, one result file each, skipping complete ones; appends
// "ran I" / "skipped I" / "failed I: why" lines to DIR/run.log. Returns the number of tasks
// whose point failed (their result files record the error; they are reported by name on stderr).
struct ShardOutcome {
  size_t ran = 0, skipped = 0, failed = 0;
};
ShardOutcome run_shard(const std::string& dir, const std::string& fingerprint,
                       const std::vector<SweepTask>& tasks, const std::vector<SweepPoint>& points,
                       const std::vector<SweepScene>& scenes, const RasterConfig& base);

// Fills `scenes` and `results` (points x scenes) from DIR's result files. Missing tasks: an
// error naming them (the first few and how many), unless allow_partial; then their results carry
// the error "no result file (task I)" and `missing` lists their names.
void merge_task_results(const std::string& dir, const std::string& fingerprint,
                        const std::vector<SweepPoint>& points,
                        const std::vector<SweepScene>& scene_specs, bool allow_partial,
                        std::vector<SweepSceneData>& scenes,
                        std::vector<std::vector<PointResult>>& results,
                        std::vector<std::string>& missing);

// DIR/synth/*.synth (scripts/synth.sh --one); throws std::runtime_error naming a file that is cut
// short, malformed or of another format version. No directory: no rows.
std::vector<SynthRow> read_synth_results(const std::string& dir);

// Configurations to synthesize in a distributed run, as "UNIT:S:COORD:BOX:N" lines (deduplicated):
// every buildable configuration (SweepPoint::rtl) on a hardware front, and the default improved
// and traditional units (the estimate's calibration, the units' comparison), whose area is not yet
// from this run's synthesis jobs (an estimate, or a docs/synth.csv row of an older RTL).
// `no_rtl`: the model-only what-if points (whatif_cycles / whatif_area), which have no RTL.
std::string synth_todo(const std::vector<SweepPoint>& points,
                       const std::vector<PointSummary>& summaries,
                       std::vector<std::string>& no_rtl);

}  // namespace trirast
