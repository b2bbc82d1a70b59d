// The robot in one process; see InProcessRobot.h.
#include "tests/eval/exploration/InProcessRobot.h"

#include <cmath>

#include "core/config/ShippedConfig.h"
#include "core/nav/avoidance/CollisionAvoidanceConfigYaml.h"
#include "core/nav/motion/LowLevelDriveConfigYaml.h"
#include "core/nav/planning/KernelPlanningMap.h"
#include "core/nav/planning/RoutePlannerConfigYaml.h"
#include "core/sim/SimulationConfigYaml.h"
#include "servers/collisionavoidance/MapFrame.h"

namespace rgnav {

RobotSetup shippedRobotSetup() {
  RobotSetup setup;
  setup.simulation = loadSimulationConfig(shippedConfigFile("sim/default.yaml"));
  setup.pipeline = shippedPipelineConfig();
  setup.planner = loadRoutePlannerConfig(shippedConfigFile("modules/pathplanning.yaml"));
  setup.avoidance = loadCollisionAvoidanceConfig(shippedConfigFile("modules/collisionavoidance.yaml"));
  setup.avoidance.obstacleMap.laserForwardOffsetM = setup.simulation.laser.forwardOffset;
  setup.drive = loadLowLevelDriveConfig(shippedConfigFile("modules/lowleveldrive.yaml"));
  setup.drive.periodSeconds = setup.simulation.stepSeconds;
  return setup;
}

InProcessRobot::InProcessRobot(const OccupancyGrid& world, const RobotSetup& setup, const Pose2D& start,
                               std::optional<HmmClassifier> classifier)
    : setup_(setup),
      sim_(world, setup.simulation, start),
      pipeline_(setup.pipeline, std::move(classifier)),
      obstacles_(setup.avoidance.obstacleMap),
      drive_(setup.avoidance, setup.simulation.robot.footprint, referenceLimits(setup.drive)),
      lowLevel_(setup.drive),
      planner_(setup.planner),
      lastTrue_(start),
      firstTrue_(start) {}

SimulationStep InProcessRobot::step() {
  SimulationStep step = sim_.step();
  pathM_ += std::hypot(step.truePose.x - lastTrue_.x, step.truePose.y - lastTrue_.y);
  lastTrue_ = step.truePose;
  if (step.scan) {
    LaserScan scan = *step.scan;
    scan.sensorPose = scan.odometry;
    if (scan.id == 1) firstTrue_ = step.truePose;
    pipeline_.addScan(scan);
    obstacles_.add(scan);
    mapFromOdometry_ = mapFromOdometry(pipeline_.correctedPose(scan.id), scan.odometry);
    if (sim_.time() - mapAt_ >= setup_.mapPeriodS) refreshMap();
    const RobotState state{step.odometry.stamp, step.odometry.pose, step.odometry.translationalVelocity,
                           step.odometry.rotationalVelocity};
    const AvoidanceDecision decision = drive_.update(state, obstacles_.grid(), mapFromOdometry_, planner_);
    if (decision.chain) pending_ = decision.chain;
    if (decision.stopNow) {
      pending_.reset();
      lowLevel_.stop();
    }
  }
  // A chain reaches the drive at its start time, as from a module one planning latency away.
  if (pending_ && step.odometry.stamp >= pending_->startTime - 1e-9) {
    lowLevel_.setChain(*pending_);
    pending_.reset();
  }
  sim_.command(lowLevel_.tick(step.odometry, step.odometry.stamp));
  return step;
}

void InProcessRobot::refreshMap() {
  planner_.setMap(planningMapOf(pipeline_.kernel()));
  mapAt_ = sim_.time();
}

void InProcessRobot::driveTo(const PlanGoal& goal) { drive_.start(goal, planner_, pose(), mapFromOdometry_); }

Pose2D InProcessRobot::pose() const { return toMap(mapFromOdometry_, sim_.odometryPose()); }

Pose2D InProcessRobot::mapToWorld() const {
  if (pipeline_.counts().scans == 0) return {};
  return compose(firstTrue_, inverse(pipeline_.correctedPose(1)));
}

}  // namespace rgnav
