// The truth an exploration is measured against; see TruthCoverage.h.
#include "tests/eval/exploration/TruthCoverage.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/common/Errors.h"
#include "core/nav/grid/GridPlanner.h"
#include "core/sim/world/IpaGroundTruth.h"

namespace rgnav {

bool RoomCoverage::reachable() const { return reachableCells >= std::size_t(kIpaMinRoomPixels); }

TruthCoverage::TruthCoverage(const OccupancyGrid& world, const GroundTruth& truth, const WorldPoint& start,
                             double robotRadiusM, double usefulRangeM)
    : world_(world), truth_(truth), usefulRangeM_(usefulRangeM) {
  if (truth.width != world.width() || truth.height != world.height() || truth.labels.size() != world.cells().size())
    throw InvalidArgumentError("truth coverage: the ground truth does not share the world's grid");
  if (!(usefulRangeM > 0.0)) throw InvalidArgumentError("truth coverage: the useful range must be positive");
  GridPlannerConfig config;
  config.robotRadius = robotRadiusM;
  const std::vector<bool> traversable = GridPlanner(world, config).reachableFrom(start);
  cv::Mat centres(world.height(), world.width(), CV_8U);
  for (std::size_t i = 0; i < traversable.size(); ++i) centres.data[i] = traversable[i] ? 1 : 0;
  const int radius = int(std::ceil(robotRadiusM / world.resolution()));
  const cv::Mat disk = cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * radius + 1, 2 * radius + 1));
  cv::Mat covered;
  cv::dilate(centres, covered, disk);
  reachable_.assign(world.cells().size(), 0);
  for (std::size_t i = 0; i < reachable_.size(); ++i) {
    reachable_[i] = covered.data[i] != 0 && world.cells()[i] == Cell::Free;
    reachableCount_ += reachable_[i];
  }
  seen_.assign(world.cells().size(), 0);
}

void TruthCoverage::addScan(const LaserScan& scan) {
  const std::optional<CellIndex> from = world_.cellOf({scan.sensorPose.x, scan.sensorPose.y});
  if (!from) return;
  const cv::Rect bounds(0, 0, world_.width(), world_.height());
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const double measured = scan.ranges[i];
    if (std::isnan(measured)) continue;
    const double range = std::min(measured, usefulRangeM_);
    const double angle = scan.sensorPose.theta + scan.startAngle + double(i) * scan.angleIncrement;
    const double x = (scan.sensorPose.x + range * std::cos(angle) - world_.origin().x) / world_.resolution();
    const double y = (scan.sensorPose.y + range * std::sin(angle) - world_.origin().y) / world_.resolution();
    cv::Point to(int(std::floor(x)), int(std::floor(y)));
    if (!cv::clipLine(bounds, to, to)) to = {std::clamp(to.x, 0, bounds.width - 1), std::clamp(to.y, 0, bounds.height - 1)};
    cv::LineIterator line(bounds.size(), cv::Point(from->col, from->row), to, 8);
    for (int k = 0; k < line.count; ++k, ++line) {
      const cv::Point p = line.pos();
      const std::size_t cell = std::size_t(p.y) * std::size_t(world_.width()) + std::size_t(p.x);
      if (!reachable_[cell] || seen_[cell]) continue;
      seen_[cell] = 1;
      ++seenCount_;
    }
  }
}

double TruthCoverage::seenShare() const {
  return reachableCount_ == 0 ? 0.0 : double(seenCount_) / double(reachableCount_);
}

std::vector<RoomCoverage> TruthCoverage::rooms() const {
  std::vector<RoomCoverage> out(std::size_t(std::max(truth_.roomCount, 0)));
  for (std::size_t r = 0; r < out.size(); ++r) out[r].room = int(r);
  for (std::size_t cell = 0; cell < reachable_.size(); ++cell) {
    const int room = truth_.labels[cell];
    if (room < 0 || !reachable_[cell]) continue;
    ++out[std::size_t(room)].reachableCells;
    out[std::size_t(room)].seenCells += seen_[cell];
  }
  return out;
}

}  // namespace rgnav
