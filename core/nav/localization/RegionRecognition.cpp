// Matching the local observation against every mapped region (see RegionRecognition.h).
#include "core/nav/localization/RegionRecognition.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/common/Errors.h"
#include "core/lines/ScanPoints.h"

namespace rgnav {

namespace {

// A peak of the correlation: the robot in the region frame and the correlation's value.
struct Peak {
  Pose2D pose;
  double value = 0.0;
};

bool sameRotation(double a, double b) { return std::abs(normalizeAngle(a - b)) < M_PI / 180.0; }

// Rotations that take the observation's main directions onto the region's (see the header).
std::vector<double> candidateRotations(const std::vector<MainDirection>& observed,
                                       const std::vector<MainDirection>& mapped, double sweepStepRad) {
  std::vector<double> out;
  const auto addRotation = [&](double r) {
    r = normalizeAngle(r);
    if (std::none_of(out.begin(), out.end(), [&](double o) { return sameRotation(o, r); })) out.push_back(r);
  };
  if (observed.empty() || mapped.empty()) {
    for (double r = 0.0; r < 2.0 * M_PI - 1e-9; r += sweepStepRad) addRotation(r);
    return out;
  }
  for (const MainDirection& m : mapped)
    for (const MainDirection& o : observed)
      for (int k = 0; k < 4; ++k) addRotation(m.angleRad - o.angleRad + k * M_PI / 2.0);
  return out;
}

// Every n-th point so that at most `count` remain.
std::vector<Eigen::Vector2d> evenSubset(const std::vector<Eigen::Vector2d>& points, std::size_t count) {
  if (points.size() <= count || count == 0) return points;
  std::vector<Eigen::Vector2d> out;
  const double stride = double(points.size()) / double(count);
  for (std::size_t i = 0; i < count; ++i) out.push_back(points[std::size_t(double(i) * stride)]);
  return out;
}

bool nearPose(const Pose2D& a, const Pose2D& b, double distanceM, double angleRad) {
  return std::hypot(a.x - b.x, a.y - b.y) < distanceM && std::abs(normalizeAngle(a.theta - b.theta)) < angleRad;
}

}  // namespace

RegionRecognizer::RegionRecognizer(const RecognitionConfig& config, const BeamModelConfig& beams,
                                   const LocalizationMap& map, const std::vector<RegionView>& regions,
                                   const std::vector<GatewayView>& gateways)
    : config_(config), fieldResolutionM_(beams.resolutionM), map_(map) {
  if (!(config.cellM > 0.0) || !(config.templateRadiusM > config.cellM) || !(config.rotationSweepStepRad > 0.0) ||
      !(config.refineStepM > 0.0) || !(config.refineStepRad > 0.0) || config.peaksPerRotation == 0 ||
      config.candidatesPerRegion == 0 || config.refinePoints == 0 || config.robotFreeMarginM < 0.0)
    throw ConfigError("RegionRecognizer: sizes, steps and counts must be positive");
  for (const RegionView& r : regions)
    if (map.hasRegion(r.summary.id)) descriptors_.emplace(r.summary.id, describeMappedRegion(r, regions, gateways));
}

const RegionRecognizer::RegionRaster& RegionRecognizer::raster(RegionId region) const {
  if (const auto it = rasters_.find(region); it != rasters_.end()) return it->second;
  const LikelihoodField& field = map_.field(region);
  const FreespaceBitmap& free = map_.region(region).freespace;
  const double cell = config_.cellM;
  Eigen::Vector2d lo = field.origin();
  Eigen::Vector2d hi = lo + Eigen::Vector2d(field.width(), field.height()) * fieldResolutionM_;
  if (free.width > 0) {
    lo = lo.cwiseMin(free.originM);
    hi = hi.cwiseMax(free.originM + Eigen::Vector2d(free.width, free.height) * free.resolutionM);
  }
  const double pad = std::ceil(config_.templateRadiusM / cell + 1.0) * cell;
  RegionRaster r;
  r.origin = lo - Eigen::Vector2d(pad, pad);
  const int cols = int(std::ceil((hi.x() - lo.x() + 2.0 * pad) / cell)), rows = int(std::ceil((hi.y() - lo.y() + 2.0 * pad) / cell));
  const auto centre = [&](int c, int row) -> Eigen::Vector2d { return r.origin + Eigen::Vector2d((c + 0.5) * cell, (row + 0.5) * cell); };
  cv::Mat logP(rows, cols, CV_32F);
  for (int row = 0; row < rows; ++row)
    for (int c = 0; c < cols; ++c) logP.at<float>(row, c) = float(field.logLikelihood(centre(c, row)));
  const double outside = field.logLikelihood(Eigen::Vector2d(r.origin.x() - 1e4, r.origin.y() - 1e4));
  double top = outside;
  cv::minMaxLoc(logP, nullptr, &top);
  const double span = std::max(top - outside, 1e-9);
  r.score = (logP - outside) / span;
  cv::threshold(r.score, r.score, 0.0, 0.0, cv::THRESH_TOZERO);
  cv::threshold(r.score, r.wall, config_.wallLevel, 1.0, cv::THRESH_BINARY);
  r.standing = cv::Mat::zeros(rows, cols, CV_8U);
  for (int row = 0; row < free.height; ++row)
    for (int c = 0; c < free.width; ++c) {
      if (!free.isFree(c, row)) continue;
      const Eigen::Vector2d p = (free.cellCenter(c, row) - r.origin) / cell;
      const int pc = int(std::floor(p.x())), pr = int(std::floor(p.y()));
      if (pc >= 0 && pr >= 0 && pc < cols && pr < rows) r.standing.at<std::uint8_t>(pr, pc) = 1;
    }
  const int grow = int(std::ceil(config_.robotFreeMarginM / cell));
  if (grow > 0)
    cv::dilate(r.standing, r.standing,
               cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * grow + 1, 2 * grow + 1)));
  return rasters_.emplace(region, std::move(r)).first->second;
}

