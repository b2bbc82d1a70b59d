// The Collision Avoidance's decisions (see CollisionAvoidance.h).
#include "core/nav/avoidance/CollisionAvoidance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/nav/avoidance/ObstacleFusion.h"

namespace rgnav {

namespace {

// The reference of the current chain is trusted as the next chain's start only while the robot
// tracks it this closely; otherwise the next chain starts where the robot will be, at its speed.
constexpr double kMaxTrackingErrorM = 0.1;
constexpr double kMaxTrackingErrorRad = 0.3;
constexpr double kMaxTrackingErrorMps = 0.15;
// A robot slower than this stands.
constexpr double kStandingSpeed = 0.02;
constexpr double kStandingTurnRate = 0.05;
// A robot this slow within the goal tolerance has arrived (the drive settles the rest).
constexpr double kArrivalSpeed = 0.1;
// The drive settles at a chain's end for up to 3 s (LowLevelDrive); after its time and this the
// robot has not arrived.
constexpr double kArrivalGraceS = 4.0;
// Curvatures below this are straight.
constexpr double kStraight = 1e-6;
// A new chain continues the current one's turn to its end if that lies within this.
constexpr double kMaxLeadM = 3.0;
// Chains cut short before an obstacle must still be this long to be worth driving.
constexpr double kMinChainM = 0.15;
// Straightening out from a turn uses this share of the rotational acceleration.
constexpr double kUnwindShare = 0.9;
// A chain with little left is replaced at most this often (each new chain restarts the drive's
// reference, which must get going).
constexpr double kRefreshPeriodS = 0.5;
// Chains are cut back in these steps to where the robot can turn on the spot, with this much
// more than the margin around it (the robot stops within a few centimetres of the chain's end).
constexpr double kTurnableStepM = 0.05;
constexpr double kTurnSlackM = 0.05;
// A chain's end off the targets' polyline counts this many times its distance to it.
constexpr double kOffPathWeight = 2.0;
// What cutting a chain short costs: a chain that reaches its end beats one that stops early.
constexpr double kCutPenaltyS = 2.0;
// From a scan to the drive acting on it: the scan period, the planning latency and the drive's
// command period and delay, s.
constexpr double kReactionS = 0.3;
// The slowest cruise speed, m/s: the robot as good as stands (a few millimetres a second).
constexpr double kCrawlSpeed = 0.005;
// Held back by moving obstacles (its chains capped below kHeldSpeedMps) for longer than this, the
// robot treats them as standing ones: people who do not pass, or obstacles taken for moving (a
// wall's face beside the robot that far beams graze and near ones hit).
constexpr double kHeldSpeedMps = 0.1;
constexpr double kPeoplePatienceS = 5.0;
// A chain driven this much faster than the moving obstacles allow is replaced.
constexpr double kSpeedSlackMps = 0.05;
// Moving obstacles farther than this (clearance plus arc length) do not slow the robot, m: from
// the top speed the robot stops within less (oncomingStopSpeed(6 m) is above 1.3 m/s at 0.5 m/s^2).
constexpr double kMovingReachM = 6.0;

double distance(const Pose2D& a, const Pose2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }

// Where `p` lies along the stretch from a to b: u = 0 at a, 1 at b (not clamped), and its
// distance to the nearest point of the stretch.
struct OnStretch {
  double u = 0.0;
  double distance = 0.0;
};
OnStretch onStretch(const Pose2D& a, const Pose2D& b, const Pose2D& p) {
  const double length = distance(a, b);
  const double u = length > 0.0 ? ((p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y)) / (length * length) : 0.0;
  const double w = std::clamp(u, 0.0, 1.0);
  return {u, std::hypot(a.x + w * (b.x - a.x) - p.x, a.y + w * (b.y - a.y) - p.y)};
}

}  // namespace

std::string toString(AvoidanceAction action) {
  switch (action) {
    case AvoidanceAction::Keep: return "keep";
    case AvoidanceAction::Drive: return "drive";
    case AvoidanceAction::Wait: return "wait";
    case AvoidanceAction::Blocked: return "blocked";
    case AvoidanceAction::GoalReached: return "goal-reached";
  }
  return "unknown";
}

CollisionAvoidance::CollisionAvoidance(const CollisionAvoidanceConfig& config, const Footprint& footprint,
                                       const MotionLimits& limits)
    : config_(config), footprint_(footprint), limits_(limits) {
  validate(config);
  validate(footprint);
  validate(limits);
}

void CollisionAvoidance::setTargets(std::vector<Pose2D> targets) {
  targets_ = std::move(targets);
  targetsChanged_ = true;
}

CollisionAvoidance::PlanStart CollisionAvoidance::planStart(const RobotState& state) const {
  if (current_ && currentTimed_) {
    const double t = state.stamp + config_.planningLatencyS - current_->startTime;
    if (t < currentTimed_->duration()) {
      const ReferenceState ref = currentTimed_->stateAt(std::max(t, 0.0));
      const ReferenceState nowRef = currentTimed_->stateAt(std::max(state.stamp - current_->startTime, 0.0));
      const Pose2D& now = nowRef.pose;
      if (distance(now, state.pose) < kMaxTrackingErrorM &&
          std::abs(normalizeAngle(now.theta - state.pose.theta)) < kMaxTrackingErrorRad &&
          std::abs(nowRef.velocity - state.velocity) < kMaxTrackingErrorMps) {
        const TrajectoryChain& chain = current_->chain;
        // The lead: the rest of the turn the reference is in, up to where the curvature is 0.
        double leadEnd = ref.s;
        if (std::abs(chain.curvatureAt(ref.s)) > kStraight) {
          double segmentStart = 0.0;
          for (const TrajectorySegment& segment : chain.segments()) {
            if (segmentStart > ref.s && std::abs(segment.curvature) <= kStraight) {
              if (segmentStart - ref.s <= kMaxLeadM) leadEnd = segmentStart;
              break;
            }
            segmentStart += segment.length;
          }
        }
        return {{ref.pose, ref.velocity, chain.curvatureAt(ref.s)}, sliceChain(chain, ref.s, leadEnd), ref.s,
                chain.length() - ref.s};
      }
    }
  }
  const bool standing = std::abs(state.velocity) < kStandingSpeed && std::abs(state.rotational) < kStandingTurnRate;
  if (standing) return {{state.pose, 0.0, 0.0, true}, {}, 0.0, 0.0};
  // Moving off the reference (or without a chain): where the robot's arc takes it meanwhile.
  const double speed = std::max(0.0, state.velocity);
  const double dt = config_.planningLatencyS;
  const double heading = state.pose.theta + state.rotational * dt / 2.0;
  const Pose2D ahead{state.pose.x + speed * dt * std::cos(heading), state.pose.y + speed * dt * std::sin(heading),
                     normalizeAngle(state.pose.theta + state.rotational * dt)};
  return {{ahead, speed, speed > kStandingSpeed ? state.rotational / speed : 0.0, false}, {}, 0.0, 0.0};
}

double CollisionAvoidance::margin() const {
  return escaping_ ? std::min(config_.safetyMarginM, config_.escapeMarginM) : config_.safetyMarginM;
}

SweptCheckOptions CollisionAvoidance::checkOptions() const {
  return {margin(), config_.sampleStepM, config_.comfortClearanceM};
}

bool CollisionAvoidance::currentStillFree(const RobotState& state, const ObstacleClearance& clearance) const {
  if (!current_ || !currentTimed_) return false;
  const double t = std::max(0.0, state.stamp - current_->startTime);
  const double s = currentTimed_->stateAt(t).s;
  const TrajectoryChain rest = sliceChain(current_->chain, s, current_->chain.length());
  return rest.empty() || checkSwept(clearance, rest, footprint_, checkOptions()).clear;
}

void CollisionAvoidance::dropPassedTargets(const Pose2D& from) {
  // From the first on: a target is passed when the robot came within targetPassedM of it, or is
  // beside the stretch to the next one (past the target along it, within twice that of it: it went
  // around something standing on the target). A target the robot only drove by at a distance (the
  // door beside the hallway it overshot) stays: the robot turns back to it.
  std::size_t passed = 0;
  while (passed + 1 < targets_.size()) {
    const Pose2D& a = targets_[passed];
    const OnStretch next = onStretch(a, targets_[passed + 1], from);
    if (distance(a, from) >= config_.targetPassedM && !(next.u > 0.0 && next.distance < 2.0 * config_.targetPassedM)) break;
    ++passed;
  }
  targets_.erase(targets_.begin(), targets_.begin() + static_cast<std::ptrdiff_t>(passed));
}

double CollisionAvoidance::pathLeftFrom(const TrajectoryChain& chain) const {
  // The nearest point of the targets' polyline to the chain's end, off it at kOffPathWeight (a
  // straight line to a later target would cut through the walls the path goes around), then along
  // it to the goal. Only the part of the polyline the chain can have reached counts: the segments
  // that begin within the chain's length along the path from its start (it cannot get farther); a
  // nearer point farther along lies behind a wall the path goes around (the hallway beyond a
  // room's door, seen through the room's wall).
  const std::size_t n = targets_.size();
  std::vector<double> toGoal(n, 0.0);  // path length from target j to the goal
  for (std::size_t j = n - 1; j-- > 0;) toGoal[j] = toGoal[j + 1] + distance(targets_[j], targets_[j + 1]);
  const Pose2D end = chain.end();
  const double reach = chain.length() - distance(chain.start(), targets_.front());
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < n && (j == 0 || toGoal[0] - toGoal[j] <= reach); ++j) {
    const Pose2D& a = targets_[j];
    double off = distance(end, a), along = toGoal[j];
    if (j + 1 < n) {
      const OnStretch on = onStretch(a, targets_[j + 1], end);
      off = on.distance;
      along = toGoal[j + 1] + (1.0 - std::clamp(on.u, 0.0, 1.0)) * distance(a, targets_[j + 1]);
    }
    best = std::min(best, kOffPathWeight * off + along);
  }
  return best;
}

