// LikelihoodField (LikelihoodField.h): lines rasterised with cv::line, cv::distanceTransform
// (DIST_L2, DIST_MASK_PRECISE) for the distance of every cell centre to the nearest line cell.
#include "core/nav/localization/LikelihoodField.h"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace rgnav {
namespace {

// The largest field side in cells (a 200 m floor at 5 cm).
constexpr int kMaxSide = 4000;

}  // namespace

LikelihoodField::LikelihoodField(std::span<const Segment2> lines, const BeamModelConfig& config) : config_(config) {
  MclConfig whole;
  whole.beam = config;
  validate(whole);
  const double randomP = config.zRand / config.maxRangeM;
  outside_ = std::log(randomP);
  if (lines.empty()) return;
  Eigen::Vector2d lo = lines.front().a, hi = lines.front().a;
  for (const Segment2& s : lines) {
    lo = lo.cwiseMin(s.a).cwiseMin(s.b);
    hi = hi.cwiseMax(s.a).cwiseMax(s.b);
  }
  const double res = config.resolutionM;
  origin_ = lo - Eigen::Vector2d::Constant(config.marginM);
  width_ = std::min(kMaxSide, static_cast<int>(std::ceil((hi.x() - lo.x() + 2.0 * config.marginM) / res)) + 1);
  height_ = std::min(kMaxSide, static_cast<int>(std::ceil((hi.y() - lo.y() + 2.0 * config.marginM) / res)) + 1);
  cv::Mat free(height_, width_, CV_8U, cv::Scalar(255));
  const auto cell = [&](const Eigen::Vector2d& p) {
    return cv::Point(static_cast<int>(std::floor((p.x() - origin_.x()) / res)),
                     static_cast<int>(std::floor((p.y() - origin_.y()) / res)));
  };
  for (const Segment2& s : lines) cv::line(free, cell(s.a), cell(s.b), cv::Scalar(0), 1, cv::LINE_8);
  cv::Mat distance;
  cv::distanceTransform(free, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  const double step = std::max(res / 4.0, 8.0 * config.sigmaHitM / 255.0);
  const double norm = config.zHit / (std::sqrt(2.0 * M_PI) * config.sigmaHitM);
  const double twoSigma2 = 2.0 * config.sigmaHitM * config.sigmaHitM;
  for (std::size_t q = 0; q < logP_.size(); ++q) {
    const double m = static_cast<double>(q) * step;
    logP_[q] = std::log(norm * std::exp(-m * m / twoSigma2) + randomP);
  }
  steps_.resize(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_));
  const double cellsPerStep = res / step;
  for (int row = 0; row < height_; ++row) {
    const float* d = distance.ptr<float>(row);
    std::uint8_t* out = &steps_[static_cast<std::size_t>(row) * static_cast<std::size_t>(width_)];
    for (int col = 0; col < width_; ++col)
      out[col] = static_cast<std::uint8_t>(std::min(255.0, std::round(d[col] * cellsPerStep)));
  }
}

double LikelihoodField::logLikelihood(const Eigen::Vector2d& point) const {
  const double res = config_.resolutionM;
  const double fx = (point.x() - origin_.x()) / res, fy = (point.y() - origin_.y()) / res;
  if (!(fx >= 0.0 && fy >= 0.0 && fx < width_ && fy < height_)) return outside_;
  return logP_[steps_[static_cast<std::size_t>(fy) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(fx)]];
}

double LikelihoodField::sumLogLikelihood(const Pose2D& pose, std::span<const Eigen::Vector2d> points) const {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  double sum = 0.0;
  for (const Eigen::Vector2d& e : points)
    sum += logLikelihood(Eigen::Vector2d(pose.x + c * e.x() - s * e.y(), pose.y + s * e.x() + c * e.y()));
  return sum;
}

double LikelihoodField::logLikelihood(const Pose2D& robotPose, const ScanBeams& beams) const {
  return sumLogLikelihood(robotPose, beams.endpoints) * config_.beamWeight;
}

double LikelihoodField::meanLogLikelihood(const Pose2D& pose, std::span<const Eigen::Vector2d> points) const {
  return points.empty() ? 0.0 : sumLogLikelihood(pose, points) / static_cast<double>(points.size());
}

std::size_t LikelihoodField::bytes() const { return steps_.size() + sizeof(logP_); }

}  // namespace rgnav
