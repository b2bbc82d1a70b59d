// The LowLevelDrive module's control thread (see DriveLoop.h).
#include "servers/lowleveldrive/DriveLoop.h"

#include <iostream>

#include "clientlibs/lowleveldrive/convert.h"

namespace rgnav {
namespace {

using Clock = std::chrono::steady_clock;

// Odometry readings asked for per call: a tick normally finds one or two new ones.
constexpr std::uint32_t kOdometryBatch = 50;

// Calls to the Base must fit the control loop: each call (and its retries) gets two periods.
ClientSettings withTickBudget(ClientSettings settings, double periodSeconds) {
  const auto budget = std::chrono::milliseconds(static_cast<long>(2000.0 * periodSeconds));
  settings.callTimeout = budget;
  settings.connectTimeout = budget;
  settings.retryBudget = budget;
  settings.firstContactBudget = budget;
  return settings;
}

double wallSeconds(Clock::time_point t) { return std::chrono::duration<double>(t.time_since_epoch()).count(); }

bool sameChain(const DriveChain& a, const DriveChain& b) {
  return a.id == b.id && a.chain.segments() == b.chain.segments() && a.startSpeed == b.startSpeed &&
         a.startTime == b.startTime && a.cruiseSpeed == b.cruiseSpeed;
}

}  // namespace

DriveLoop::DriveLoop(const LowLevelDriveConfig& config, ClientSettings baseSettings, const std::string& baseObject,
                     ModuleHealth& health)
    : config_(config),
      health_(health),
      base_(withTickBudget(std::move(baseSettings), config.periodSeconds), baseObject),
      drive_(config) {
  health_.addReporter([this](ModuleHealth& h) {
    const DriveReport r = report();
    h.set("loop_period_last_us", static_cast<std::uint64_t>(r.loopPeriodLastSeconds * 1e6));
    h.set("loop_period_p99_us", static_cast<std::uint64_t>(r.loopPeriodP99Seconds * 1e6));
    h.set("drive_state", static_cast<std::uint64_t>(toIdl(r.drive.state)));
    h.set("commands_sent", r.commandsSent);
    std::lock_guard lock(mutex_);
    h.set("chains_accepted", chainsAccepted_);
    h.set("loop_ticks", periods_.periods());
  });
}

DriveLoop::~DriveLoop() { stop(); }

void DriveLoop::start() { thread_ = std::thread([this] { run(); }); }

void DriveLoop::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void DriveLoop::setChain(const DriveChain& chain) {
  std::lock_guard lock(mutex_);
  if (accepted_ && accepted_->id == chain.id) {
    if (sameChain(*accepted_, chain)) return;  // a retry of the accepted chain
    throw InvalidArgumentError("chain " + std::to_string(chain.id) + " was accepted before with other segments");
  }
  drive_.setChain(chain);
  accepted_ = chain;
  ++chainsAccepted_;
}

void DriveLoop::brake() {
  std::lock_guard lock(mutex_);
  drive_.stop();
}

DriveReport DriveLoop::report() {
  std::lock_guard lock(mutex_);
  return DriveReport{drive_.status(), periods_.lastSeconds(), periods_.p99Seconds(), commandsSent_};
}

void DriveLoop::run() {
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(config_.periodSeconds));
  Clock::time_point slot = Clock::now();
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    lock.unlock();
    tick(Clock::now());
    lock.lock();
    slot += period;
    const Clock::time_point now = Clock::now();
    if (slot < now) slot += (now - slot) / period * period + period;  // overran: skip the missed slots
    wake_.wait_until(lock, slot, [this] { return stopping_; });
  }
  lock.unlock();
  if (commanding_) send(VelocityCommand{});
}

void DriveLoop::tick(Clock::time_point start) {
  const std::optional<OdometryReading> reading = newestOdometry();
  VelocityCommand command;
  bool idle = false;
  {
    std::lock_guard lock(mutex_);
    periods_.tickStarted(start);
    command = drive_.tick(reading, wallSeconds(Clock::now()));
    idle = drive_.status().state == DriveState::Idle;
  }
  if (!idle || commanding_) send(command);  // an idle drive sends one last command, then none
  commanding_ = !idle;
}

std::optional<OdometryReading> DriveLoop::newestOdometry() {
  try {
    DataBatch<OdometryReading> batch = base_.odometrySince(latest_ ? latest_->id : 0, kOdometryBatch);
    if (latest_ && batch.latestId < latest_->id) {  // the Base restarted: its IDs begin again
      latest_.reset();
      batch = base_.odometrySince(0, kOdometryBatch);
    }
    const DataId have = batch.records.empty() ? (latest_ ? latest_->id : 0) : batch.records.back().id;
    if (have < batch.latestId) batch = base_.odometrySince(batch.latestId - 1, 1);  // behind: the newest is enough
    if (!batch.records.empty()) latest_ = batch.records.back();
    baseResult("base_odometry", odometryError_, "");
  } catch (const Error& e) {
    baseResult("base_odometry", odometryError_, e.what());
  }
  return latest_;
}

void DriveLoop::send(const VelocityCommand& command) {
  try {
    base_.setVelocity(command.translational, command.rotational);
    std::lock_guard lock(mutex_);
    ++commandsSent_;
  } catch (const Error& e) {
    baseResult("base_commands", commandError_, e.what());
    return;
  }
  baseResult("base_commands", commandError_, "");
}

void DriveLoop::baseResult(const char* source, std::string& lastError, const std::string& error) {
  if (error == lastError) return;
  if (error.empty()) {
    health_.clearError(source);
    std::cerr << "LowLevelDrive: " << source << ": the Base answers again" << std::endl;
  } else {
    health_.setError(source, error);
    std::cerr << "LowLevelDrive: " << source << ": " << error << std::endl;
  }
  lastError = error;
}

}  // namespace rgnav
