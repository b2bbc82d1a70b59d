// Frontier clusters of the exploration grid and their viewpoints (Frontiers.h; Yamauchi 1997).
// Deliberate differences from Yamauchi: the frontier cells come from the RG map's freespace (no
// occupancy probabilities), a cluster longer than the useful laser range is cut into pieces, and
// each frontier offers a viewpoint the planner accepts instead of its centroid, which may lie in
// unknown space or in a wall's inflation.
#include "core/nav/exploration/Frontiers.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

namespace rgnav {
namespace {

struct Cell {
  int col = 0, row = 0;
};

constexpr std::array<Cell, 4> kNeighbours4{{{1, 0}, {-1, 0}, {0, 1}, {0, -1}}};
constexpr std::array<Cell, 8> kNeighbours8{{{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}}};
constexpr double kViewpointSearchM = 1.0;  // the viewpoint is sought this far beyond the backoff

bool isFrontierCell(const ExplorationGrid& grid, int col, int row) {
  if (grid.at(col, row) != ExplorationCell::Free) return false;
  for (const Cell& d : kNeighbours4)
    if (grid.at(col + d.col, row + d.row) == ExplorationCell::Unknown) return true;
  return false;
}

// 8-connected clusters of frontier cells, in scan order of their first cell.
std::vector<std::vector<Cell>> clusters(const ExplorationGrid& grid) {
  const auto index = [&](int col, int row) { return static_cast<std::size_t>(row) * grid.width() + col; };
  std::vector<char> frontier(static_cast<std::size_t>(grid.width()) * grid.height(), 0);
  for (int row = 0; row < grid.height(); ++row)
    for (int col = 0; col < grid.width(); ++col) frontier[index(col, row)] = isFrontierCell(grid, col, row);
  std::vector<std::vector<Cell>> out;
  for (int row = 0; row < grid.height(); ++row)
    for (int col = 0; col < grid.width(); ++col) {
      if (!frontier[index(col, row)]) continue;
      std::vector<Cell> cluster{{col, row}};
      frontier[index(col, row)] = 0;
      for (std::size_t next = 0; next < cluster.size(); ++next)
        for (const Cell& d : kNeighbours8) {
          const int c = cluster[next].col + d.col, r = cluster[next].row + d.row;
          if (c < 0 || r < 0 || c >= grid.width() || r >= grid.height() || !frontier[index(c, r)]) continue;
          frontier[index(c, r)] = 0;
          cluster.push_back({c, r});
        }
      out.push_back(std::move(cluster));
    }
  return out;
}

// The cluster cut along its main axis into pieces at most `maxLengthM` long.
std::vector<std::vector<Cell>> pieces(const ExplorationGrid& grid, const std::vector<Cell>& cluster, double maxLengthM) {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Cell& c : cluster) mean += grid.cellCenter(c.col, c.row);
  mean /= static_cast<double>(cluster.size());
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (const Cell& c : cluster) {
    const Eigen::Vector2d d = grid.cellCenter(c.col, c.row) - mean;
    scatter += d * d.transpose();
  }
  const Eigen::Vector2d axis = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(scatter).eigenvectors().col(1);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Cell& c : cluster) {
    const double t = axis.dot(grid.cellCenter(c.col, c.row) - mean);
    lo = std::min(lo, t), hi = std::max(hi, t);
  }
  const double extent = hi - lo + grid.resolutionM();
  const std::size_t count = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(extent / maxLengthM)));
  std::vector<std::vector<Cell>> out(count);
  for (const Cell& c : cluster) {
    const double t = axis.dot(grid.cellCenter(c.col, c.row) - mean) - lo;
    out[std::min(count - 1, static_cast<std::size_t>(t / extent * static_cast<double>(count)))].push_back(c);
  }
  std::erase_if(out, [](const std::vector<Cell>& piece) { return piece.empty(); });
  return out;
}

// The region holding most of the cells (the lowest ID on a tie).
RegionId majorityRegion(const ExplorationGrid& grid, const std::vector<Cell>& cells) {
  std::map<RegionId, std::size_t> counts;
  for (const Cell& c : cells) ++counts[grid.regionAt(c.col, c.row)];
  RegionId best;
  std::size_t most = 0;
  for (const auto& [region, count] : counts)
    if (count > most) best = region, most = count;
  return best;
}

