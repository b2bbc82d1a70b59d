// The checkpoint writing thread of the kernel (see CheckpointWriter.h).
#include "servers/rgmappingkernel/CheckpointWriter.h"

#include "core/common/Errors.h"

namespace rgnav {

CheckpointWriter::CheckpointWriter(Write write, ModuleHealth& health, std::uint64_t durableRevision)
    : write_(std::move(write)), health_(health), durableRevision_(durableRevision), thread_([this] { run(); }) {}

CheckpointWriter::~CheckpointWriter() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void CheckpointWriter::submit(std::string journal, std::string map, std::uint64_t revision) {
  {
    std::lock_guard lock(mutex_);
    journal_ += journal;
    map_ = std::move(map);
    revision_ = revision;
    pending_ = true;
  }
  changed_.notify_all();
}

void CheckpointWriter::flush() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return !pending_ && !writing_; });
}

std::uint64_t CheckpointWriter::durableRevision() const {
  std::lock_guard lock(mutex_);
  return durableRevision_;
}

void CheckpointWriter::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return pending_ || stopping_; });
    if (!pending_) return;
    std::string journal = std::move(journal_), map = std::move(map_);
    const std::uint64_t revision = revision_;
    journal_.clear();
    pending_ = false;
    writing_ = true;
    lock.unlock();
    bool written = false;
    try {
      write_(journal, map);
      written = true;
      health_.clearError("checkpoint");
    } catch (const Error& e) {
      health_.setError("checkpoint", e.what());
    }
    lock.lock();
    writing_ = false;
    if (written) {
      durableRevision_ = revision;
    } else {
      journal_ = journal + journal_;  // appended before what came meanwhile, with the next map
    }
    changed_.notify_all();
  }
}

}  // namespace rgnav
