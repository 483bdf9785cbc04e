// The golden engines: one traversal over every triangle, on one thread or several.
//
// Several threads: the calling thread is the writer, the only one that touches the output list;
// the others are helpers. The triangles are cut into chunks of consecutive triangles, and the
// chunks into two ranges: a front range [0, split) and a back range [split, chunks). The writer
// rasterizes the front range from its first chunk on, straight into the output (no copy: the
// spans land where the single-threaded engine puts them). The helpers rasterize the back range
// from its first chunk on, each chunk into a span list of its own, which the writer appends in
// order (one copy each) when it gets there. Whichever side runs out of work takes the lowest
// chunk not yet taken from the other's range, so that both sides end together and the chunks
// still to be copied at the end are the last one or two: the writer, having finished its range,
// first copies the helpers' finished chunks and then works beside them on the chunks right
// after theirs (straight into the output when a chunk is the next one in order, else into its
// list). The split is set from an estimate of each triangle's cost (a sample of the boxes) so
// that the writer's range plus its copying of the helpers' share takes as long as the helpers'
// share: the better the guess, the fewer spans are copied.
//
// The output is the single-threaded list, span for span and in the same order, for any thread
// count: every chunk's spans are appended exactly once, in chunk order. Nothing is merged or
// sorted, and the output is never zero-filled or resized: it is reserved once (see Plan) and
// grows by push_back and by appending whole chunks.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <thread>
#include <vector>

#include "golden/golden.hpp"
#include "golden/helper_pool.hpp"

namespace trirast {

namespace {

// At most one span per row of each box: reserving this spares a chunk list its regrowth. It reads
// each triangle's box just before the chunk is rasterized, so the traversal finds them in cache.
size_t max_spans(const std::vector<TriangleSetup>& tris, size_t first, size_t last) {
  size_t n = 0;
  for (size_t k = first; k < last; ++k) n += size_t(tris[k].box.height());
  return n;
}

// A traversal's cost for one triangle, in units of one pixel tested, as a guess for balancing: a
// fixed part (setup of the walk) plus its rows, or its box's pixels if fewer (small boxes are
// walked pixel by pixel, large ones row by row). Only the split depends on it; the taking of
// chunks from the other side corrects a wrong guess.
constexpr int64_t kTriangleCost = 24;
constexpr int64_t kRowCost = 12;
int64_t cost_guess(const PixelBox& box) {
  const int64_t rows = box.height();
  return kTriangleCost + std::min(rows * box.width(), kRowCost * rows);
}

// Both from every 64th triangle: summing every box is a pass over the whole scene, a cache and
// TLB miss per triangle (about a seventh of a one-thread run on 10-pixel triangles); the sample
// costs a 64th of that.
struct Plan {
  // The output's reservation: at most one span per row of each box, scaled up from the sample,
  // plus an eighth. The bound exceeds the spans by 5..8% on the benchmark scenes, so the output
  // rarely regrows; when it does (a scene whose big triangles the sample missed), push_back and
  // insert grow it geometrically.
  size_t reserve = 0;
  // The first chunk of the back range: the writer's range [0, split) holds `writer_share` of the
  // scene's guessed cost.
  size_t split = 0;
};

constexpr size_t kSampleStride = 64;

Plan make_plan(const std::vector<TriangleSetup>& tris, size_t per_chunk, size_t chunks,
               double writer_share) {
  Plan plan;
  size_t sampled = 0, rows = 0;
  int64_t total = 0;
  std::vector<int64_t> cost;  // the guessed cost of each sampled triangle
  if (chunks > 1) cost.reserve(tris.size() / kSampleStride + 1);
  for (size_t k = 0; k < tris.size(); k += kSampleStride, ++sampled) {
    rows += size_t(tris[k].box.height());
    if (chunks > 1) {
      cost.push_back(cost_guess(tris[k].box));
      total += cost.back();
    }
  }
  if (sampled == 0) return plan;
  const size_t scaled = size_t(double(rows) * double(tris.size()) / double(sampled));
  plan.reserve = scaled + scaled / 8 + 256;
  if (chunks > 1) {
    // The sampled triangle where the writer's share of the cost is reached, and its chunk.
    const int64_t target = int64_t(writer_share * double(total));
    int64_t sum = 0;
    size_t s = 0;
    while (s < cost.size() && sum + cost[s] <= target) sum += cost[s++];
    plan.split = std::clamp<size_t>((s * kSampleStride) / per_chunk, 1, chunks - 1);
  }
  return plan;
}

// Chunks of consecutive triangles: at most 256 triangles, and at least 16 chunks per thread when
// the scene is small, so that a few big triangles still spread over the threads.
constexpr size_t kMaxChunkTriangles = 256;
constexpr size_t kChunksPerThread = 16;

// Copying a span into the output costs about this fraction of rasterizing it (measured with
// scanline bounds on 10..60-pixel triangles: a 22 MB append against 48 ms of traversal); it sets
// the split only, the stealing at the ends corrects a wrong guess.
constexpr double kCopyCost = 0.07;

// A range of chunk indices [next, end) that several threads take from its front, lock-free. On
// a cache line of its own, so that claims from one range do not slow down claims from the other.
class alignas(64) ChunkRange {
 public:
  void reset(uint32_t first, uint32_t end) {
    next_.store(first, std::memory_order_relaxed);
    end_ = end;
  }
  bool take(uint32_t& chunk) {
    if (next_.load(std::memory_order_relaxed) >= end_) return false;  // spares a write when done
    chunk = next_.fetch_add(1, std::memory_order_relaxed);
    return chunk < end_;
  }

