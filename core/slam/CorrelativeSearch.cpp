// Branch and bound over (angle, x, y) with the likelihood pyramid as the bound (Hess et al. 2016,
// algorithm 3), depth-first with candidates sorted by bound.
#include "core/slam/CorrelativeSearch.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace rgnav {

namespace {

constexpr double kAngularStepPercentile = 0.9;

struct Candidate {
  int angle = 0;  // index into the discretised scans
  int dx = 0;     // cells
  int dy = 0;
  std::int64_t score = 0;
};

class BranchAndBound {
 public:
  BranchAndBound(const LikelihoodPyramid& pyramid, std::vector<std::vector<Eigen::Vector2i>> scans, int window)
      : pyramid_(pyramid), scans_(std::move(scans)), window_(window) {}

  std::int64_t score(int level, const Candidate& c) const {
    std::int64_t sum = 0;
    for (const Eigen::Vector2i& cell : scans_[static_cast<std::size_t>(c.angle)])
      sum += pyramid_.value(level, cell.x() + c.dx, cell.y() + c.dy);
    return sum;
  }

  std::vector<Candidate> topLevel(int level) const {
    const int step = 1 << level;
    std::vector<Candidate> out;
    for (int a = 0; a < static_cast<int>(scans_.size()); ++a)
      for (int dx = -window_; dx <= window_; dx += step)
        for (int dy = -window_; dy <= window_; dy += step) out.push_back(scored(level, {a, dx, dy, 0}));
    sortByScore(out);
    return out;
  }

  // The best leaf under `candidates` (all at `level`) scoring above `best.score`, or `best`.
  Candidate search(const std::vector<Candidate>& candidates, int level, Candidate best) const {
    for (const Candidate& c : candidates) {
      if (c.score <= best.score) break;
      if (level == 0) return c;  // sorted: the first above the bound is the best leaf here
      const int half = 1 << (level - 1);
      std::vector<Candidate> children;
      children.reserve(4);
      for (int ox : {0, half})
        for (int oy : {0, half}) {
          const int dx = c.dx + ox, dy = c.dy + oy;
          if (dx > window_ || dy > window_) continue;
          children.push_back(scored(level - 1, {c.angle, dx, dy, 0}));
        }
      sortByScore(children);
      best = search(children, level - 1, best);
    }
    return best;
  }

 private:
  Candidate scored(int level, Candidate c) const {
    c.score = score(level, c);
    return c;
  }
  static void sortByScore(std::vector<Candidate>& candidates) {
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
      if (a.score != b.score) return a.score > b.score;
      if (a.angle != b.angle) return a.angle < b.angle;
      return a.dx != b.dx ? a.dx < b.dx : a.dy < b.dy;
    });
  }

  const LikelihoodPyramid& pyramid_;
  std::vector<std::vector<Eigen::Vector2i>> scans_;
  int window_;
};

}  // namespace

double angularStep(std::span<const Eigen::Vector2f> query, double resolution) {
  std::vector<float> ranges;
  ranges.reserve(query.size());
  for (const auto& p : query) ranges.push_back(p.norm());
  double range = resolution;
  if (!ranges.empty()) {
    const auto k = static_cast<std::ptrdiff_t>(kAngularStepPercentile * static_cast<double>(ranges.size() - 1));
    std::nth_element(ranges.begin(), ranges.begin() + k, ranges.end());
    range = std::max(range, static_cast<double>(ranges[static_cast<std::size_t>(k)]));
  }
  return std::acos(1.0 - resolution * resolution / (2.0 * range * range));
}

std::optional<CorrelativeMatch> correlativeSearch(const PointGrid& grid, const LikelihoodPyramid& pyramid,
                                                  std::span<const Eigen::Vector2f> query, const Pose2D& guess,
                                                  const SearchWindow& window, double minScore) {
  if (query.empty() || grid.width() == 0) return std::nullopt;
  const double resolution = grid.resolution();
  const double angleStep = angularStep(query, resolution);
  const int angleSteps = static_cast<int>(std::ceil(window.rotation / angleStep));
  const int linear = static_cast<int>(std::ceil(window.translation / resolution));

  std::vector<std::vector<Eigen::Vector2i>> scans;
  scans.reserve(static_cast<std::size_t>(2 * angleSteps + 1));
  for (int k = -angleSteps; k <= angleSteps; ++k) {
    const double theta = guess.theta + k * angleStep;
    const double c = std::cos(theta), s = std::sin(theta);
    std::vector<Eigen::Vector2i> cells;
    cells.reserve(query.size());
    for (const Eigen::Vector2f& q : query) {
      const Eigen::Vector2d p(guess.x + c * q.x() - s * q.y(), guess.y + s * q.x() + c * q.y());
      cells.push_back(grid.cellOf(p));
    }
    scans.push_back(std::move(cells));
  }

  int level = 0;
  while (level + 1 < pyramid.levels() && (1 << level) <= linear) ++level;
  const BranchAndBound search(pyramid, std::move(scans), linear);
  const double fullScore = 255.0 * static_cast<double>(query.size());
  Candidate floor;
  floor.score = static_cast<std::int64_t>(std::ceil(minScore * fullScore)) - 1;
  const Candidate best = search.search(search.topLevel(level), level, floor);
  if (best.score == floor.score) return std::nullopt;
  CorrelativeMatch match;
  match.pose = {guess.x + best.dx * resolution, guess.y + best.dy * resolution,
                normalizeAngle(guess.theta + (best.angle - angleSteps) * angleStep)};
  match.score = static_cast<double>(best.score) / fullScore;
  return match;
}

}  // namespace rgnav
