// The checkpoint writing thread of the kernel (see CheckpointWriter.h).
#include "servers/rgmappingkernel/CheckpointWriter.h"

#include "core/common/Errors.h"

namespace rgnav {

CheckpointWriter::CheckpointWriter(Files files, ModuleHealth& health, std::uint64_t durableRevision,
                                   std::chrono::milliseconds minDelay, std::chrono::milliseconds maxDelay)
    : files_(std::move(files)),
      retry_(health, minDelay, maxDelay),
      durableRevision_(durableRevision),
      thread_([this] { run(); }) {}

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
    ++submitted_;
  }
  changed_.notify_all();
}

void CheckpointWriter::flush() {
  std::unique_lock lock(mutex_);
  if (!unwritten() && !writing_) return;
  urgent_ = true;
  changed_.notify_all();
  changed_.wait(lock, [&] { return !writing_ && (!unwritten() || !urgent_); });
}

std::uint64_t CheckpointWriter::durableRevision() const {
  std::lock_guard lock(mutex_);
  return durableRevision_;
}

void CheckpointWriter::run() {
  std::unique_lock lock(mutex_);
  bool lastAttemptMade = false;
  for (;;) {
    // After a failure only the backoff's end, a flush or the end starts the next attempt.
    const auto ready = [&] { return stopping_ || urgent_ || (unwritten() && !retry_.failing()); };
    if (unwritten() && retry_.failing()) {
      changed_.wait_until(lock, retry_.nextAttempt(), ready);
    } else {
      changed_.wait(lock, ready);
    }
    if (stopping_ && (lastAttemptMade || !unwritten())) return;
    if (!unwritten()) {
      urgent_ = false;
      changed_.notify_all();
      continue;
    }
    lastAttemptMade = stopping_;
    attempt(lock);
  }
}

void CheckpointWriter::attempt(std::unique_lock<std::mutex>& lock) {
  std::string journal = std::move(journal_), map = std::move(map_);
  journal_.clear();
  const std::uint64_t serial = submitted_, revision = revision_;
  urgent_ = false;
  writing_ = true;
  lock.unlock();
  bool appended = journal.empty();
  std::string error;
  try {
    if (!appended) files_.appendJournal(journal);
    appended = true;
    files_.replaceMap(map);
  } catch (const Error& e) {
    error = e.what();
  }
  lock.lock();
  writing_ = false;
  if (!appended) journal_ = journal + journal_;  // before what came meanwhile, with the next map
  if (error.empty()) {
    written_ = serial;
    durableRevision_ = revision;
    retry_.succeeded();
  } else {
    if (submitted_ == serial) map_ = std::move(map);  // else a newer map waits already
    retry_.failed(error);
  }
  changed_.notify_all();
}

}  // namespace rgnav
