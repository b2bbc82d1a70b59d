// rgnav-eval-planning: the MovingAI benchmark of issue 26. For every problem of each map's .scen
// the framed-quadtree planner (robot a point, no inflation, wall costs off) plans between the cell
// centres; every path is checked (starts and ends at the problem's cell centres, every segment
// segmentFree) and compared with the .scen's octile optimum; the 8-connected grid A* baseline
// solves the same problem in the same run for the speed comparison, and the exact Euclidean
// shortest path (VisibilityGraph) is the limit the path's length is measured against. A line per
// map, then the summary line `planning: ...` (see issue 26). tree_build_ms is the planner's
// construction once per map: the framed quadtree, the line-of-sight distance field and the
// landmark distances; planner_ms and grid_astar_ms sum the plan() calls only.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "core/common/Errors.h"
#include "core/nav/planning/FramedQuadtreePlanner.h"
#include "core/nav/planning/GridAStar.h"
#include "core/nav/planning/SegmentVisibility.h"
#include "core/nav/planning/VisibilityGraph.h"
#include "tests/eval/planning/MovingAiMap.h"
#include "tools/common/CommandLine.h"

namespace po = boost::program_options;

namespace {

using Clock = std::chrono::steady_clock;

struct Options {
  std::vector<std::string> maps;
  std::size_t maxProblemsPerMap = 0;
};

struct Figures {
  std::size_t problems = 0;
  std::size_t solved = 0;
  std::size_t invalid = 0;
  std::size_t gridAStarMismatches = 0;  // grid A* lengths that differ from the .scen optimum
  double ratioToOctileMax = 0.0;
  double ratioToEuclidSum = 0.0;
  std::size_t ratiosToEuclid = 0;
  double ratioToEuclidMax = 0.0;
  double plannerSeconds = 0.0;
  double gridAStarSeconds = 0.0;
  std::size_t plannerExpansions = 0;
  std::size_t gridAStarExpansions = 0;