std::vector<Candidate> CollisionAvoidance::candidatesFrom(const PlanStart& start) const {
  // Chains from a turning start first straighten out along a clothoid as sharp as the
  // rotational acceleration allows at the start speed (no jump in the turn rate), or follow the
  // current chain's turn to its end (the lead).
  const auto after = [&](const TrajectoryChain& prefix, std::vector<Candidate>& out) {
    const ChainStart from{prefix.end(), start.state.speed, 0.0, false};
    for (Candidate& candidate : candidateChains(from, targets_, config_.candidates)) {
      TrajectoryChain joined = prefix;
      for (const TrajectorySegment& segment : candidate.chain.segments()) joined.append(segment);
      out.push_back({candidate.kind, std::move(joined)});
    }
  };
  const double kappa = start.state.curvature;
  if (std::abs(kappa) <= kStraight) return candidateChains(start.state, targets_, config_.candidates);
  std::vector<Candidate> all;
  // (Within a turn on the spot only the lead: it ends the turn.)
  if (std::abs(kappa) < kPivotCurvature) {
    const double speed = std::max(start.state.speed, kStandingSpeed);
    const double sharpness = std::min(config_.candidates.turnMaxSharpnessPerM2,
                                      kUnwindShare * limits_.maxRotationalAcceleration / (speed * speed));
    after(TrajectoryChain({TrajectorySegment{start.state.pose, std::abs(kappa) / sharpness, kappa,
                                             kappa > 0.0 ? -sharpness : sharpness}}),
          all);
  }
  if (!start.lead.empty()) after(start.lead, all);
  return all;
}