// Unit vector from the cells' unknown neighbours into the free side; zero if they cancel out.
Eigen::Vector2d intoFreeSide(const ExplorationGrid& grid, const std::vector<Cell>& cells) {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (const Cell& c : cells)
    for (const Cell& d : kNeighbours4)
      if (grid.at(c.col + d.col, c.row + d.row) == ExplorationCell::Unknown) sum -= Eigen::Vector2d(d.col, d.row);
  return sum.norm() > 1e-9 ? Eigen::Vector2d(sum.normalized()) : Eigen::Vector2d::Zero();
}

// See findFrontiers (Frontiers.h): a breadth-first search over free cells from the middle.
Eigen::Vector2d viewpointOf(const ExplorationGrid& grid, const Cell& middle, const Eigen::Vector2d& direction,
                            const FrontierConfig& config, double robotRadiusM) {
  const Eigen::Vector2d from = grid.cellCenter(middle.col, middle.row);
  const Eigen::Vector2d target = from + direction * config.viewpointBackoffM;
  const double reach = config.viewpointBackoffM + kViewpointSearchM;
  const double clearance = goalClearanceM(grid, robotRadiusM);
  const int span = static_cast<int>(std::ceil(reach / grid.resolutionM()));
  const int side = 2 * span + 1;
  std::vector<char> visited(static_cast<std::size_t>(side) * side, 0);
  const auto seen = [&](const Cell& c) -> char& {
    return visited[static_cast<std::size_t>(c.row - middle.row + span) * side + (c.col - middle.col + span)];
  };
  std::vector<Cell> queue{middle};
  seen(middle) = 1;
  Eigen::Vector2d best = from, widest = from;
  double bestDistance = std::numeric_limits<double>::infinity(), widestClearance = -1.0, widestDistance = 0.0;
  for (std::size_t next = 0; next < queue.size(); ++next) {
    const Cell cell = queue[next];
    const Eigen::Vector2d p = grid.cellCenter(cell.col, cell.row);
    const double distance = (p - target).norm(), wall = grid.wallDistanceM(cell.col, cell.row);
    if (wall >= clearance && distance < bestDistance) best = p, bestDistance = distance;
    if (wall > widestClearance || (wall == widestClearance && distance < widestDistance))
      widest = p, widestClearance = wall, widestDistance = distance;
    for (const Cell& d : kNeighbours8) {
      const Cell n{cell.col + d.col, cell.row + d.row};
      if (std::abs(n.col - middle.col) > span || std::abs(n.row - middle.row) > span || seen(n)) continue;
      if (grid.at(n.col, n.row) != ExplorationCell::Free || (grid.cellCenter(n.col, n.row) - from).norm() > reach) continue;
      seen(n) = 1;
      queue.push_back(n);
    }
  }
  return bestDistance < std::numeric_limits<double>::infinity() ? best : widest;
}

Frontier frontierOf(const ExplorationGrid& grid, const std::vector<Cell>& cells, const FrontierConfig& config,
                    double robotRadiusM) {
  Frontier f;
  f.region = majorityRegion(grid, cells);
  f.cellSizeM = grid.resolutionM();
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (const Cell& c : cells) {
    f.cells.push_back(grid.cellCenter(c.col, c.row));
    centroid += f.cells.back();
  }
  centroid /= static_cast<double>(cells.size());
  std::size_t middle = 0;
  for (std::size_t i = 1; i < cells.size(); ++i)
    if ((f.cells[i] - centroid).squaredNorm() < (f.cells[middle] - centroid).squaredNorm()) middle = i;
  f.middle = f.cells[middle];
  f.viewpoint = viewpointOf(grid, cells[middle], intoFreeSide(grid, cells), config, robotRadiusM);
  return f;
}

}  // namespace

double Frontier::lengthM() const { return static_cast<double>(cells.size()) * cellSizeM; }

std::vector<Frontier> findFrontiers(const ExplorationGrid& grid, const FrontierConfig& config, double robotRadiusM) {
  std::vector<Frontier> out;
  for (const std::vector<Cell>& cluster : clusters(grid)) {
    if (cluster.size() < config.minCells) continue;
    for (const std::vector<Cell>& piece : pieces(grid, cluster, config.usefulRangeM))
      out.push_back(frontierOf(grid, piece, config, robotRadiusM));
  }
  std::stable_sort(out.begin(), out.end(), [](const Frontier& a, const Frontier& b) { return a.cells.size() > b.cells.size(); });
  return out;
}

}  // namespace rgnav
