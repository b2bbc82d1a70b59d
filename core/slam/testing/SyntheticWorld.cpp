// Wall layouts and the ray caster of the synthetic test worlds.
#include "core/slam/testing/SyntheticWorld.h"

#include <cmath>
#include <limits>

namespace rgnav::testing {

namespace {

void addRectangle(World& world, double x0, double y0, double x1, double y1) {
  world.push_back({{x0, y0}, {x1, y0}});
  world.push_back({{x1, y0}, {x1, y1}});
  world.push_back({{x1, y1}, {x0, y1}});
  world.push_back({{x0, y1}, {x0, y0}});
}

// Distance along the ray from `origin` in direction `d` to the wall, or infinity.
double hit(const Eigen::Vector2d& origin, const Eigen::Vector2d& d, const Wall& wall) {
  const Eigen::Vector2d e = wall.b - wall.a;
  const double denominator = d.x() * e.y() - d.y() * e.x();
  if (std::abs(denominator) < 1e-12) return std::numeric_limits<double>::infinity();
  const Eigen::Vector2d w = wall.a - origin;
  const double t = (w.x() * e.y() - w.y() * e.x()) / denominator;
  const double u = (w.x() * d.y() - w.y() * d.x()) / denominator;
  return t > 0.0 && u >= 0.0 && u <= 1.0 ? t : std::numeric_limits<double>::infinity();
}

}  // namespace

World boxWorld() {
  World world;
  addRectangle(world, -5.0, -4.0, 5.0, 4.0);
  addRectangle(world, 1.5, 1.0, 3.0, 2.2);
  addRectangle(world, -3.5, -2.5, -2.0, -1.8);
  addRectangle(world, -1.0, 2.5, -0.7, 2.8);
  return world;
}

World corridorWorld() {
  World world;
  for (int side : {-1, 1}) {
    double x = -15.0;
    // Recesses 1 m wide and 0.4 m deep, at irregular spacing so that no shift repeats the view.
    for (double door : {-11.0, -6.5, -3.0, 2.0, 4.5, 9.0, 12.5}) {
      const double d = door + 0.7 * side;
      world.push_back({{x, side * 1.0}, {d, side * 1.0}});
      world.push_back({{d, side * 1.0}, {d, side * 1.4}});
      world.push_back({{d, side * 1.4}, {d + 1.0, side * 1.4}});
      world.push_back({{d + 1.0, side * 1.4}, {d + 1.0, side * 1.0}});
      x = d + 1.0;
    }
    world.push_back({{x, side * 1.0}, {15.0, side * 1.0}});
  }
  world.push_back({{-15.0, -1.0}, {-15.0, 1.0}});
  world.push_back({{15.0, -1.0}, {15.0, 1.0}});
  return world;
}

World loopWorld() {
  World world;
  addRectangle(world, -8.0, -5.0, 8.0, 5.0);    // the block
  addRectangle(world, -11.0, -8.0, 11.0, 8.0);  // the outer wall
  // Landmarks along the way so that the corridor is not self-similar.
  addRectangle(world, -4.0, 5.0, -3.6, 5.5);
  addRectangle(world, 2.0, -8.0, 2.8, -7.5);
  addRectangle(world, 8.0, 1.0, 8.5, 1.6);
  addRectangle(world, -11.0, -2.0, -10.4, -1.0);
  addRectangle(world, 6.0, 7.4, 6.3, 8.0);
  addRectangle(world, -6.0, -8.0, -5.5, -7.6);
  return world;
}

std::vector<Pose2D> loopTrajectory(double step, int laps) {
  const Eigen::Vector2d corners[4] = {{9.5, -6.5}, {9.5, 6.5}, {-9.5, 6.5}, {-9.5, -6.5}};
  std::vector<Pose2D> poses;
  for (int lap = 0; lap < laps; ++lap)
    for (int side = 0; side < 4; ++side) {
      const Eigen::Vector2d a = corners[side], b = corners[(side + 1) % 4];
      const double heading = std::atan2(b.y() - a.y(), b.x() - a.x());
      for (double turn = -M_PI / 2; turn < 0.0; turn += M_PI / 8)  // turning on the spot at the corner
        poses.push_back({a.x(), a.y(), normalizeAngle(heading + turn)});
      const double length = (b - a).norm();
      for (double s = 0.0; s < length - 1e-9; s += step) {
        const Eigen::Vector2d p = a + (b - a) * (s / length);
        poses.push_back({p.x(), p.y(), heading});
      }
    }
  return poses;
}

std::vector<Pose2D> driftingOdometry(const std::vector<Pose2D>& truth, double scaleError, double headingErrorPerMetre) {
  std::vector<Pose2D> odometry;
  if (truth.empty()) return odometry;
  odometry.push_back(truth[0]);
  for (std::size_t i = 1; i < truth.size(); ++i) {
    const Pose2D step = between(truth[i - 1], truth[i]);
    const double length = std::hypot(step.x, step.y);
    odometry.push_back(compose(odometry.back(), {step.x * (1.0 + scaleError), step.y * (1.0 + scaleError),
                                                 step.theta + headingErrorPerMetre * length}));
  }
  return odometry;
}

SyntheticRun ringRun() {
  SyntheticRun run;
  run.truth = loopTrajectory(0.1, 2);
  const auto odometry = driftingOdometry(run.truth, 0.02, 1.5 * M_PI / 180.0);
  const World world = loopWorld();
  for (std::size_t i = 0; i < run.truth.size(); ++i) {
    run.scans.push_back(simulateScan(world, run.truth[i], i + 1));
    run.scans.back().odometry = odometry[i];
  }
  return run;
}

LaserScan simulateScan(const World& world, const Pose2D& pose, DataId id, double maxRange) {
  LaserScan scan;
  scan.id = id;
  scan.stamp = static_cast<double>(id);
  scan.odometry = scan.sensorPose = pose;
  scan.startAngle = -M_PI / 2.0;
  scan.angleIncrement = M_PI / 180.0;
  scan.maxRange = maxRange;
  const Eigen::Vector2d origin(pose.x, pose.y);
  for (int i = 0; i < 180; ++i) {
    const double a = pose.theta + scan.startAngle + i * scan.angleIncrement;
    const Eigen::Vector2d d(std::cos(a), std::sin(a));
    double range = std::numeric_limits<double>::infinity();
    for (const Wall& wall : world) range = std::min(range, hit(origin, d, wall));
    scan.ranges.push_back(range < maxRange ? static_cast<float>(range) : LaserScan::kNoReturn);
  }
  return scan;
}

}  // namespace rgnav::testing
