// IdSequenceCheck: counts what a consumer received by ID: how many, gaps (IDs skipped, e.g.
// evicted from the producer's buffer before they were fetched) and duplicates or reorderings.
#pragma once

#include <cstdint>
#include <string>

#include "core/common/SensorData.h"

namespace rgnav {

class IdSequenceCheck {
 public:
  explicit IdSequenceCheck(DataId after = 0) : last_(after) {}

  void observe(DataId id) {
    if (id <= last_) {
      ++duplicates_;
      return;
    }
    if (received_ == 0) first_ = id;
    else if (id != last_ + 1) gaps_ += id - last_ - 1;
    last_ = id;
    ++received_;
  }

  DataId last() const { return last_; }
  std::uint64_t received() const { return received_; }
  bool clean() const { return gaps_ == 0 && duplicates_ == 0; }
  std::string summary() const {
    return "received=" + std::to_string(received_) + " first=" + std::to_string(first_) + " last=" +
           std::to_string(last_) + " gaps=" + std::to_string(gaps_) + " duplicates=" + std::to_string(duplicates_);
  }

 private:
  DataId last_;
  DataId first_ = 0;
  std::uint64_t received_ = 0;
  std::uint64_t gaps_ = 0;
  std::uint64_t duplicates_ = 0;
};

}  // namespace rgnav
