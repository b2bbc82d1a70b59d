// TimedTrajectory: the velocity profile of a chain. Each segment is cut into pieces of at most
// 1 cm, at least four (every joint is a grid point, so no segment is skipped); the acceleration
// is constant on a piece. A forward pass raises the speed as fast as the acceleration and the
// rotational acceleration allow, a backward pass lowers it so that the robot can always brake to
// the next caps and to the end speed. The caps at a grid point are the top speed, the top
// rotational speed, the lateral acceleration and the rotational acceleration at constant speed
// (sharpness v^2) over both pieces that touch it, and at a curvature jump the speed whose
// rotational step the rotational acceleration makes up in one 50 ms control period. The
// rotational acceleration sharpness v^2 + kappa a is checked at both ends of a piece (it is
// linear in kappa and in v^2 there).
#include "core/nav/motion/TimedTrajectory.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/Errors.h"

namespace rgnav {

namespace {

constexpr double kGridStep = 0.01;  // m
constexpr int kMinPieces = 4;       // per segment: a chain shorter than a step still gets a ramp
constexpr double kJumpSeconds = 0.05;  // s: one period of the Low-Level Drive
constexpr double kInf = std::numeric_limits<double>::infinity();

// A piece of the grid: its length and the curvature at its ends, its sharpness.
struct Piece {
  double ds;
  double kappaA;
  double kappaB;
  double sharpness;
};

// Tightens [lo, hi] to the accelerations a with |base + slope * a| <= bound.
void limitAcceleration(double base, double slope, double bound, double& lo, double& hi) {
  if (std::abs(slope) < 1e-12) return;  // the caps keep |base| <= bound
  const double a1 = (-bound - base) / slope, a2 = (bound - base) / slope;
  lo = std::max(lo, std::min(a1, a2));
  hi = std::min(hi, std::max(a1, a2));
}

// The accelerations allowed on a piece starting (forward) or ending (backward) at squared speed
// w: the (de)acceleration limits and |sharpness v^2 + kappa a| <= maxRotationalAcceleration at
// both ends of the piece, where v^2 = w + 2 a ds (forward) or w - 2 a ds (backward).
void allowedAccelerations(const Piece& p, const MotionLimits& m, double w, bool forward, double& lo,
                          double& hi) {
  lo = -m.maxDeceleration;
  hi = m.maxAcceleration;
  const double far = forward ? 2.0 * p.ds : -2.0 * p.ds;
  for (double kappa : {p.kappaA, p.kappaB}) {
    limitAcceleration(p.sharpness * w, kappa, m.maxRotationalAcceleration, lo, hi);
    limitAcceleration(p.sharpness * w, kappa + p.sharpness * far, m.maxRotationalAcceleration, lo, hi);
  }
}

// The highest squared speed on a piece at constant speed.
double pieceCap(const Piece& p, const MotionLimits& m) {
  const double kappa = std::max(std::abs(p.kappaA), std::abs(p.kappaB));
  double cap = m.maxVelocity * m.maxVelocity;
  if (kappa > 0.0) {
    const double rotational = m.maxRotationalVelocity / kappa;
    cap = std::min({cap, rotational * rotational, m.maxLateralAcceleration / kappa});
  }
  if (p.sharpness != 0.0) cap = std::min(cap, m.maxRotationalAcceleration / std::abs(p.sharpness));
  return cap;
}

// The grid interval [grid[j], grid[j + 1]] holding value (clamped to the grid).
std::size_t intervalAt(const std::vector<double>& grid, double value) {
  const auto after = std::upper_bound(grid.begin(), grid.end(), value);
  if (after == grid.begin()) return 0;
  if (after == grid.end()) return grid.size() - 2;
  return static_cast<std::size_t>(after - grid.begin()) - 1;
}

}  // namespace

TimedTrajectory::TimedTrajectory(TrajectoryChain chain, const MotionLimits& limits, double startSpeed,
                                 double endSpeed, double cruiseSpeed)
    : chain_(std::move(chain)), cruiseSpeed_(cruiseSpeed) {
  validate(limits);
  if (chain_.empty()) throw InvalidArgumentError("timed trajectory: empty chain");
  if (!(std::isfinite(startSpeed) && startSpeed >= 0.0 && std::isfinite(endSpeed) && endSpeed >= 0.0)) {
    throw InvalidArgumentError("timed trajectory: start and end speeds must be finite and not negative");
  }
  std::vector<Piece> pieces;
  s_.push_back(0.0);
  for (const TrajectorySegment& segment : chain_.segments()) {
    const int n = std::max(kMinPieces, static_cast<int>(std::ceil(segment.length / kGridStep)));
    const double ds = segment.length / n;
    const double s0 = s_.back();
    for (int k = 0; k < n; ++k) {
      pieces.push_back({ds, segment.curvatureAt(k * ds), segment.curvatureAt((k + 1) * ds), segment.sharpness});
      s_.push_back(s0 + (k + 1) * ds);
    }
  }
  const std::size_t n = pieces.size();
  std::vector<double> cap(n + 1, kInf);  // squared speeds
  for (std::size_t j = 0; j < n; ++j) {
    const double c = pieceCap(pieces[j], limits);
    cap[j] = std::min(cap[j], c);
    cap[j + 1] = std::min(cap[j + 1], c);
    // A curvature jump at a joint steps the rotational speed by v * jump: slow enough that the
    // rotational acceleration makes the step up within one control period.
    const double jump = j > 0 ? std::abs(pieces[j].kappaA - pieces[j - 1].kappaB) : 0.0;
    if (jump > 1e-9) {
      const double v = limits.maxRotationalAcceleration * kJumpSeconds / jump;
      cap[j] = std::min(cap[j], v * v);
    }
  }
  const double w0 = startSpeed * startSpeed, wEnd = endSpeed * endSpeed;
  if (!(cruiseSpeed > 0.0)) throw InvalidArgumentError("timed trajectory: the cruise speed must be positive");
  if (std::isfinite(cruiseSpeed))
    for (std::size_t j = 0; j <= n; ++j)
      cap[j] = std::min(cap[j], std::max(cruiseSpeed * cruiseSpeed, w0 - 2.0 * limits.maxDeceleration * s_[j]));
  if (w0 > cap.front() * (1.0 + 1e-9)) {
    throw InvalidArgumentError("timed trajectory: start speed " + std::to_string(startSpeed) +
                               " m/s is above what the limits allow at the chain's start (" +
                               std::to_string(std::sqrt(cap.front())) + " m/s)");
  }
  if (wEnd > cap.back() * (1.0 + 1e-9)) {
    throw InvalidArgumentError("timed trajectory: end speed " + std::to_string(endSpeed) +
                               " m/s is above what the limits allow at the chain's end");
  }
  std::vector<double> w(n + 1);
  w[0] = w0;
  for (std::size_t j = 0; j < n; ++j) {
    double lo = 0.0, hi = 0.0;
    allowedAccelerations(pieces[j], limits, w[j], true, lo, hi);
    w[j + 1] = std::clamp(w[j] + 2.0 * hi * pieces[j].ds, 0.0, cap[j + 1]);
  }
  w[n] = std::min(w[n], wEnd);
  for (std::size_t j = n; j-- > 0;) {
    double lo = 0.0, hi = 0.0;
    allowedAccelerations(pieces[j], limits, w[j + 1], false, lo, hi);
    w[j] = std::min(w[j], w[j + 1] - 2.0 * std::min(lo, 0.0) * pieces[j].ds);
  }
  if (w[0] < w0 * (1.0 - 1e-9) - 1e-12) {
    throw InvalidArgumentError("timed trajectory: the chain (" + std::to_string(chain_.length()) +
                               " m) is too short to slow from " + std::to_string(startSpeed) + " to " +
                               std::to_string(endSpeed) + " m/s within the limits");
  }
  v_.resize(n + 1);
  t_.assign(n + 1, 0.0);
  for (std::size_t j = 0; j <= n; ++j) v_[j] = std::sqrt(std::max(w[j], 0.0));
  for (std::size_t j = 0; j < n; ++j) {
    const double sum = v_[j] + v_[j + 1];
    if (sum <= 0.0) throw InvalidArgumentError("timed trajectory: the limits allow no motion on the chain");
    t_[j + 1] = t_[j] + 2.0 * pieces[j].ds / sum;
  }
}

double TimedTrajectory::duration() const { return t_.empty() ? 0.0 : t_.back(); }
double TimedTrajectory::startSpeed() const { return v_.empty() ? 0.0 : v_.front(); }
double TimedTrajectory::endSpeed() const { return v_.empty() ? 0.0 : v_.back(); }

ReferenceState TimedTrajectory::stateAt(double t) const {
  if (t_.empty()) throw InvalidArgumentError("timed trajectory: no chain");
  t = std::clamp(t, 0.0, duration());
  const std::size_t j = intervalAt(t_, t);
  const double ds = s_[j + 1] - s_[j];
  const double a = (v_[j + 1] * v_[j + 1] - v_[j] * v_[j]) / (2.0 * ds);
  const double tau = std::min(t - t_[j], t_[j + 1] - t_[j]);
  ReferenceState state;
  state.velocity = std::max(0.0, v_[j] + a * tau);
  state.s = std::min(s_[j] + v_[j] * tau + 0.5 * a * tau * tau, s_[j + 1]);
  state.pose = chain_.poseAt(state.s);
  state.rotational = state.velocity * chain_.curvatureAt(state.s);
  state.acceleration = a;
  return state;
}

double TimedTrajectory::timeAt(double s) const {
  if (t_.empty()) throw InvalidArgumentError("timed trajectory: no chain");
  s = std::clamp(s, 0.0, s_.back());
  const std::size_t j = intervalAt(s_, s);
  const double v = speedAt(s);
  const double sum = v_[j] + v;
  return sum > 0.0 ? t_[j] + 2.0 * (s - s_[j]) / sum : t_[j];
}

double TimedTrajectory::speedAt(double s) const {
  if (t_.empty()) throw InvalidArgumentError("timed trajectory: no chain");
  s = std::clamp(s, 0.0, s_.back());
  const std::size_t j = intervalAt(s_, s);
  const double ds = s_[j + 1] - s_[j];
  const double w = v_[j] * v_[j] + (v_[j + 1] * v_[j + 1] - v_[j] * v_[j]) * (s - s_[j]) / ds;
  return std::sqrt(std::max(w, 0.0));
}

}  // namespace rgnav