double RegionRecognizer::fit(RegionId region, const Pose2D& regionPose, const std::vector<Eigen::Vector2d>& points) const {
  return map_.field(region).meanLogLikelihood(regionPose, points);
}

Pose2D RegionRecognizer::refine(RegionId region, Pose2D pose, const std::vector<Eigen::Vector2d>& points) const {
  double best = fit(region, pose, points);
  double stepM = config_.refineStepM, stepRad = config_.refineStepRad;
  for (int level = 0; level < 4; ++level, stepM /= 2.0, stepRad /= 2.0)
    for (int iteration = 0; iteration < 20; ++iteration) {
      const Pose2D moves[] = {{stepM, 0, 0}, {-stepM, 0, 0}, {0, stepM, 0}, {0, -stepM, 0}, {0, 0, stepRad}, {0, 0, -stepRad}};
      Pose2D bestPose = pose;
      for (const Pose2D& m : moves) {
        const Pose2D tried{pose.x + m.x, pose.y + m.y, normalizeAngle(pose.theta + m.theta)};
        if (const double f = fit(region, tried, points); f > best) {
          best = f;
          bestPose = tried;
        }
      }
      if (bestPose == pose) break;
      pose = bestPose;
    }
  return pose;
}

std::vector<PoseCandidate> RegionRecognizer::searchRegion(RegionId region, const LocalObservation& observation,
                                                          const std::vector<double>& rotations,
                                                          const std::vector<Eigen::Vector2d>& refinePoints) const {
  const RegionRaster& r = raster(region);
  const double cell = config_.cellM;
  const int half = int(std::ceil(config_.templateRadiusM / cell)), size = 2 * half + 1;
  if (r.score.cols < size || r.score.rows < size) return {};
  const auto templateCell = [&](const Eigen::Vector2d& q) {
    return std::pair<int, int>(int(std::floor(q.x() / cell + 0.5)) + half, int(std::floor(q.y() / cell + 0.5)) + half);
  };
  const auto inTemplate = [&](std::pair<int, int> c) { return c.first >= 0 && c.second >= 0 && c.first < size && c.second < size; };
  std::vector<Eigen::Vector2d> freeCells;
  const CellWindow& w = observation.freespace.window();
  for (int j = w.row0; j < w.row0 + w.height; ++j)
    for (int i = w.col0; i < w.col0 + w.width; ++i)
      if (observation.freespace.cell(i, j) == FreespaceCell::Free) freeCells.push_back(observation.freespace.cellCenter(i, j));

  std::vector<Peak> peaks;
  for (const double theta : rotations) {
    const Pose2D rotation{0.0, 0.0, theta};
    cv::Mat hits = cv::Mat::zeros(size, size, CV_32F), free = cv::Mat::zeros(size, size, CV_32F);
    for (const Eigen::Vector2d& p : observation.points)
      if (const auto c = templateCell(transformPoint(rotation, p)); inTemplate(c)) hits.at<float>(c.second, c.first) = 1.0f;
    for (const Eigen::Vector2d& p : freeCells)
      if (const auto c = templateCell(transformPoint(rotation, p)); inTemplate(c)) free.at<float>(c.second, c.first) = 1.0f;
    const double hitCount = cv::sum(hits)[0], freeCount = cv::sum(free)[0];
    if (hitCount <= 0.0) continue;
    cv::Mat hitScore, freeOnWall;
    cv::matchTemplate(r.score, hits, hitScore, cv::TM_CCORR);
    cv::Mat value = hitScore / hitCount;
    if (freeCount > 0.0) {
      cv::matchTemplate(r.wall, free, freeOnWall, cv::TM_CCORR);
      value -= freeOnWall * (config_.freeOnWallWeight / freeCount);
    }
    std::vector<Peak> here;
    for (int v = 0; v < value.rows; ++v)
      for (int u = 0; u < value.cols; ++u) {
        if (!r.standing.at<std::uint8_t>(v + half, u + half)) continue;
        const Eigen::Vector2d at = r.origin + Eigen::Vector2d((u + half + 0.5) * cell, (v + half + 0.5) * cell);
        here.push_back({{at.x(), at.y(), theta}, value.at<float>(v, u)});
      }
    std::sort(here.begin(), here.end(), [](const Peak& a, const Peak& b) { return a.value > b.value; });
    std::size_t kept = 0;
    const std::size_t firstOfRotation = peaks.size();
    for (const Peak& p : here) {
      if (kept >= config_.peaksPerRotation) break;
      const bool suppressed = std::any_of(peaks.begin() + std::ptrdiff_t(firstOfRotation), peaks.end(), [&](const Peak& q) {
        return std::hypot(p.pose.x - q.pose.x, p.pose.y - q.pose.y) < config_.peakSeparationM;
      });
      if (suppressed) continue;
      peaks.push_back(p);
      ++kept;
    }
  }
  // Only the best peaks of the region are refined (the correlation ranks them well enough).
  std::sort(peaks.begin(), peaks.end(), [](const Peak& a, const Peak& b) { return a.value > b.value; });
  peaks.resize(std::min(peaks.size(), 2 * config_.candidatesPerRegion));
  std::vector<PoseCandidate> out;
  const Pose2D frame = map_.region(region).frame;
  for (const Peak& p : peaks) {
    PoseCandidate c;
    c.region = region;
    c.regionPose = refine(region, p.pose, refinePoints);
    if (std::any_of(out.begin(), out.end(), [&](const PoseCandidate& o) {
          return nearPose(o.regionPose, c.regionPose, 0.3, 10.0 * M_PI / 180.0);
        }))
      continue;
    c.mapPose = compose(frame, c.regionPose);
    c.fit = fit(region, c.regionPose, refinePoints);
    out.push_back(c);
  }
  std::sort(out.begin(), out.end(), [](const PoseCandidate& a, const PoseCandidate& b) { return a.fit > b.fit; });
  out.resize(std::min(out.size(), config_.candidatesPerRegion));
  return out;
}

