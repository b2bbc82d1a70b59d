// A shared-counter thread pool for independent jobs; see ParallelFor.h.
#include "tests/eval/crossings/ParallelFor.h"

#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "core/common/Errors.h"

namespace rgnav {

void parallelFor(std::size_t count, int threads, const std::function<void(std::size_t)>& job) {
  if (threads < 1) throw InvalidArgumentError("parallelFor: at least one thread");
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failureMutex;
  const auto work = [&] {
    try {
      for (std::size_t i = next++; i < count; i = next++) job(i);
    } catch (...) {
      const std::lock_guard lock(failureMutex);
      if (!failure) failure = std::current_exception();
      next = count;
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(work);
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace rgnav
