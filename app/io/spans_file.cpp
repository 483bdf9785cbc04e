#include "io/spans_file.hpp"

#include <cinttypes>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/output_file.hpp"

namespace trirast {

void write_spans_file(const SpanList& spans, const std::string& path, const std::string& option) {
  OutputFile out(path, option);
  std::string buf;
  buf.reserve(1 << 16);
  char line[64];
  for (const Span& s : spans) {
    int n = std::snprintf(line, sizeof line, "%" PRIu32 " %" PRId32 " %" PRId32 " %" PRId32 "\n",
                          s.tri, s.y, s.x_begin, s.x_end);
    buf.append(line, size_t(n));
    if (buf.size() > (1 << 16) - 64) {
      out.write(buf);
      buf.clear();
    }
  }
  out.write(buf);
  out.commit();
}

SpanList read_spans_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  SpanList spans;
  std::string text;
  int line_no = 0;
  while (std::getline(in, text)) {
    ++line_no;
    std::istringstream ls(text);
    long long tri, y, b, e;
    std::string rest;
    if (!(ls >> tri >> y >> b >> e) || (ls >> rest) || tri < 0)
      throw std::runtime_error(path + ":" + std::to_string(line_no) +
                               ": expected 'tri y x_begin x_end'");
    spans.push_back(Span{uint32_t(tri), int32_t(y), int32_t(b), int32_t(e)});
  }
  return spans;
}

}  // namespace trirast
