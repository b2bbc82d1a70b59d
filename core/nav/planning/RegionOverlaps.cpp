// RegionOverlaps: transfer points where two regions' free cells overlap (see the header).
#include "core/nav/planning/RegionOverlaps.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "core/lines/ScanPoints.h"

namespace rgnav {

namespace {

// The map-frame box of a grid placed at `frame`.
Eigen::AlignedBox2d boxOf(const RegionGrid& g, const Pose2D& frame) {
  Eigen::AlignedBox2d box;
  const double w = g.grid.width() * g.grid.resolution(), h = g.grid.height() * g.grid.resolution();
  const Eigen::Vector2d o(g.grid.origin().x, g.grid.origin().y);
  for (const Eigen::Vector2d& corner : {o, Eigen::Vector2d(o + Eigen::Vector2d(w, 0)), Eigen::Vector2d(o + Eigen::Vector2d(0, h)),
                                        Eigen::Vector2d(o + Eigen::Vector2d(w, h))})
    box.extend(transformPoint(frame, corner));
  return box;
}

}  // namespace

std::vector<Eigen::Vector2d> overlapTransfers(const RegionGrid& a, const Pose2D& frameA, const RegionGrid& b,
                                              const Pose2D& frameB, double sampleM, double minAreaM2) {
  if (!boxOf(a, frameA).intersects(boxOf(b, frameB))) return {};
  const Pose2D aToB = between(frameB, frameA);
  const int step = std::max(1, static_cast<int>(std::lround(sampleM / a.grid.resolution())));
  const int cols = (a.grid.width() + step - 1) / step, rows = (a.grid.height() + step - 1) / step;
  cv::Mat both(rows, cols, CV_8U, cv::Scalar(0));
  std::vector<Eigen::Vector2d> inA(static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols));
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const CellIndex cell{c * step, r * step};
      if (a.grid.blocked(cell)) continue;
      const Eigen::Vector2d p = a.toRegion({cell.col + 0.5, cell.row + 0.5});
      inA[static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c)] = p;
      if (b.freeAt(transformPoint(aToB, p))) both.at<std::uint8_t>(r, c) = 1;
    }
  cv::Mat labels, stats, centroids;
  const int count = cv::connectedComponentsWithStats(both, labels, stats, centroids, 8, CV_32S);
  const double sampleArea = std::pow(step * a.grid.resolution(), 2);
  std::vector<Eigen::Vector2d> out;
  for (int k = 1; k < count; ++k) {
    if (stats.at<int>(k, cv::CC_STAT_AREA) * sampleArea < minAreaM2) continue;
    const Eigen::Vector2d centroid(centroids.at<double>(k, 0), centroids.at<double>(k, 1));
    double best = std::numeric_limits<double>::infinity();
    Eigen::Vector2d chosen = Eigen::Vector2d::Zero();
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < cols; ++c)
        if (labels.at<int>(r, c) == k && (Eigen::Vector2d(c, r) - centroid).squaredNorm() < best) {
          best = (Eigen::Vector2d(c, r) - centroid).squaredNorm();
          chosen = inA[static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c)];
        }
    out.push_back(transformPoint(frameA, chosen));
  }
  return out;
}

}  // namespace rgnav