PoseCandidate RegionRecognizer::candidateAt(RegionId region, const Pose2D& regionPose,
                                           const LocalObservation& observation) const {
  const auto mapped = descriptors_.find(region);
  if (mapped == descriptors_.end()) throw NotAvailableError("RegionRecognizer: no region " + std::to_string(region.value()));
  PoseCandidate c;
  c.region = region;
  c.regionPose = regionPose;
  c.mapPose = compose(map_.region(region).frame, regionPose);
  c.fit = fit(region, regionPose, evenSubset(observation.points, config_.refinePoints));
  c.descriptorDistance = descriptorDistance(describeObservation(observation), mapped->second, config_.descriptor);
  c.score = c.fit - config_.descriptorWeight * c.descriptorDistance;
  return c;
}

std::vector<PoseCandidate> RegionRecognizer::recognize(const LocalObservation& observation) const {
  if (observation.points.empty()) return {};
  const RegionDescriptor observed = describeObservation(observation);
  const std::vector<Eigen::Vector2d> refinePoints = evenSubset(observation.points, config_.refinePoints);
  std::vector<PoseCandidate> all;
  for (const auto& [id, mapped] : descriptors_) {
    const double distance = descriptorDistance(observed, mapped, config_.descriptor);
    const std::vector<double> rotations =
        candidateRotations(observed.mainDirections, mapped.mainDirections, config_.rotationSweepStepRad);
    for (PoseCandidate& c : searchRegion(id, observation, rotations, refinePoints)) {
      c.descriptorDistance = distance;
      c.score = c.fit - config_.descriptorWeight * distance;
      all.push_back(c);
    }
  }
  std::sort(all.begin(), all.end(), [](const PoseCandidate& a, const PoseCandidate& b) { return a.score > b.score; });
  return all;
}

}  // namespace rgnav
