// CircleDetector: round 2D objects (thesis Table 2.1, "2D circle": round tables, bins, pillars)
// in the scan points of a region. Points are clustered (PointClustering); each cluster with
// enough points gets a circle fit (CircleFit) and is kept if the radius lies within limits, the
// fit is tight and the points cover enough of the circle's arc, which also rules out straight
// walls. Confidence = min(1, arc / pi) * (1 - rms / maxResidualM): half a circle seen, as from
// one viewpoint, with no residual gives 1. The thesis names circles as objects but gives no
// method; this one and its defaults are ours.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <vector>

namespace rgnav {

struct Circle2D {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  double radiusM = 0.0;
  double rmsResidualM = 0.0;
  double arcRad = 0.0;  // angle of the circle covered by the points (2 pi minus the largest gap)
  double confidence = 0.0;
  std::size_t pointCount = 0;
};

struct CircleDetectorParams {
  double clusterGapM = 0.10;  // points closer than this belong to one object
  std::size_t minPoints = 8;
  double minRadiusM = 0.10;
  double maxRadiusM = 0.80;
  double maxResidualM = 0.02;  // largest rms geometric residual
  double minArcRad = 90.0 * M_PI / 180.0;
};

class CircleDetector {
 public:
  // Throws InvalidArgumentError for parameters that can never work.
  explicit CircleDetector(const CircleDetectorParams& params = {});

  // Circles among `points` (e.g. all aligned scan points of a region), most confident first.
  std::vector<Circle2D> detect(const std::vector<Eigen::Vector2d>& points) const;

 private:
  CircleDetectorParams params_;
};

}  // namespace rgnav
