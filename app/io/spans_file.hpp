// The spans interchange format: one line per span, "tri y x_begin x_end", sorted by tri, then y,
// then x_begin; nothing else in the file.
#pragma once
#include <string>

#include "common/span.hpp"

namespace trirast {

// `spans` must be sorted (sort_spans). Written atomically.
void write_spans_file(const SpanList& spans, const std::string& path, const std::string& option);

// Reads a spans file; throws std::runtime_error("PATH:LINE: ...") on malformed lines.
SpanList read_spans_file(const std::string& path);

}  // namespace trirast
