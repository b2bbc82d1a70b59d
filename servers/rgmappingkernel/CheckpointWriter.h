// CheckpointWriter: writes the RG Mapping Kernel's checkpoints on its own thread, so that no
// client call waits for a file write: the service takes a checkpoint's content under its lock
// (fast: serialising in memory) and hands it over; the writer appends the new scans to the
// journal and then replaces the map file (RgMappingKernelService.h), in the order handed over.
// A map handed over while an older one waits is written instead of it (the journal lines of
// both are appended, in order). Each journal line is appended exactly once: lines whose append
// failed wait for the next attempt, lines appended before the map write failed are not appended
// again (a journal longer than its map is what a crash leaves too; loading trims it). A failed
// write degrades the module with the reason and is retried with backoff (CheckpointRetry.h) on
// the writer's thread, with the newest map, also when nothing new is handed over.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include "servers/common/CheckpointRetry.h"

namespace rgnav {

class CheckpointWriter {
 public:
  // The two files of a checkpoint; each throws FileError.
  struct Files {
    std::function<void(const std::string& lines)> appendJournal;
    std::function<void(const std::string& map)> replaceMap;
  };

  // `durableRevision`: the pose revision of the checkpoint already on disk. The backoff after
  // failed writes is [minDelay, maxDelay] (CheckpointRetry.h).
  CheckpointWriter(Files files, ModuleHealth& health, std::uint64_t durableRevision,
                   std::chrono::milliseconds minDelay = CheckpointRetry::kMinDelay,
                   std::chrono::milliseconds maxDelay = CheckpointRetry::kMaxDelay);
  ~CheckpointWriter();  // makes one last attempt at what was handed over, then stops
  CheckpointWriter(const CheckpointWriter&) = delete;
  CheckpointWriter& operator=(const CheckpointWriter&) = delete;

  // Hands a checkpoint over: the journal lines after those handed over before, the whole map and
  // the pose revision it holds. Returns at once.
  void submit(std::string journal, std::string map, std::uint64_t revision);
  // Writes what was handed over now, also during a backoff, and waits until it is written or
  // has failed.
  void flush();
  // The pose revision of the last checkpoint written: what a restart would resume with.
  std::uint64_t durableRevision() const;

 private:
  void run();
  void attempt(std::unique_lock<std::mutex>& lock);
  bool unwritten() const { return submitted_ != written_; }  // under lock

  Files files_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  CheckpointRetry retry_;      // under mutex_
  std::string journal_, map_;  // lines not appended yet; the newest map not written yet
  std::uint64_t revision_ = 0;
  std::uint64_t submitted_ = 0, written_ = 0;  // maps handed over; the last of them written
  bool writing_ = false, urgent_ = false, stopping_ = false;
  std::uint64_t durableRevision_;
  std::thread thread_;  // last: starts once the rest is ready
};

}  // namespace rgnav
