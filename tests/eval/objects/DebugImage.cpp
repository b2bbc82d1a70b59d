// Debug rendering of ground truth and detections; see DebugImage.h.
#include "tests/eval/objects/DebugImage.h"

#include <array>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "core/raster/ImageFile.h"

namespace rgnav {
namespace {

using Colour = std::array<std::uint8_t, 3>;
constexpr int kScale = 3;

Colour cellColour(const OccupancyGrid& world, const FurnitureTruth& truth, const MatchResult& match, std::size_t cell) {
  const int blob = truth.blobOfCell[cell];
  if (blob < 0) return world.cells()[cell] == Cell::Free ? Colour{255, 255, 255} : Colour{90, 90, 90};
  switch (truth.blobs[static_cast<std::size_t>(blob)].exclusion) {
    case Exclusion::kSpeck: return {150, 200, 255};
    case Exclusion::kNotVisible: return {190, 150, 230};
    case Exclusion::kNone: break;
  }
  return match.detectionOfBlob[static_cast<std::size_t>(blob)] >= 0 ? Colour{120, 220, 120} : Colour{240, 60, 60};
}

Colour outcomeColour(Outcome outcome) {
  switch (outcome) {
    case Outcome::kMatch: return {0, 110, 0};
    case Outcome::kFalse: return {230, 0, 230};
    case Outcome::kIgnored: return {0, 0, 230};
  }
  return {0, 0, 0};
}

cv::Scalar bgr(const Colour& c) { return {double(c[2]), double(c[1]), double(c[0])}; }

void paint(cv::Mat& image, int x, int y, const Colour& c) { image.at<cv::Vec3b>(y, x) = {c[2], c[1], c[0]}; }

}  // namespace

void writeDebugImage(const std::string& path, const OccupancyGrid& world, const FurnitureTruth& truth,
                     const std::vector<Detection>& detections, const MatchResult& match,
                     const std::vector<bool>& hitCells) {
  const int w = world.width(), h = world.height();
  cv::Mat image(h * kScale, w * kScale, CV_8UC3);
  const auto pixelOf = [&](std::size_t cell) {
    return std::pair(static_cast<int>(cell % static_cast<std::size_t>(w)) * kScale,
                     (h - 1 - static_cast<int>(cell / static_cast<std::size_t>(w))) * kScale);
  };
  for (std::size_t cell = 0; cell < world.cells().size(); ++cell) {
    const auto [x, y] = pixelOf(cell);
    cv::rectangle(image, cv::Rect(x, y, kScale, kScale), bgr(cellColour(world, truth, match, cell)), cv::FILLED);
    if (hitCells[cell]) paint(image, x, y, {0, 0, 0});
  }
  for (std::size_t d = 0; d < detections.size(); ++d)
    for (const std::size_t cell : detections[d].cells) {
      const auto [x, y] = pixelOf(cell);
      paint(image, x + kScale / 2, y + kScale / 2, outcomeColour(match.outcomes[d]));
    }
  writeImage(path, image);
}

}  // namespace rgnav