  void add(const Figures& o) {
    problems += o.problems;
    solved += o.solved;
    invalid += o.invalid;
    gridAStarMismatches += o.gridAStarMismatches;
    ratioToOctileMax = std::max(ratioToOctileMax, o.ratioToOctileMax);
    ratioToEuclidSum += o.ratioToEuclidSum;
    ratiosToEuclid += o.ratiosToEuclid;
    ratioToEuclidMax = std::max(ratioToEuclidMax, o.ratioToEuclidMax);
    plannerSeconds += o.plannerSeconds;
    gridAStarSeconds += o.gridAStarSeconds;
    plannerExpansions += o.plannerExpansions;
    gridAStarExpansions += o.gridAStarExpansions;
  }
  double ratioToEuclidMean() const { return ratiosToEuclid ? ratioToEuclidSum / double(ratiosToEuclid) : 0.0; }
  double speedup() const { return plannerSeconds > 0.0 ? gridAStarSeconds / plannerSeconds : 0.0; }
};

double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

Eigen::Vector2d centre(rgnav::CellIndex c) { return {c.col + 0.5, c.row + 0.5}; }

// At most `limit` problems (0: all), spread evenly over the list, which the .scen orders by bucket.
std::vector<rgnav::MovingAiProblem> selectProblems(const std::vector<rgnav::MovingAiProblem>& all, std::size_t limit) {
  if (limit == 0 || limit >= all.size()) return all;
  std::vector<rgnav::MovingAiProblem> chosen;
  for (std::size_t k = 0; k < limit; ++k) chosen.push_back(all[k * all.size() / limit]);
  return chosen;
}

// Whether a path starts and ends at the given points, each segment is free, and its stated length
// is its polyline's.
bool validPath(const rgnav::OccupancyGrid& grid, const rgnav::CellUnitPath& path, const Eigen::Vector2d& start,
               const Eigen::Vector2d& goal) {
  if (path.points.empty() || path.points.front() != start || path.points.back() != goal) return false;
  double length = 0.0;
  for (std::size_t i = 1; i < path.points.size(); ++i) {
    if (!rgnav::segmentFree(grid, path.points[i - 1], path.points[i])) return false;
    length += (path.points[i] - path.points[i - 1]).norm();
  }
  return std::abs(length - path.length) <= 1e-9 * std::max(1.0, length);
}

Figures scoreProblems(const rgnav::OccupancyGrid& grid, const rgnav::FramedQuadtreePlanner& planner,
                      const rgnav::VisibilityGraph& euclid, const std::vector<rgnav::MovingAiProblem>& problems,
                      const std::string& name) {
  const rgnav::GridAStar gridAStar(grid);
  Figures f;
  for (const rgnav::MovingAiProblem& p : problems) {
    ++f.problems;
    const Eigen::Vector2d start = centre(p.start), goal = centre(p.goal);
    try {
      const Clock::time_point t0 = Clock::now();
      const rgnav::CellUnitPath path = planner.plan(start, goal);
      f.plannerSeconds += secondsSince(t0);
      ++f.solved;
      f.plannerExpansions += path.expansions;
      if (!validPath(grid, path, start, goal)) {
        ++f.invalid;
        std::cerr << name << ": invalid path from " << p.start.col << "," << p.start.row << " to " << p.goal.col << ","
                  << p.goal.row << std::endl;
      }
      if (p.octileOptimum > 0.0) f.ratioToOctileMax = std::max(f.ratioToOctileMax, path.length / p.octileOptimum);
      const double optimum = euclid.shortestPath(start, goal).length;
      if (optimum > 0.0) {
        f.ratioToEuclidSum += path.length / optimum;
        ++f.ratiosToEuclid;
        f.ratioToEuclidMax = std::max(f.ratioToEuclidMax, path.length / optimum);
      }
    } catch (const rgnav::Error& e) {
      std::cerr << name << ": " << e.what() << std::endl;
    }
    const Clock::time_point t0 = Clock::now();
    const rgnav::GridPath baseline = gridAStar.plan(p.start, p.goal);
    f.gridAStarSeconds += secondsSince(t0);
    f.gridAStarExpansions += baseline.expansions;
    if (std::abs(baseline.length - p.octileOptimum) > 1e-6 * std::max(1.0, p.octileOptimum)) ++f.gridAStarMismatches;
  }
  return f;
}

void printFigures(const Figures& f) {
  std::printf(" problems=%zu solved=%zu invalid=%zu ratio_to_octile_max=%.6f ratio_to_euclid_mean=%.5f", f.problems,
              f.solved, f.invalid, f.ratioToOctileMax, f.ratioToEuclidMean());
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  po::options_description desc("rgnav-eval-planning <map.map...> [--max-problems-per-map N]");
  desc.add_options()
      ("help", "this text")
      ("map", po::value(&options.maps)->required()->multitoken(), "MovingAI .map files (each beside its .map.scen)")
      ("max-problems-per-map", po::value(&options.maxProblemsPerMap)->default_value(0),
       "run at most N problems of each map, spread evenly over its buckets (0: all)");
  po::positional_options_description positional;
  positional.add("map", -1);
  try {
    if (!rgnav::parseCommandLine(argc, argv, desc, positional)) return 0;
    Figures total;
    std::size_t nodes = 0, freeCells = 0, roomNodes = 0, roomFreeCells = 0;
    for (const std::string& mapPath : options.maps) {
      const std::filesystem::path path(mapPath);
      const std::string name = (path.parent_path().filename() / path.stem()).string();
      const rgnav::OccupancyGrid grid = rgnav::loadMovingAiMap(mapPath);
      const std::vector<rgnav::MovingAiProblem> problems =
          selectProblems(rgnav::loadMovingAiScenario(mapPath + ".scen", grid.height()), options.maxProblemsPerMap);
      const Clock::time_point t0 = Clock::now();
      const rgnav::FramedQuadtreePlanner planner(grid);
      const double buildSeconds = secondsSince(t0);
      const rgnav::VisibilityGraph euclid(grid);
      const Figures f = scoreProblems(grid, planner, euclid, problems, name);
      const rgnav::FramedQuadtree& tree = planner.tree();
      const double nodesRatio = double(tree.nodeCount()) / double(tree.freeCellCount());
      std::printf("map=%s", name.c_str());
      printFigures(f);
      std::printf(" ratio_to_euclid_max=%.5f quads=%zu nodes=%zu free_cells=%zu nodes_ratio=%.4f tree_build_ms=%.1f planner_ms=%.1f"
                  " grid_astar_ms=%.1f speedup_vs_grid_astar=%.2f expansions_ratio=%.3f grid_astar_mismatches=%zu\n",
                  f.ratioToEuclidMax, tree.quads().size(), tree.nodeCount(), tree.freeCellCount(), nodesRatio, 1e3 * buildSeconds,
                  1e3 * f.plannerSeconds, 1e3 * f.gridAStarSeconds, f.speedup(),
                  f.gridAStarExpansions ? double(f.plannerExpansions) / double(f.gridAStarExpansions) : 0.0,
                  f.gridAStarMismatches);
      std::fflush(stdout);
      total.add(f);
      nodes += tree.nodeCount();
      freeCells += tree.freeCellCount();
      if (path.parent_path().filename() == "room") {
        roomNodes += tree.nodeCount();
        roomFreeCells += tree.freeCellCount();
      }
    }
    const double nodesRatio = roomFreeCells ? double(roomNodes) / double(roomFreeCells) : double(nodes) / double(freeCells);
    std::printf("planning: maps=%zu", options.maps.size());
    printFigures(total);
    std::printf(" nodes_ratio=%.4f speedup_vs_grid_astar=%.2f\n", nodesRatio, total.speedup());
    return total.invalid == 0 && total.solved == total.problems ? 0 : 1;
  } catch (const po::error& e) {
    std::cerr << "rgnav-eval-planning: " << e.what() << "\n" << desc << std::endl;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-eval-planning: " << e.what() << std::endl;
    return 1;
  }
}
