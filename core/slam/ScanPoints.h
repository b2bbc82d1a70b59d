// ScanPoints: the beams of a laser scan as 2D points in the sensor frame, and surface normals
// estimated from each point's neighbours along the scan (principal component of the points within
// a radius, as PLICP (Censi 2008) takes its lines from consecutive points; we use a small PCA
// window instead of the segment between two neighbours to be robust to range noise).
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "core/common/SensorData.h"
#include "core/slam/SlamConfig.h"

namespace rgnav {

// Finite ranges within [minRange, maxRange], in beam order, rounded to float.
std::vector<Eigen::Vector2f> scanToPoints(const LaserScan& scan, const ScanPointsConfig& config);

// A unit normal per point, or zero where the neighbourhood is too small or not line-like.
// `points` must be in beam order (as scanToPoints gives them).
std::vector<Eigen::Vector2f> estimateNormals(std::span<const Eigen::Vector2f> points, const ScanPointsConfig& config);

}  // namespace rgnav
