#include "io/cycles_file.hpp"

#include <cinttypes>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "io/output_file.hpp"

namespace trirast {

// The first seven columns are the original file's, unchanged; the stage breakdown follows.
static const char* kHeaderBase = "tri,accept_cycle,first_span_cycle,done_cycle,spans,pixels,stall_cycles";
static const char* kHeaderStages =
    ",setup_start_cycle,setup_done_cycle,handoff_cycle,walk_start_cycle,walk_end_cycle,"
    "divider_iterations,boundary_steps,box_width,box_height";

void write_cycles_file(const std::vector<TriangleCycles>& cycles, const std::string& path,
                       const std::string& option) {
  OutputFile out(path, option);
  std::string text = std::string(kHeaderBase) + kHeaderStages + "\n";
  char line[400];
  for (const TriangleCycles& c : cycles) {
    const int n = std::snprintf(
        line, sizeof line,
        "%" PRIu32 ",%" PRIu64 ",%" PRIu64 ",%" PRIu64 ",%" PRIu64 ",%" PRIu64 ",%" PRIu64
        ",%" PRIu64 ",%" PRIu64 ",%" PRIu64 ",%" PRIu64 ",%" PRIu64 ",%" PRIu64 ",%" PRIu64
        ",%" PRIu64 ",%" PRIu64 "\n",
        c.tri, c.accept_cycle, c.first_span_cycle, c.done_cycle, c.spans, c.pixels,
        c.stall_cycles, c.setup_start_cycle, c.setup_done_cycle, c.handoff_cycle,
        c.walk_start_cycle, c.walk_end_cycle, c.divider_iterations, c.boundary_steps,
        c.box_width, c.box_height);
    text.append(line, size_t(n));
  }
  out.write(text);
  out.commit();
}

std::vector<TriangleCycles> read_cycles_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::string text;
  const std::string base = kHeaderBase, full = base + kHeaderStages;
  if (!std::getline(in, text) || (text != full && text != base))
    throw std::runtime_error(path + ":1: expected the header '" + full + "' (or its first seven columns)");
  // A file of the first seven columns (written before the stage breakdown) reads with zeros there.
  const int columns = text == full ? 16 : 7;
  std::vector<TriangleCycles> rows;
  int line_no = 1;
  while (std::getline(in, text)) {
    ++line_no;
    TriangleCycles c{};
    char extra;
    const int got = std::sscanf(
        text.c_str(),
        "%" SCNu32 ",%" SCNu64 ",%" SCNu64 ",%" SCNu64 ",%" SCNu64 ",%" SCNu64 ",%" SCNu64
        ",%" SCNu64 ",%" SCNu64 ",%" SCNu64 ",%" SCNu64 ",%" SCNu64 ",%" SCNu64 ",%" SCNu64
        ",%" SCNu64 ",%" SCNu64 "%c",
        &c.tri, &c.accept_cycle, &c.first_span_cycle, &c.done_cycle, &c.spans, &c.pixels,
        &c.stall_cycles, &c.setup_start_cycle, &c.setup_done_cycle, &c.handoff_cycle,
        &c.walk_start_cycle, &c.walk_end_cycle, &c.divider_iterations, &c.boundary_steps,
        &c.box_width, &c.box_height, &extra);
    if (got != columns)
      throw std::runtime_error(path + ":" + std::to_string(line_no) + ": malformed row (expected " +
                               std::to_string(columns) + " columns)");
    rows.push_back(c);
  }
  return rows;
}

}  // namespace trirast
