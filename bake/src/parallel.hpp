#pragma once
// A fixed work partition over std::threads: items [0, count) in chunks of `chunk`, each chunk
// done whole by one thread, taken in order from an atomic counter. Results must be written per
// item (or per chunk) by the caller, never accumulated across chunks in completion order: then
// the bytes do not depend on which thread did what. The calling thread reports progress while
// the workers run.

#include "luxel/bake/bake.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <string_view>
#include <thread>
#include <vector>

namespace luxel::bake::detail {

struct Counters {
  std::atomic<uint64_t> done{0}, rays{0};
};

/// Runs fn(chunk_index, begin, end) for every chunk on `threads` threads; the first exception a
/// worker throws is rethrown here after all have stopped.
template <class Fn>
void parallel_chunks(uint64_t count, uint64_t chunk, int threads, std::string_view phase, const ProgressFn& progress,
                     Counters& counters, Fn&& fn) {
  const uint64_t chunks = (count + chunk - 1) / chunk;
  const auto start = std::chrono::steady_clock::now();
  auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  std::atomic<uint64_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex m;
  std::condition_variable cv;
  int running = std::max(1, threads);
  auto worker = [&] {
    for (;;) {
      if (failed.load()) break;
      const uint64_t c = next.fetch_add(1);
      if (c >= chunks) break;
      try {
        fn(c, c * chunk, std::min(count, (c + 1) * chunk));
      } catch (...) {
        std::lock_guard lock(m);
        if (!error) error = std::current_exception();
        failed = true;
      }
    }
    std::lock_guard lock(m);
    --running;
    cv.notify_all();
  };
  std::vector<std::thread> pool;
  const int n = std::max(1, threads);
  pool.reserve(size_t(n));
  for (int i = 0; i < n; ++i) pool.emplace_back(worker);
  {
    std::unique_lock lock(m);
    while (running > 0) {
      cv.wait_for(lock, std::chrono::milliseconds(100));
      if (progress && running > 0) {
        lock.unlock();
        progress({phase, counters.done.load(), count, counters.rays.load(), seconds(), false});
        lock.lock();
      }
    }
  }
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  if (progress) progress({phase, count, count, counters.rays.load(), seconds(), true});
}

}  // namespace luxel::bake::detail
