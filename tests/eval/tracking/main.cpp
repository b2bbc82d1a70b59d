// rgnav-eval-tracking: the trajectory-tracking evaluation of issue 27 ("rgctl eval tracking"):
// the Low-Level Drive follows the fixed suite of chains (TrackingSuite) driving the simulator's
// robot without odometry noise, in a 20 Hz loop on the wall clock with simulated time equal to
// wall time (--fast: simulated time only, no sleeping; the loop periods are then the nominal
// 50 ms and the summary says clock=simulated; a real-time loop asks for SCHED_FIFO and says
// clock=wall-fifo, or clock=wall-normal without the privilege). A line per chain, then
//   tracking: chains=… rms_lateral_m=… final_pos_err_m=… final_yaw_err_deg=… time_prediction_err=…
//             loop_period_p99_ms=…
// with the worst chain's RMS lateral error, the worst final errors, the largest relative
// difference between the predicted and the real time to drive a chain (start to standing at
// its end) and the 99th percentile of the loop's periods. The drive's limits are the simulated
// robot's (0.5 m/s^2, pi/2 rad/s, pi/2 rad/s^2); its reference keeps a 10 % margin on the
// accelerations (LowLevelDriveConfig::referenceMargin). --command-delay N hands the robot each
// command N ticks late and tells the drive, which then predicts over the commands in flight.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "core/common/Errors.h"
#include "core/sim/motion/DiffDriveRobot.h"
#include "tests/eval/tracking/LoopClock.h"
#include "tests/eval/tracking/TrackingRun.h"
#include "tests/eval/tracking/TrackingSuite.h"
#include "tests/support/Statistics.h"
#include "tools/common/CommandLine.h"

namespace po = boost::program_options;

int main(int argc, char** argv) {
  bool fast = false;
  std::size_t chains = 0;
  int delay = 0;
  po::options_description desc("rgnav-eval-tracking [--fast] [--chains N] [--command-delay N]");
  desc.add_options()
      ("help", "this text")
      ("fast", po::bool_switch(&fast), "simulated time only, no sleeping (loop periods are nominal)")
      ("chains", po::value(&chains)->default_value(0), "drive only the first N chains of the suite (0: all)")
      ("command-delay", po::value(&delay)->default_value(0), "the robot receives each command N ticks late");
  try {
    if (!rgnav::parseCommandLine(argc, argv, desc)) return 0;
    // The simulated robot's limits; the reference keeps the default 10 % margin on accelerations.
    rgnav::LowLevelDriveConfig config;
    const rgnav::DiffDriveConfig robot;
    config.limits.maxAcceleration = robot.maxTranslationalAcceleration;
    config.limits.maxDeceleration = robot.maxTranslationalAcceleration;
    config.limits.maxRotationalVelocity = robot.maxRotationalVelocity;
    config.limits.maxRotationalAcceleration = robot.maxRotationalAcceleration;
    config.limits.maxLateralAcceleration = 1.0;
    std::vector<rgnav::TrackingCase> suite = rgnav::trackingSuite();
    if (chains > 0 && chains < suite.size()) suite.resize(chains);
    rgnav::LoopClock clock(config.periodSeconds, !fast);
    std::uint64_t odometryId = 0;
    double rms = 0.0, position = 0.0, yaw = 0.0, timeError = 0.0;
    std::size_t unfinished = 0;
    for (const rgnav::TrackingCase& c : suite) {
      const rgnav::TrackingResult r = rgnav::runTracking(c, config, clock, odometryId, delay);
      const double relative = r.finished ? std::abs(r.realSeconds - r.predictedSeconds) / r.predictedSeconds : 1.0;
      std::printf("chain=%s v_max=%.1f length_m=%.2f predicted_s=%.2f real_s=%.2f time_err=%.4f rms_lateral_m=%.4f"
                  " max_lateral_m=%.4f final_pos_err_m=%.4f final_yaw_err_deg=%.3f finished=%d\n",
                  c.name.c_str(), c.maxVelocity, c.chain.length(), r.predictedSeconds, r.realSeconds, relative,
                  r.rmsLateral, r.maxLateral, r.finalPositionError, r.finalYawError * 180.0 / M_PI, r.finished ? 1 : 0);
      std::fflush(stdout);
      rms = std::max(rms, r.rmsLateral);
      position = std::max(position, r.finalPositionError);
      yaw = std::max(yaw, r.finalYawError * 180.0 / M_PI);
      timeError = std::max(timeError, relative);
      if (!r.finished) ++unfinished;
    }
    std::printf("tracking: chains=%zu rms_lateral_m=%.4f final_pos_err_m=%.4f final_yaw_err_deg=%.3f time_prediction_err=%.4f"
                " loop_period_p99_ms=%.1f unfinished=%zu clock=%s\n",
                suite.size(), rms, position, yaw, timeError, 1e3 * rgnav::testing::percentile(clock.periods(), 0.99),
                unfinished, clock.scheduling().c_str());
    return unfinished == 0 ? 0 : 1;
  } catch (const po::error& e) {
    std::cerr << "rgnav-eval-tracking: " << e.what() << "\n" << desc << std::endl;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-eval-tracking: " << e.what() << std::endl;
    return 1;
  }
}
