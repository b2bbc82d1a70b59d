// PingThreads: the watchdog's LivenessProbe. One thread per module runs the module's ping (a
// CORBA call bounded by the heartbeat timeout, see CorbaPing.h) when asked to, and hands the
// outcome to a callback, so a hung module delays neither supervision nor the other pings.
#pragma once

#include <condition_variable>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/supervision/LivenessProbe.h"

namespace rgnav {

class PingThreads : public LivenessProbe {
 public:
  // True if the module's process (this PID) answered.
  using Ping = std::function<bool(pid_t)>;
  // Called on the module's thread, with no lock of this class held.
  using OnResult = std::function<void(const std::string& module, bool answered)>;

  PingThreads(std::map<std::string, Ping> pings, OnResult onResult);
  ~PingThreads() override;
  PingThreads(const PingThreads&) = delete;
  PingThreads& operator=(const PingThreads&) = delete;

  // std::out_of_range for a module without a ping.
  void ping(const std::string& module, pid_t pid) override;
  // Ends the threads once their current ping is over; no callback follows.
  void stop();

 private:
  struct Slot {
    Ping ping;
    bool asked = false;
    pid_t pid = 0;  // of the asked ping
  };
  void run(const std::string& module, Slot& slot);

  OnResult onResult_;
  std::map<std::string, Slot> slots_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace rgnav