double CollisionAvoidance::movingGap(const TrajectoryChain& chain, const ObstacleClearance& moving) const {
  // The smallest footprint clearance to a moving obstacle plus the arc length where it occurs: a
  // person straight ahead at d counts d, one beside the chain further on counts its distance
  // along the chain on top. An empty chain (what is left of one the reference has all but
  // passed) has nothing ahead.
  if (chain.empty()) return std::numeric_limits<double>::infinity();
  double best = kMovingReachM;
  const double length = chain.length();
  for (double s = 0.0; s <= length && s < best; s += config_.sampleStepM)
    best = std::min(best, s + std::max(0.0, moving.footprintClearance(footprint_, chain.poseAt(s), best - s)));
  return best < kMovingReachM ? best : std::numeric_limits<double>::infinity();
}

double CollisionAvoidance::peopleCap(const TrajectoryChain& chain, const ObstacleClearance& moving, bool patient) const {
  return patient ? oncomingStopSpeed(movingGap(chain, moving)) : std::numeric_limits<double>::infinity();
}

std::optional<CollisionAvoidance::Scored> CollisionAvoidance::bestCandidate(const PlanStart& start,
                                                                            const ObstacleClearance& clearance,
                                                                            const ObstacleClearance& moving,
                                                                            bool patient) const {
  std::optional<Scored> best;
  for (Candidate& candidate : candidatesFrom(start)) {
    const SweptCheck check = checkSwept(clearance, candidate.chain, footprint_, checkOptions());
    // The chain must end where the robot can turn on the spot (it cannot back out): cut it back
    // from where it stops being free, or from its end, to such a pose.
    const double end = check.clear ? candidate.chain.length() : check.freeLength;
    const double keep = turnableUntil(candidate.chain, end, clearance);
    if (keep < kMinChainM) continue;
    double cost = 0.0;
    if (keep < candidate.chain.length() - 1e-9) {
      candidate.chain = sliceChain(candidate.chain, 0.0, keep);
      cost += kCutPenaltyS;
    }
    // Manoeuvres (deviations and fans) drive no faster than their tight turns allow, so that the
    // robot can still turn tightly from anywhere on them (into the door it would otherwise pass);
    // chains passing moving obstacles no faster than lets the robot stop before they could reach
    // it (a person walking towards the robot). A standing obstacle that cuts a chain short only
    // ends it (a cap for it too kept the robot crawling through every door).
    const bool manoeuvre = candidate.kind == Candidate::Kind::Deviation || candidate.kind == Candidate::Kind::Fan;
    const double cruise = std::min(manoeuvre ? manoeuvreSpeed() : std::numeric_limits<double>::infinity(),
                                   peopleCap(candidate.chain, moving, patient));
    std::optional<TimedTrajectory> timed;
    try {
      timed.emplace(candidate.chain, limits_, start.state.speed, 0.0, cruise);
    } catch (const InvalidArgumentError&) {
      continue;  // cannot stop within it from the start speed
    }
    cost += timed->duration() + config_.progressWeightSPerM * pathLeftFrom(candidate.chain) +
            config_.clearanceWeightSPerM *
                std::max(0.0, config_.safetyMarginM + config_.comfortClearanceM - check.minClearance);
    if (!best || cost < best->cost) best = Scored{std::move(candidate), std::move(*timed), cost};
  }
  return best;
}

