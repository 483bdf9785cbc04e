// stream_golden: a program outside trirast that uses the installed library (docs/embedding.md).
// It rasterizes a small triangle stream with the golden rasterizer (the truth for coverage) and
// with the improved2 unit's bit-accurate datapath, prints the spans of each triangle and checks
// that the datapath's spans equal the golden's, triangle for triangle.
//   stream_golden [FILE.tri]     the stream below, or a .tri file (x0 y0 x1 y1 x2 y2 per line)
// Exit status: 0 when they agree on every triangle, 1 when they differ, 2 on bad input.
#include <cstdint>
#include <cstdio>
#include <exception>
#include <map>
#include <memory>

#include <trirast/common/config.hpp>
#include <trirast/common/engine.hpp>
#include <trirast/common/setup.hpp>
#include <trirast/common/span.hpp>
#include <trirast/golden/golden.hpp>
#include <trirast/improved2/improved2_unit.hpp>
#include <trirast/scene/scene.hpp>

namespace {

// Cases that make the coverage rule hard: an edge shared by two triangles, counter-clockwise
// input, slivers, a subpixel triangle, no area, partly outside the viewport.
const char* const kStream = R"(
4 4  60 4  4 60              # clockwise on screen
60 4  60 60  4 60            # shares the hypotenuse with the first
70.25 10.5  120.75 30.125  80.5 58.875
100 70  70 90  120 94        # counter-clockwise on screen
2 80  126 81  2 81.5         # sliver
33.3 70.1  33.6 70.4  33.2 70.9
10 10  20 20  30 30          # degenerate: no area, removed by setup
-20 -10  40 20  -5 50        # partly off screen
)";

// One engine's spans, sorted and grouped by scene triangle.
std::map<uint32_t, trirast::SpanList> spans_by_triangle(trirast::Engine& engine,
                                                        const trirast::SetupResult& setup,
                                                        const trirast::RasterConfig& cfg) {
  trirast::EngineResult result;
  engine.run(setup, cfg, result);
  trirast::sort_spans(result.spans);
  std::map<uint32_t, trirast::SpanList> by_tri;
  for (const trirast::Span& s : result.spans) by_tri[s.tri].push_back(s);
  return by_tri;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 2) {
    std::fprintf(stderr, "usage: stream_golden [FILE.tri]\n");
    return 2;
  }
  try {
    // A small viewport, 8 subpixel bits (the default precision of the units).
    trirast::RasterConfig cfg;
    cfg.width = 128;
    cfg.height = 96;
    cfg.validate();
    const trirast::Scene scene = argc == 2 ? trirast::read_tri_file(argv[1])
                                           : trirast::parse_tri_text(kStream, "stream");
    // Setup once (snap, orient, cull, edge functions, box); both engines take its result.
    const trirast::SetupResult setup = trirast::setup_scene(scene.tris, cfg);

    const auto golden = trirast::make_golden_engine();
    const auto datapath = trirast::make_improved2_datapath_engine();
    auto golden_spans = spans_by_triangle(*golden, setup, cfg);
    auto datapath_spans = spans_by_triangle(*datapath, setup, cfg);

    int differ = 0;
    for (const trirast::TriangleSetup& t : setup.tris) {
      const trirast::SpanList& g = golden_spans[t.index];
      const trirast::SpanList& d = datapath_spans[t.index];
      const bool same = g == d;
      differ += same ? 0 : 1;
      std::printf("tri %u: golden %zu spans %lld pixels, improved2-datapath %zu spans %lld pixels:"
                  " %s\n", t.index, g.size(), static_cast<long long>(trirast::count_pixels(g)),
                  d.size(), static_cast<long long>(trirast::count_pixels(d)),
                  same ? "same" : "DIFFERENT");
    }
    std::printf("stream_golden: %zu triangles read, %zu set up (%llu degenerate, %llu culled); "
                "improved2-datapath %s the golden on %zu of them\n",
                scene.tris.size(), setup.tris.size(),
                static_cast<unsigned long long>(setup.counts.degenerate),
                static_cast<unsigned long long>(setup.counts.culled),
                differ ? "DIFFERS from" : "equals", differ ? size_t(differ) : setup.tris.size());
    return differ ? 1 : 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "stream_golden: %s\n", e.what());
    return 2;
  }
}
