// DataBuffer: the bounded, ID-ordered buffer every producer keeps (DESIGN.md "Data by ID"):
// consumers ask for "everything after ID n"; the oldest records drop out when it is full.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "core/common/Errors.h"
#include "core/common/SensorData.h"

namespace rgnav {

template <class Record>
struct DataBatch {
  std::vector<Record> records;  // consecutive IDs, oldest first
  DataId oldestId = 0;          // oldest ID held (0 if empty)
  DataId latestId = 0;          // newest ID produced (0 if none)
  bool endOfData = false;       // no record after latestId will ever come
};

// Records must arrive with strictly increasing, consecutive IDs (record.id).
template <class Record>
class DataBuffer {
 public:
  explicit DataBuffer(std::size_t capacity) : capacity_(std::max<std::size_t>(capacity, 1)) {}

  void push(Record record) {
    if (!records_.empty() && record.id != records_.back().id + 1)
      throw InvalidArgumentError("DataBuffer: ID " + std::to_string(record.id) + " does not follow " +
                                 std::to_string(records_.back().id));
    records_.push_back(std::move(record));
    if (records_.size() > capacity_) records_.pop_front();
  }

  void markEndOfData() { endOfData_ = true; }
  bool endOfData() const { return endOfData_; }
  DataId oldestId() const { return records_.empty() ? 0 : records_.front().id; }
  DataId latestId() const { return records_.empty() ? 0 : records_.back().id; }
  std::size_t size() const { return records_.size(); }
  bool full() const { return records_.size() == capacity_; }

  // Records with ID > afterId, at most maxCount; starts at the oldest held if afterId is older.
  DataBatch<Record> since(DataId afterId, std::size_t maxCount) const {
    if (maxCount == 0) throw InvalidArgumentError("maxCount must be at least 1");
    DataBatch<Record> batch{{}, oldestId(), latestId(), endOfData_};
    if (records_.empty() || afterId >= latestId()) return batch;
    const std::size_t first = afterId < oldestId() ? 0 : static_cast<std::size_t>(afterId + 1 - oldestId());
    const std::size_t last = std::min(records_.size(), first + maxCount);
    batch.records.assign(records_.begin() + static_cast<std::ptrdiff_t>(first),
                         records_.begin() + static_cast<std::ptrdiff_t>(last));
    return batch;
  }

  const Record& get(DataId id) const {
    if (id == 0) throw InvalidArgumentError("ID 0 names no record; IDs start at 1");
    if (records_.empty() || id < oldestId() || id > latestId())
      throw NotAvailableError("ID " + std::to_string(id) + " is not held (held: " +
                              (records_.empty() ? std::string("none")
                                                : std::to_string(oldestId()) + ".." + std::to_string(latestId())) +
                              ")");
    return records_[static_cast<std::size_t>(id - oldestId())];
  }

  const std::deque<Record>& records() const { return records_; }

 private:
  std::size_t capacity_;
  std::deque<Record> records_;
  bool endOfData_ = false;
};

}  // namespace rgnav
