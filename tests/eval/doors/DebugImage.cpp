// The door evaluation's debug picture (see DebugImage.h), drawn with OpenCV.
#include "tests/eval/doors/DebugImage.h"

#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "core/raster/GridMat.h"
#include "core/raster/ImageFile.h"

namespace rgnav {
namespace {

constexpr int kScale = 3;
constexpr int kLinePixels = 2;

// Colours in OpenCV's BGR order.
const cv::Scalar kBlocked(90, 90, 90), kExcludedDoor(0, 160, 255), kFoundDoor(0, 190, 0), kMissedDoor(0, 0, 230);
const cv::Scalar kMatch(255, 0, 0), kFalse(230, 0, 230), kOther(220, 200, 0);

class Canvas {
 public:
  explicit Canvas(const OccupancyGrid& world)
      : world_(world), image_(world.height() * kScale, world.width() * kScale, CV_8UC3, cv::Scalar::all(255)) {
    cv::Mat blocked;
    cv::flip(cellMat(world) != static_cast<int>(Cell::Free), blocked, 0);  // image row 0 is the top
    cv::resize(blocked, blocked, image_.size(), 0, 0, cv::INTER_NEAREST);
    image_.setTo(kBlocked, blocked);
  }

  void line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const cv::Scalar& colour) {
    cv::line(image_, pixelOf(a), pixelOf(b), colour, kLinePixels, cv::LINE_8);
  }

  const cv::Mat& image() const { return image_; }

 private:
  cv::Point pixelOf(const Eigen::Vector2d& p) const {
    const double pixel = world_.resolution() / kScale;
    return {static_cast<int>(std::floor((p.x() - world_.origin().x) / pixel)),
            image_.rows - 1 - static_cast<int>(std::floor((p.y() - world_.origin().y) / pixel))};
  }

  const OccupancyGrid& world_;
  cv::Mat image_;
};

}  // namespace

void writeDoorImage(const std::string& path, const OccupancyGrid& world, const std::vector<TruthDoor>& doors,
                    const std::vector<TrackedGateway>& gateways, const DoorMatch& match) {
  Canvas canvas(world);
  for (std::size_t d = 0; d < doors.size(); ++d) {
    const cv::Scalar colour = doors[d].exclusion != DoorExclusion::kNone ? kExcludedDoor
                              : match.detectionOfDoor[d] >= 0        ? kFoundDoor
                                                                     : kMissedDoor;
    canvas.line({doors[d].line.a.x, doors[d].line.a.y}, {doors[d].line.b.x, doors[d].line.b.y}, colour);
  }
  for (std::size_t k = 0; k < gateways.size(); ++k) {
    const DetectionOutcome o = match.outcomes[k];
    canvas.line(gateways[k].left, gateways[k].right,
                o == DetectionOutcome::kMatch ? kMatch : o == DetectionOutcome::kFalse ? kFalse : kOther);
  }
  writeImage(path, canvas.image());
}

}  // namespace rgnav
