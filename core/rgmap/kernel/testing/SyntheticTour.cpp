// Synthetic inputs of the RG Mapping Kernel; see SyntheticTour.h.
#include "core/rgmap/kernel/testing/SyntheticTour.h"

#include <cmath>
#include <stdexcept>

#include "core/gateways/passages/SegmentCrossing.h"
#include "core/lines/ScanPoints.h"

namespace rgnav::testing {
namespace {

Eigen::Vector2d centre(const TourDoor& d) { return 0.5 * (d.left + d.right); }

Eigen::Vector2d normal(const TourDoor& d) {
  const Eigen::Vector2d along = (d.right - d.left).normalized();
  return {-along.y(), along.x()};
}

// +1 or -1: the side of the door's line `p` lies on.
double sideOf(const TourDoor& d, const Eigen::Vector2d& p) { return normal(d).dot(p - centre(d)) >= 0.0 ? 1.0 : -1.0; }

Eigen::Vector2d position(const Pose2D& p) { return {p.x, p.y}; }

}  // namespace

TourWorld hallwayWithTwoRooms() {
  TourWorld w;
  w.walls = {{{0, 0}, {12, 0}},      {{0, 0}, {0, 2}},     {{12, 0}, {12, 2}}, {{0, 2}, {3.55, 2}},
             {{4.45, 2}, {8.55, 2}}, {{9.45, 2}, {12, 2}}, {{2, 2}, {2, 6}},   {{6, 2}, {6, 6}},
             {{2, 6}, {6, 6}},       {{7, 2}, {7, 6}},     {{11, 2}, {11, 6}}, {{7, 6}, {11, 6}}};
  w.doors = {{DetectorGatewayId{11}, {3.55, 2}, {4.45, 2}, DoorReports::All}, {DetectorGatewayId{12}, {8.55, 2}, {9.45, 2}, DoorReports::All}};
  return w;
}

TourWorld hallwayWithTwoRoomsAndCabinet() {
  TourWorld w = hallwayWithTwoRooms();
  for (const Wall& side : boxWalls(cabinetCentre(), 0.0, 0.7, 1.2)) w.walls.push_back(side);
  return w;
}

TourWorld ringCorridor() {
  TourWorld w;
  w.walls = boxWalls({5, 5}, 0.0, 10, 10);
  for (const Wall& inner : boxWalls({5, 5}, 0.0, 6, 6)) w.walls.push_back(inner);
  w.walls.push_back({{5, 0}, {5, 0.55}});
  w.walls.push_back({{5, 1.45}, {5, 2}});
  w.doors = {{DetectorGatewayId{21}, {5, 0.55}, {5, 1.45}, DoorReports::All}};
  return w;
}

void feed(RgMappingKernel& kernel, const KernelInput& input) {
  if (input.scan)
    kernel.addScan(input.scan->scan, input.scan->corrected);
  else
    kernel.addGatewayEvent(*input.event, input.lastScanCorrected);
}

std::string feedChecked(RgMappingKernel& kernel, const std::vector<KernelInput>& inputs, std::size_t begin,
                        std::size_t end) {
  for (std::size_t i = begin; i < end; ++i) {
    feed(kernel, inputs[i]);
    std::string report;
    for (const std::string& v : kernel.checkConsistency())
      report += "after input " + std::to_string(i) + ": " + v + "\n";
    if (!report.empty()) return report;
  }
  return {};
}

RgMappingKernel mapped(const std::vector<KernelInput>& inputs, std::size_t end) {
  RgMappingKernel kernel;
  const std::string report = feedChecked(kernel, inputs, 0, end);
  if (!report.empty()) throw std::logic_error(report);
  return kernel;
}

SyntheticTour twoRoomTour(TourWorld world) {
  SyntheticTour tour(std::move(world), kTourDrift);
  tour.driveThrough({{1, 0.9},
                     {4, 0.9},
                     {4, 3.5},
                     {3, 4.5},
                     {5, 4.5},
                     {4, 3.5},
                     {4, 0.9},
                     {9, 0.9},
                     {9, 3.5},
                     {8, 4.5},
                     {10, 4.5},
                     {9, 3.5},
                     {9, 0.9},
                     {4, 0.9},
                     {4, 4},
                     {4, 0.9},
                     {1, 0.9}});
  return tour;
}

SyntheticTour ringTour() {
  SyntheticTour tour(ringCorridor(), kTourDrift);
  tour.driveThrough({{1.1, 1}, {9, 1}, {9, 9}, {1, 9}, {1, 1}, {6.6, 1}});
  return tour;
}

SyntheticTour::SyntheticTour(TourWorld world, const Pose2D& drift, double stepM, double detectRangeM)
    : walls_(std::move(world.walls)), drift_(drift), stepM_(stepM), detectRangeM_(detectRangeM) {
  for (TourDoor& d : world.doors) doors_.push_back({d});
}

void SyntheticTour::setReports(DetectorGatewayId detectorId, DoorReports reports) {
  for (DoorState& d : doors_)
    if (d.door.detectorId == detectorId) d.door.reports = reports;
}

void SyntheticTour::redetect(DetectorGatewayId detectorId, DetectorGatewayId newId) {
  for (DoorState& d : doors_)
    if (d.door.detectorId == detectorId) d = DoorState{TourDoor{newId, d.door.left, d.door.right, d.door.reports}};
}

void SyntheticTour::driveThrough(const std::vector<Eigen::Vector2d>& waypoints) {
  for (const Eigen::Vector2d& to : waypoints) {
    if (!last_) {
      step({to.x(), to.y(), 0.0});
      continue;
    }
    const Eigen::Vector2d from = position(*last_);
    const double heading = std::atan2(to.y() - from.y(), to.x() - from.x());
    const int steps = static_cast<int>(std::ceil((to - from).norm() / stepM_));
    for (int i = 1; i <= steps; ++i) {
      const Eigen::Vector2d p = from + (to - from) * (double(i) / steps);
      step({p.x(), p.y(), heading});
    }
  }
}

GatewayRecord SyntheticTour::record(const DoorState& d, const Pose2D& pose) const {
  const Eigen::Vector2d c = centre(d.door);
  GatewayRecord r;
  r.id = d.door.detectorId;
  r.kind = GatewayKind::NarrowPassage;
  r.classes = {{kNarrowPassageClass, 1.0}};
  r.gatewayPoints = {transformPoint(drift_, d.door.left), transformPoint(drift_, d.door.right)};
  r.crossingPoints = {transformPoint(drift_, d.firstSide), transformPoint(drift_, 2.0 * c - d.firstSide)};
  r.widthM = (d.door.right - d.door.left).norm();
  r.firstScan = d.firstScan;
  r.lastScan = nextScan_ - 1;
  r.lastPose = compose(drift_, pose);
  r.support = 1;
  r.traversals = d.traversals;
  return r;
}

void SyntheticTour::emit(GatewayEventKind kind, const DoorState& d, const Pose2D& pose,
                         const TraversalReport& traversal) {
  inputs_.push_back({std::nullopt, GatewayEvent{nextEvent_++, kind, record(d, pose), traversal}, pose});
}

void SyntheticTour::step(const Pose2D& pose) {
  const DataId id = nextScan_++;
  LaserScan scan = syntheticScan(walls_, pose);
  scan.id = id;
  scan.stamp = 0.1 * double(id);
  scan.odometry = compose(drift_, pose);
  scan.sensorPose = scan.odometry;
  inputs_.push_back({StoredScan{scan, pose}, std::nullopt, {}});

  const Eigen::Vector2d here = position(pose);
  for (DoorState& d : doors_) {
    const TourDoor& door = d.door;
    const auto learn = [&](const Eigen::Vector2d& from) {
      d.known = true;
      d.firstSide = centre(door) + 0.5 * sideOf(door, from) * normal(door);
      d.firstScan = id;
    };
    const bool changedSide = last_ && sideOf(door, position(*last_)) != sideOf(door, here);
    const std::optional<Eigen::Vector2d> crossing =
        changedSide ? segmentCrossing(position(*last_), here, door.left, door.right) : std::nullopt;
    if (crossing && door.reports != DoorReports::None) {
      if (!d.known) learn(position(*last_));
      ++d.traversals;
      const std::size_t from = sideOf(door, position(*last_)) == sideOf(door, d.firstSide) ? 0 : 1;
      const Eigen::Vector2d direction = (here - position(*last_)).normalized();
      const double c = std::cos(drift_.theta), s = std::sin(drift_.theta);
      emit(GatewayEventKind::Traversed, d, pose,
           {id,
            from,
            1 - from,
            transformPoint(drift_, *crossing),
            {c * direction.x() - s * direction.y(), s * direction.x() + c * direction.y()}});
    }
    const bool within = (here - centre(door)).norm() <= detectRangeM_;
    if (door.reports != DoorReports::All) {
      d.inRange = false;
      continue;
    }
    if (within && !d.inRange) {
      const bool first = !d.known;
      if (first) learn(here);
      emit(first ? GatewayEventKind::Detected : GatewayEventKind::Updated, d, pose);
    }
    d.inRange = within;
  }
  last_ = pose;
}

}  // namespace rgnav::testing