double CollisionAvoidance::turnableUntil(const TrajectoryChain& chain, double end,
                                         const ObstacleClearance& clearance) const {
  const Footprint turning = Footprint::disk(footprint_.circumradius());
  const double needed = margin() + kTurnSlackM;
  for (double s = end; s >= kMinChainM; s -= kTurnableStepM)
    if (clearance.footprintClearance(turning, chain.poseAt(s), needed) >= needed) return s;
  return 0.0;
}

double CollisionAvoidance::manoeuvreSpeed() const {
  return std::sqrt(limits_.maxRotationalAcceleration / config_.candidates.manoeuvreSharpnessPerM2);
}

double CollisionAvoidance::oncomingStopSpeed(double gap) const {
  // What both cover while the robot reacts (L) and brakes: (u + v) L + v^2 / (2 a) + u v / a = gap.
  if (!std::isfinite(gap)) return std::numeric_limits<double>::infinity();
  const double a = limits_.maxDeceleration, u = config_.oncomingSpeedMps, L = kReactionS;
  const double b = u / a + L, c = u * L - gap;
  return std::max(kCrawlSpeed, a * (-b + std::sqrt(std::max(0.0, b * b - 2.0 * c / a))));
}

double CollisionAvoidance::brakingDistance(double speed) const {
  return speed * speed / (2.0 * limits_.maxDeceleration);
}

std::optional<TimedTrajectory> CollisionAvoidance::brakingChain(const PlanStart& start) const {
  const ChainStart& from = start.state;
  if (from.speed < kStandingSpeed) return std::nullopt;
  const double shortest = brakingDistance(from.speed) + 0.02;
  // Along the current chain where it goes on far enough (it was free when planned), else on the
  // arc the robot is on; turns brake slower (rotational acceleration), so longer if need be.
  for (const double stretch : {1.1, 1.5, 2.0, 3.0, 5.0}) {
    const double length = stretch * shortest;
    TrajectoryChain chain = start.leftOnCurrent >= length
                                ? sliceChain(current_->chain, start.onCurrent, start.onCurrent + length)
                                : TrajectoryChain({TrajectorySegment{from.pose, length, from.curvature, 0.0}});
    try {
      return TimedTrajectory(std::move(chain), limits_, from.speed, 0.0);
    } catch (const InvalidArgumentError&) {
      // too short to stop within: longer
    }
  }
  return std::nullopt;
}

AvoidanceDecision CollisionAvoidance::send(const RobotState& state, TimedTrajectory timed, AvoidanceAction action,
                                           std::string reason) {
  DriveChain drive{nextId_++, timed.chain(), timed.startSpeed(), state.stamp + config_.planningLatencyS,
                   std::isfinite(timed.cruiseSpeed()) ? timed.cruiseSpeed() : 0.0};
  currentTimed_ = std::move(timed);
  current_ = drive;
  lastPlan_ = state.stamp;
  targetsChanged_ = false;
  braking_ = false;
  escaping_ = false;  // one chain with the escape margin, then the full margin again
  return {action, std::move(drive), std::move(reason)};
}

