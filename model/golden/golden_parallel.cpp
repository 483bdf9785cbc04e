// The golden engines: one traversal over every triangle, on one thread or several.
//
// Several threads: the calling thread is the writer, the only one that touches the output list;
// the others are helpers. The triangles are cut into chunks of consecutive triangles, and the
// chunks into two ranges: a front range [0, split) and a back range [split, chunks). The writer
// rasterizes the front range from its first chunk on, straight into the output (no copy: the
// spans land where the single-threaded engine puts them). The helpers rasterize the back range
// from its first chunk on, each chunk into a span list of its own. When the writer has done its
// range it appends the helpers' finished chunks in order, one copy each, while the helpers are
// still rasterizing later ones. Either side that runs out of work takes chunks from the far end
// of the other's range (the writer from the end of the back range, the helpers from the end of
// the front range), into a chunk list that the writer copies when its turn comes; so neither side
// idles while the other has work, whatever the split. The split is chosen so that the writer's
// share of rasterizing plus its copying of the helpers' share takes as long as the helpers' share.
//
// The output is the single-threaded list, span for span and in the same order, for any thread
// count: every chunk's spans are appended exactly once, in chunk order. Nothing is merged or
// sorted, and the output is never zero-filled or resized: it is reserved once (see
// estimated_spans) and grows by push_back and by appending whole chunks.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <memory>
#include <system_error>
#include <thread>

#include "golden/golden.hpp"

namespace trirast {

namespace {

// At most one span per row of each box: reserving this spares a chunk list its regrowth. It reads
// each triangle's box just before the chunk is rasterized, so the traversal finds them in cache.
size_t max_spans(const std::vector<TriangleSetup>& tris, size_t first, size_t last) {
  size_t n = 0;
  for (size_t k = first; k < last; ++k) n += size_t(tris[k].box.height());
  return n;
}

// The output's reservation: the bound above from every 64th triangle, scaled up, plus an eighth.
// Summing every box is a pass over the whole scene, a cache and TLB miss per triangle (about a
// seventh of a one-thread run on 10-pixel triangles); the sample costs a 64th of that. The bound
// exceeds the spans by 5..8% on the benchmark scenes, so the output rarely regrows; when it does
// (a scene whose big triangles the sample missed), push_back and insert grow it geometrically.
size_t estimated_spans(const std::vector<TriangleSetup>& tris) {
  constexpr size_t kStride = 64;
  size_t sampled = 0, n = 0;
  for (size_t k = 0; k < tris.size(); k += kStride, ++sampled) n += size_t(tris[k].box.height());
  if (sampled == 0) return 0;
  const size_t scaled = size_t(double(n) * double(tris.size()) / double(sampled));
  return scaled + scaled / 8 + 256;
}

// Chunks of consecutive triangles: at most 256 triangles, and at least 16 chunks per thread when
// the scene is small, so that a few big triangles still spread over the threads.
constexpr size_t kMaxChunkTriangles = 256;
constexpr size_t kChunksPerThread = 16;

// Copying a span into the output costs about this fraction of rasterizing it (measured with
// scanline bounds on 10..60-pixel triangles: a 22 MB append against 48 ms of traversal); it sets
// the split only, the stealing at the ends corrects a wrong guess.
constexpr double kCopyCost = 0.07;

// A range of chunk indices [lo, hi) that two sides take from its two ends, lock-free: both bounds
// live in one 64-bit word. On a cache line of its own, so that claims from one range do not slow
// down claims from the other.
class alignas(64) ChunkRange {
 public:
  void reset(uint32_t lo, uint32_t hi) { bounds_.store(pack(lo, hi), std::memory_order_relaxed); }
  bool take_front(uint32_t& chunk) {
    uint64_t b = bounds_.load(std::memory_order_relaxed);
    for (;;) {
      const uint32_t lo = uint32_t(b), hi = uint32_t(b >> 32);
      if (lo >= hi) return false;
      if (bounds_.compare_exchange_weak(b, pack(lo + 1, hi), std::memory_order_relaxed)) {
        chunk = lo;
        return true;
      }
    }
  }
  bool take_back(uint32_t& chunk) {
    uint64_t b = bounds_.load(std::memory_order_relaxed);
    for (;;) {
      const uint32_t lo = uint32_t(b), hi = uint32_t(b >> 32);
      if (lo >= hi) return false;
      if (bounds_.compare_exchange_weak(b, pack(lo, hi - 1), std::memory_order_relaxed)) {
        chunk = hi - 1;
        return true;
      }
    }
  }

 private:
  static uint64_t pack(uint32_t lo, uint32_t hi) { return uint64_t(hi) << 32 | lo; }
  std::atomic<uint64_t> bounds_{0};
};

// One chunk rasterized off the writer: its spans and whether they are complete. A cache line (or
// more) each, so that a helper filling one chunk does not share a line with the writer copying
// the previous one.
struct alignas(64) ChunkSpans {
  SpanList spans;
  std::atomic<bool> ready{false};
};

class GoldenEngine : public Engine {
 public:
  GoldenEngine(Traversal traversal, int threads) : traversal_(traversal), threads_(threads) {
    if (threads_ <= 0) threads_ = int(std::max(1u, std::thread::hardware_concurrency()));
  }

