// The golden engines: one traversal over every triangle, on one thread or several. Several threads
// take chunks of consecutive triangles from a shared counter (so a few huge triangles cannot leave
// one thread with all the work); each chunk has its own span list, and the lists are joined in
// chunk order, so the output is the single-threaded one, span for span, for any thread count.
#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>

#include "golden/golden.hpp"

namespace trirast {

namespace {

constexpr size_t kChunkTriangles = 256;

// At most one span per row of each box: reserving this up front spares the lists their regrowth.
size_t max_spans(const std::vector<TriangleSetup>& tris, size_t first, size_t last) {
  size_t n = 0;
  for (size_t k = first; k < last; ++k) n += size_t(tris[k].box.height());
  return n;
}

class GoldenEngine : public Engine {
 public:
  GoldenEngine(Traversal traversal, int threads) : traversal_(traversal), threads_(threads) {
    if (threads_ <= 0) threads_ = int(std::max(1u, std::thread::hardware_concurrency()));
  }

  void run(const SetupResult& setup, const RasterConfig& cfg, EngineResult& out) override {
    const std::vector<TriangleSetup>& tris = setup.tris;
    const size_t chunks = (tris.size() + kChunkTriangles - 1) / kChunkTriangles;
    const size_t threads = std::min<size_t>(size_t(threads_), chunks);
    if (threads <= 1) {
      out.spans.reserve(out.spans.size() + max_spans(tris, 0, tris.size()));
      for (const TriangleSetup& t : tris) golden_triangle(t, cfg, traversal_, out.spans);
      return;
    }
    // Chunk lists live in the engine, so a second run reuses their memory.
    std::vector<SpanList>& parts = parts_;
    if (parts.size() < chunks) parts.resize(chunks);
    std::atomic<size_t> next{0};
    std::vector<std::exception_ptr> errors(threads);
    auto rasterize = [&](size_t id) {
      try {
        for (size_t c; (c = next.fetch_add(1, std::memory_order_relaxed)) < chunks;) {
          const size_t end = std::min(tris.size(), (c + 1) * kChunkTriangles);
          parts[c].clear();
          parts[c].reserve(max_spans(tris, c * kChunkTriangles, end));
          for (size_t k = c * kChunkTriangles; k < end; ++k)
            golden_triangle(tris[k], cfg, traversal_, parts[c]);
        }
      } catch (...) {
        errors[id] = std::current_exception();
        next.store(chunks);  // the others stop at their next chunk
      }
    };
    run_on_threads(threads, rasterize);
    for (const std::exception_ptr& e : errors)
      if (e) std::rethrow_exception(e);
    // Join the chunks' lists in triangle order: offsets first, then the copies in parallel.
    std::vector<size_t> offset(chunks + 1);
    offset[0] = out.spans.size();
    for (size_t c = 0; c < chunks; ++c) offset[c + 1] = offset[c] + parts[c].size();
    out.spans.resize(offset[chunks]);
    next.store(0);
    run_on_threads(threads, [&](size_t) {
      for (size_t c; (c = next.fetch_add(1, std::memory_order_relaxed)) < chunks;)
        std::copy(parts[c].begin(), parts[c].end(), out.spans.begin() + ptrdiff_t(offset[c]));
    });
  }

 private:
  // Runs fn(0) on the calling thread and fn(1..threads-1) on new ones; returns when all are done.
  template <class Fn>
  static void run_on_threads(size_t threads, Fn&& fn) {
    std::vector<std::thread> pool;
    for (size_t id = 1; id < threads; ++id) pool.emplace_back(fn, id);
    fn(0);
    for (std::thread& th : pool) th.join();
  }

  Traversal traversal_;
  int threads_;
  std::vector<SpanList> parts_;
};

class FloatScanlineEngine : public Engine {
 public:
  void run(const SetupResult& setup, const RasterConfig& cfg, EngineResult& out) override {
    for (const TriangleSetup& t : setup.tris) float_scanline_triangle(t, cfg, out.spans);
  }
};

}  // namespace

std::unique_ptr<Engine> make_golden_engine(Traversal traversal, int threads) {
  return std::make_unique<GoldenEngine>(traversal, threads);
}

std::unique_ptr<Engine> make_golden_engine() { return make_golden_engine(Traversal::Auto, 1); }

std::unique_ptr<Engine> make_float_scanline_engine() {
  return std::make_unique<FloatScanlineEngine>();
}

}  // namespace trirast