 private:
  std::atomic<uint32_t> next_{0};
  uint32_t end_ = 0;
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
      out.spans.reserve(out.spans.size() + make_plan(tris, per_chunk, 1, 0).reserve);
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
    // A chunk into its own list, marked ready for the writer to append (release: the writer
    // reads the list after seeing the flag).
    auto rasterize_to_list = [&](size_t c) {
      ChunkSpans& mine = chunk_[c];
      mine.spans.clear();
      mine.spans.reserve(max_spans(tris, first(c), first(c + 1)));
      rasterize(c, mine.spans);
      mine.ready.store(true, std::memory_order_release);
    };
    if (chunk_capacity_ < chunks) {
      chunk_ = std::make_unique<ChunkSpans[]>(chunks);
      chunk_capacity_ = chunks;
    }
    for (size_t c = 0; c < chunks; ++c) chunk_[c].ready.store(false, std::memory_order_relaxed);
    const size_t helpers_here = std::min(threads - 1, helpers_.reserve(threads - 1));
    // The writer's share x of the work: x + kCopyCost * (1 - x) = (1 - x) / helpers.
    const double helpers = double(helpers_here);
    const double x = (1 - kCopyCost * helpers) / (1 + helpers - kCopyCost * helpers);
    std::atomic<bool> stop{false}, planned{false};
    // A failure anywhere stops every thread at its next chunk; the one of the lowest chunk wins.
    struct Failure {
      size_t chunk = SIZE_MAX;
      std::exception_ptr error;
    };
    std::vector<Failure> failures(threads);

    const HelperPool::Job helper = [&](size_t id) {
      uint32_t c = 0;
      bool busy = false;
      while (!planned.load(std::memory_order_acquire)) std::this_thread::yield();
      try {
        while (!stop.load(std::memory_order_relaxed) &&
               (back_.take(c) || front_.take(c))) {
          busy = true;
          rasterize_to_list(c);
          busy = false;
        }
      } catch (...) {
        failures[id] = Failure{busy ? c : 0, std::current_exception()};
        stop.store(true);
      }
    };

    // Wake the helpers first: they take longer to wake (about 80 us here) than the writer takes
    // to plan (about 30 us on 100,000 triangles).
    if (helpers_here > 0) helpers_.start(helper, helpers_here);
    Plan plan;
    try {
      plan = make_plan(tris, per_chunk, chunks, x);
    } catch (...) {  // out of memory for the sample: let the helpers go before giving up
      stop.store(true);
      planned.store(true, std::memory_order_release);
      if (helpers_here > 0) helpers_.finish();
      throw;
    }
    front_.reset(0, uint32_t(plan.split));
    back_.reset(uint32_t(plan.split), uint32_t(chunks));
    planned.store(true, std::memory_order_release);

    // The writer (its reservation overlaps with the helpers' first chunks).
    size_t next = 0;  // the next chunk to append to the output
    uint32_t c = 0;
    try {
      out.reserve(out.size() + plan.reserve);
      while (next < chunks && !stop.load(std::memory_order_relaxed)) {
        if (chunk_[next].ready.load(std::memory_order_acquire)) {
          const SpanList& done = chunk_[next].spans;
          out.insert(out.end(), done.begin(), done.end());
          ++next;
        } else if (front_.take(c) || back_.take(c)) {
          if (c == next) {
            rasterize(c, out);  // the next chunk in order: straight into the output
            ++next;
          } else {
            rasterize_to_list(c);  // a later one, appended when its turn comes
          }
        } else {
          std::this_thread::yield();  // the next chunk is a helper's, still being rasterized
        }
      }
    } catch (...) {
      failures[0] = Failure{c, std::current_exception()};
      stop.store(true);
    }
    if (helpers_here > 0) helpers_.finish();
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
  HelperPool helpers_;  // last: destroyed (its threads joined) before what they use
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