  void run(const SetupResult& setup, const RasterConfig& cfg, EngineResult& out) override {
    const std::vector<TriangleSetup>& tris = setup.tris;
    const size_t n = tris.size();
    const size_t threads = size_t(threads_);
    const size_t per_chunk =
        std::clamp<size_t>(n / (threads * kChunksPerThread), 1, kMaxChunkTriangles);
    const size_t chunks = (n + per_chunk - 1) / per_chunk;
    if (threads <= 1 || chunks < 2) {
      out.spans.reserve(out.spans.size() + estimated_spans(tris));
      for (const TriangleSetup& t : tris) golden_triangle(t, cfg, traversal_, out.spans);
      return;
    }
    run_parallel(tris, cfg, std::min(threads, chunks), per_chunk, chunks, out.spans);
  }

 private:
  void run_parallel(const std::vector<TriangleSetup>& tris, const RasterConfig& cfg,
                    size_t threads, size_t per_chunk, size_t chunks, SpanList& out) {
    const size_t n = tris.size();
    auto first = [&](size_t c) { return std::min(n, c * per_chunk); };
    auto rasterize = [&](size_t c, SpanList& spans) {
      for (size_t k = first(c), end = first(c + 1); k < end; ++k)
        golden_triangle(tris[k], cfg, traversal_, spans);
    };
    if (chunk_capacity_ < chunks) {
      chunk_ = std::make_unique<ChunkSpans[]>(chunks);
      chunk_capacity_ = chunks;
    }
    for (size_t c = 0; c < chunks; ++c) chunk_[c].ready.store(false, std::memory_order_relaxed);
    // The writer's share x of the chunks: x + kCopyCost * (1 - x) = (1 - x) / helpers.
    const double helpers = double(threads - 1);
    const double x = (1 - kCopyCost * helpers) / (1 + helpers - kCopyCost * helpers);
    const size_t split = std::clamp<size_t>(size_t(x * double(chunks) + 0.5), 1, chunks - 1);
    front_.reset(0, uint32_t(split));
    back_.reset(uint32_t(split), uint32_t(chunks));
    std::atomic<bool> stop{false};
    // A failure anywhere stops every thread at its next chunk; the one of the lowest chunk wins.
    struct Failure {
      size_t chunk = SIZE_MAX;
      std::exception_ptr error;
    };
    std::vector<Failure> failures(threads);

    auto helper = [&](size_t id) {
      uint32_t c = 0;
      bool busy = false;
      try {
        while (!stop.load(std::memory_order_relaxed) &&
               (back_.take_front(c) || front_.take_back(c))) {
          busy = true;
          ChunkSpans& mine = chunk_[c];
          mine.spans.clear();
          mine.spans.reserve(max_spans(tris, first(c), first(c + 1)));
          rasterize(c, mine.spans);
          mine.ready.store(true, std::memory_order_release);
          busy = false;
        }
      } catch (...) {
        failures[id] = Failure{busy ? c : 0, std::current_exception()};
        stop.store(true);
      }
    };

    std::vector<std::thread> pool;
    pool.reserve(threads - 1);
    try {
      for (size_t id = 1; id < threads; ++id) pool.emplace_back(helper, id);
    } catch (const std::system_error&) {
      // No more threads to be had: the writer takes whatever the helpers started leave.
    }

    // The writer (its reservation overlaps with the helpers' first chunks).
    size_t next = 0;  // the next chunk to append to the output
    uint32_t c = 0;
    try {
      out.reserve(out.size() + estimated_spans(tris));
      while (next < chunks && !stop.load(std::memory_order_relaxed)) {
        if (chunk_[next].ready.load(std::memory_order_acquire)) {
          const SpanList& done = chunk_[next].spans;
          out.insert(out.end(), done.begin(), done.end());
          ++next;
        } else if (front_.take_front(c)) {
          // The front range's first chunk is always the next one: straight into the output.
          rasterize(c, out);
          ++next;
        } else if (back_.take_back(c)) {
          ChunkSpans& mine = chunk_[c];
          mine.spans.clear();
          mine.spans.reserve(max_spans(tris, first(c), first(c + 1)));
          rasterize(c, mine.spans);
          mine.ready.store(true, std::memory_order_relaxed);
        } else {
          std::this_thread::yield();  // the next chunk is a helper's, still being rasterized
        }
      }
    } catch (...) {
      failures[0] = Failure{c, std::current_exception()};
      stop.store(true);
    }
    for (std::thread& th : pool) th.join();
    const Failure* worst = nullptr;
    for (const Failure& f : failures)
      if (f.error && (!worst || f.chunk < worst->chunk)) worst = &f;
    if (worst) std::rethrow_exception(worst->error);
  }

  Traversal traversal_;
  int threads_;
  // Chunk span lists of the helpers (and the writer's stolen chunks), kept between runs so that a
  // second run reuses their memory.
  std::unique_ptr<ChunkSpans[]> chunk_;
  size_t chunk_capacity_ = 0;
  ChunkRange front_, back_;
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
