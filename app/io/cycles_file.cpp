#include "io/cycles_file.hpp"

#include <cinttypes>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "io/output_file.hpp"

namespace trirast {

static const char* kHeader = "tri,accept_cycle,first_span_cycle,done_cycle,spans,pixels,stall_cycles";

void write_cycles_file(const std::vector<TriangleCycles>& cycles, const std::string& path,
                       const std::string& option) {
  OutputFile out(path, option);
  std::string text = std::string(kHeader) + "\n";
  char line[200];
  for (const TriangleCycles& c : cycles) {
    const int n = std::snprintf(line, sizeof line,
                                "%" PRIu32 ",%" PRIu64 ",%" PRIu64 ",%" PRIu64 ",%" PRIu64
                                ",%" PRIu64 ",%" PRIu64 "\n",
                                c.tri, c.accept_cycle, c.first_span_cycle, c.done_cycle, c.spans,
                                c.pixels, c.stall_cycles);
    text.append(line, size_t(n));
  }
  out.write(text);
  out.commit();
}

std::vector<TriangleCycles> read_cycles_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::string text;
  if (!std::getline(in, text) || text != kHeader)
    throw std::runtime_error(path + ":1: expected the header '" + std::string(kHeader) + "'");
  std::vector<TriangleCycles> rows;
  int line_no = 1;
  while (std::getline(in, text)) {
    ++line_no;
    TriangleCycles c;
    char extra;
    if (std::sscanf(text.c_str(),
                    "%" SCNu32 ",%" SCNu64 ",%" SCNu64 ",%" SCNu64 ",%" SCNu64 ",%" SCNu64
                    ",%" SCNu64 "%c",
                    &c.tri, &c.accept_cycle, &c.first_span_cycle, &c.done_cycle, &c.spans,
                    &c.pixels, &c.stall_cycles, &extra) != 7)
      throw std::runtime_error(path + ":" + std::to_string(line_no) + ": malformed row");
    rows.push_back(c);
  }
  return rows;
}

}  // namespace trirast
