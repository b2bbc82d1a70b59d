// One ping thread per module (see PingThreads.h).
#include "watchdog/PingThreads.h"

namespace rgnav {

PingThreads::PingThreads(std::map<std::string, Ping> pings, OnResult onResult) : onResult_(std::move(onResult)) {
  for (auto& [module, ping] : pings) slots_.emplace(module, Slot{std::move(ping)});
  for (auto& [module, slot] : slots_) threads_.emplace_back([this, &module, &slot] { run(module, slot); });
}

PingThreads::~PingThreads() { stop(); }

void PingThreads::ping(const std::string& module, pid_t pid) {
  {
    std::lock_guard lock(mutex_);
    Slot& slot = slots_.at(module);
    slot.asked = true;
    slot.pid = pid;
  }
  wake_.notify_all();
}

void PingThreads::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (auto& t : threads_)
    if (t.joinable()) t.join();
}

void PingThreads::run(const std::string& module, Slot& slot) {
  std::unique_lock lock(mutex_);
  while (true) {
    wake_.wait(lock, [&] { return stopping_ || slot.asked; });
    if (stopping_) return;
    slot.asked = false;
    const pid_t pid = slot.pid;
    lock.unlock();
    const bool answered = slot.ping(pid);
    lock.lock();
    if (stopping_) return;
    lock.unlock();
    onResult_(module, answered);
    lock.lock();
  }
}

}  // namespace rgnav
