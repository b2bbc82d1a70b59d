// CheckpointWriter: writes the RG Mapping Kernel's checkpoints on its own thread, so that no
// client call waits for a file write: the service takes a checkpoint's content under its lock
// (fast: serialising in memory) and hands it over; the writer appends the new scans to the
// journal and then replaces the map file (RgMappingKernelService.h), in the order handed over.
// A map handed over while an older one waits is written instead of it (the journal lines of
// both are appended, in order). A failed write is reported as the health error "checkpoint" and
// retried with the next checkpoint; the journal lines it did not append are kept for it.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include "servers/common/ModuleHealth.h"

namespace rgnav {

class CheckpointWriter {
 public:
  // Writes one checkpoint: appends `journal` (may be empty) to the journal, then replaces the
  // map; throws FileError.
  using Write = std::function<void(const std::string& journal, const std::string& map)>;

  // `durableRevision`: the pose revision of the checkpoint already on disk.
  CheckpointWriter(Write write, ModuleHealth& health, std::uint64_t durableRevision);
  ~CheckpointWriter();  // writes what was handed over, then stops
  CheckpointWriter(const CheckpointWriter&) = delete;
  CheckpointWriter& operator=(const CheckpointWriter&) = delete;

  // Hands a checkpoint over: the journal lines after those handed over before, the whole map and
  // the pose revision it holds. Returns at once.
  void submit(std::string journal, std::string map, std::uint64_t revision);
  // Waits until everything handed over is written or has failed.
  void flush();
  // The pose revision of the last checkpoint written: what a restart would resume with.
  std::uint64_t durableRevision() const;

 private:
  void run();

  Write write_;
  ModuleHealth& health_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::string journal_, map_;
  std::uint64_t revision_ = 0;
  bool pending_ = false, writing_ = false, stopping_ = false;
  std::uint64_t durableRevision_;
  std::thread thread_;  // last: starts once the rest is ready
};

}  // namespace rgnav
