// RequestIds: the request IDs a client gives its non-idempotent calls (DESIGN.md "Restarts are
// normal"): random, nonzero, so that two clients of one module do not pick the same, and kept by
// the caller over its retries.
#pragma once

#include <cstdint>
#include <random>

namespace rgnav {

class RequestIds {
 public:
  RequestIds() : random_([] {
    std::random_device entropy;
    return (std::uint64_t{entropy()} << 32) | entropy();
  }()) {}

  // `given` if nonzero, else a new random ID.
  std::uint64_t operator()(std::uint64_t given = 0) {
    std::uint64_t id = given;
    while (id == 0) id = random_();
    return id;
  }

 private:
  std::mt19937_64 random_;
};

}  // namespace rgnav
