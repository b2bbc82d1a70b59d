// parallelFor: runs job(0) ... job(count - 1) on `threads` threads, each index once; the first
// exception thrown by a job is rethrown after all threads have stopped (the remaining indices
// are skipped).
#pragma once

#include <cstddef>
#include <functional>

namespace rgnav {

// Throws InvalidArgumentError for threads < 1.
void parallelFor(std::size_t count, int threads, const std::function<void(std::size_t)>& job);

}  // namespace rgnav