AvoidanceDecision CollisionAvoidance::wait(const RobotState& state, const PlanStart& start, bool currentFree) {
  if (!waitingSince_) waitingSince_ = state.stamp;
  if (state.stamp - *waitingSince_ >= config_.blockedWaitS && std::abs(state.velocity) < kStandingSpeed) {
    waitingSince_ = state.stamp;
    escaping_ = true;
    return {AvoidanceAction::Blocked, std::nullopt, "no free chain for " + std::to_string(config_.blockedWaitS) + " s"};
  }
  if (!currentFree && !braking_) {
    if (auto braking = brakingChain(start)) {
      AvoidanceDecision decision = send(state, std::move(*braking), AvoidanceAction::Wait, "no free chain: braking");
      braking_ = true;
      return decision;
    }
    // Too slow for a braking chain (the drive creeping to settle at the chain's end, where
    // something now stands) or none could be timed: the drive stops at once.
    braking_ = true;
    current_.reset();
    currentTimed_.reset();
    return {AvoidanceAction::Wait, std::nullopt, "no free chain: stop now", true};
  }
  return {AvoidanceAction::Wait, std::nullopt, "no free chain"};
}

AvoidanceDecision CollisionAvoidance::update(const RobotState& state, std::span<const ObstacleGrid> grids) {
  if (targets_.empty()) return {AvoidanceAction::Keep, std::nullopt, "no targets"};
  const Pose2D goal = targets_.back();
  if (distance(state.pose, goal) <= config_.goalToleranceM && std::abs(state.velocity) < kArrivalSpeed) {
    targets_.clear();
    current_.reset();
    currentTimed_.reset();
    return {AvoidanceAction::GoalReached, std::nullopt, "at the goal"};
  }
  const ObstacleClearance clearance(fuseObstacles(grids));
  const ObstacleClearance moving(fuseMovingObstacles(grids));
  const bool patient = !heldSince_ || state.stamp - *heldSince_ < kPeoplePatienceS;
  const PlanStart start = planStart(state);
  dropPassedTargets(start.state.pose);
  const bool currentFree = currentStillFree(state, clearance);
  const bool endsAtGoal = current_ && distance(current_->chain.end(), goal) <= config_.goalToleranceM;
  const bool running = start.leftOnCurrent > 0.0;
  const bool refresh = !endsAtGoal && start.leftOnCurrent < config_.refreshDistanceM &&
                       state.stamp - lastPlan_ >= kRefreshPeriodS;
  const bool newTargets = targetsChanged_ && (!running || state.stamp - lastPlan_ >= config_.replanPeriodS);
  // People near the chain ahead: the robot must be slow enough to stop before they could reach it.
  const bool tooFast =
      running && start.state.speed > kSpeedSlackMps + peopleCap(sliceChain(current_->chain, start.onCurrent, current_->chain.length()),
                                                                moving, patient);
  // Out of patience: the crawl the people set is replaced.
  const bool crawling = !patient && running && current_->cruiseSpeed > 0.0 && current_->cruiseSpeed < kHeldSpeedMps;
  if (currentFree && running && !refresh && !newTargets && !tooFast && !crawling)
    return {AvoidanceAction::Keep, std::nullopt, "chain free"};
  // Arriving: the drive settles at the goal; a robot that stands short of it long after the chain's
  // time (something it cannot see stopped it, and the drive gave up) gets a new chain.
  const bool arriving = current_ && currentTimed_ &&
                        state.stamp - current_->startTime < currentTimed_->duration() + kArrivalGraceS;
  if (currentFree && endsAtGoal && !newTargets && arriving) return {AvoidanceAction::Keep, std::nullopt, "arriving"};

  auto best = bestCandidate(start, clearance, moving, patient);
  if (!best) {
    if (currentFree && running) return {AvoidanceAction::Keep, std::nullopt, "no better chain"};
    return wait(state, start, currentFree && running);
  }
  waitingSince_.reset();
  if (peopleCap(best->candidate.chain, moving, true) >= kHeldSpeedMps) heldSince_.reset();
  else if (!heldSince_) heldSince_ = state.stamp;
  return send(state, std::move(best->timed), AvoidanceAction::Drive,
              !currentFree ? "obstacle on the chain"
              : tooFast    ? "people near the chain"
              : crawling   ? "people do not pass"
                           : "replanned");
}

}  // namespace rgnav
