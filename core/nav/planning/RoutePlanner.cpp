// RoutePlanner: the RG route joined with region paths (see the header).
#include "core/nav/planning/RoutePlanner.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <queue>
#include <sstream>

#include "core/common/Errors.h"
#include "core/lines/ScanPoints.h"
#include "core/nav/grid/PlanningErrors.h"
#include "core/nav/planning/RegionGrid.h"
#include "core/nav/planning/TargetSpacing.h"

namespace rgnav {

namespace {

constexpr double kUnreachable = std::numeric_limits<double>::infinity();

using Polyline = std::vector<Eigen::Vector2d>;

double polylineLength(const Polyline& line) {
  double length = 0.0;
  for (std::size_t i = 1; i < line.size(); ++i) length += (line[i] - line[i - 1]).norm();
  return length;
}

std::string text(const Eigen::Vector2d& p) {
  std::ostringstream out;
  out.precision(2);
  out << std::fixed << "(" << p.x() << ", " << p.y() << ")";
  return out.str();
}

}  // namespace

void validate(const RoutePlannerConfig& c) {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  const auto notNegative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  if (!notNegative(c.robotRadiusM)) throw ConfigError("route planner: robot_radius_m must be >= 0");
  if (!positive(c.gridResolutionM)) throw ConfigError("route planner: grid_resolution_m must be positive");
  if (!notNegative(c.startSnapM)) throw ConfigError("route planner: start_snap_m must be >= 0");
  if (!notNegative(c.crossingSnapM)) throw ConfigError("route planner: crossing_snap_m must be >= 0");
  if (!positive(c.targetMinSpacingM) || !std::isfinite(c.targetMaxSpacingM) || c.targetMaxSpacingM < c.targetMinSpacingM)
    throw ConfigError("route planner: 0 < target_min_spacing_m <= target_max_spacing_m must hold");
  validate(c.region);
}

// A region's planning grid, its planner and the region paths found between crossing points.
struct RoutePlanner::RegionEntry {
  const RegionView* view = nullptr;
  RegionGrid grid;
  std::unique_ptr<FramedQuadtreePlanner> planner;
  std::map<std::pair<std::size_t, std::size_t>, std::optional<Polyline>> between;  // graph node pairs

  Eigen::Vector2d toRegion(const Eigen::Vector2d& mapPoint) const {
    return transformPoint(inverse(view->summary.frame), mapPoint);
  }
  Eigen::Vector2d toMap(const Eigen::Vector2d& regionPoint) const {
    return transformPoint(view->summary.frame, regionPoint);
  }
  bool freeAt(const Eigen::Vector2d& mapPoint) const { return grid.freeAt(toRegion(mapPoint)); }
  std::optional<Eigen::Vector2d> nearestFree(const Eigen::Vector2d& mapPoint, double maxM) const {
    const auto p = grid.nearestFree(toRegion(mapPoint), maxM);
    if (!p) return std::nullopt;
    return toMap(*p);
  }
  // The region path between two free points (map frame), or none.
  std::optional<Polyline> path(const Eigen::Vector2d& from, const Eigen::Vector2d& to) const {
    try {
      const CellUnitPath cells = planner->plan(grid.toCells(toRegion(from)), grid.toCells(toRegion(to)));
      Polyline out;
      out.reserve(cells.points.size());
      for (const Eigen::Vector2d& c : cells.points) out.push_back(toMap(grid.toRegion(c)));
      out.front() = from;
      out.back() = to;
      return out;
    } catch (const Error&) {  // blocked ends or no connection
      return std::nullopt;
    }
  }
};

// Where a plan starts or ends: the point in the free cells of one or more regions, the point the
// caller gave (which may lie off the grid for a snapped start), and a heading to arrive with.
struct RoutePlanner::Ends {
  Eigen::Vector2d given = Eigen::Vector2d::Zero();
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  std::vector<RegionId> regions;
  std::optional<double> heading;
};

RoutePlanner::RoutePlanner(const RoutePlannerConfig& config) : config_(config) { validate(config_); }

void RoutePlanner::setMap(PlanningMap map) {
  // The map revision is the change marker the kernel gives: a new revision rebuilds the region
  // grids as they are planned on next; the same revision keeps them.
  const bool same = map.revision == map_.revision;
  map_ = std::move(map);
  if (!same) {
    regions_.clear();
    return;
  }
  for (auto it = regions_.begin(); it != regions_.end();) {
    const auto view = std::find_if(map_.regions.begin(), map_.regions.end(),
                                   [&](const RegionView& r) { return r.summary.id == it->first; });
    if (view == map_.regions.end()) {
      it = regions_.erase(it);
    } else {
      it->second->view = &*view;
      ++it;
    }
  }
}

RoutePlanner::RegionEntry& RoutePlanner::entry(RegionId region) const {
  if (const auto it = regions_.find(region); it != regions_.end()) return *it->second;
  const auto view = std::find_if(map_.regions.begin(), map_.regions.end(),
                                 [&](const RegionView& r) { return r.summary.id == region; });
  if (view == map_.regions.end()) throw NoPathError("region " + std::to_string(region.value()) + " is not in the map");
  auto made = std::make_shared<RegionEntry>();
  made->view = &*view;
  made->grid = buildRegionGrid(*view, config_.gridResolutionM, config_.robotRadiusM);
  made->planner = std::make_unique<FramedQuadtreePlanner>(made->grid.grid, config_.region);
  return *regions_.emplace(region, std::move(made)).first->second;
}

std::vector<RegionId> RoutePlanner::regionsAt(const Eigen::Vector2d& point) const {
  std::vector<RegionId> out;
  for (const RegionView& r : map_.regions)
    if (entry(r.summary.id).freeAt(point)) out.push_back(r.summary.id);
  return out;
}

RoutePlanner::Ends RoutePlanner::startOf(const Pose2D& start) const {
  const Eigen::Vector2d p(start.x, start.y);
  if (!p.allFinite()) throw InvalidArgumentError("route planner: the start is not a finite point");
  Ends ends{p, p, regionsAt(p), std::nullopt};
  if (!ends.regions.empty()) return ends;
  // Placed in the nearest region within startSnapM.
  double best = kUnreachable;
  for (const RegionView& r : map_.regions) {
    const auto snapped = entry(r.summary.id).nearestFree(p, config_.startSnapM);
    if (snapped && (*snapped - p).norm() < best) {
      best = (*snapped - p).norm();
      ends.point = *snapped;
      ends.regions = {r.summary.id};
    }
  }
  if (ends.regions.empty())
    throw NoPathError("the start " + text(p) + " lies outside every region (none within " +
                      std::to_string(config_.startSnapM) + " m)");
  return ends;
}

RoutePlanner::Ends RoutePlanner::goalOf(const PlanGoal& goal, const Eigen::Vector2d& start) const {
  const auto regionNamed = [&](const std::string& name) -> RegionId {
    for (const RegionView& r : map_.regions)
      if (r.summary.name == name) return r.summary.id;
    throw NoPathError("no region is named \"" + name + "\"");
  };
  switch (goal.kind) {
    case PlanGoal::Kind::Point: {
      if (!goal.point.allFinite()) throw InvalidArgumentError("route planner: the goal is not a finite point");
      Ends ends{goal.point, goal.point, regionsAt(goal.point), std::nullopt};
      if (!ends.regions.empty()) return ends;
      for (const RegionView& r : map_.regions)
        if (r.freespace.isFreeAt(entry(r.summary.id).toRegion(goal.point)))
          throw NoPathError("the goal " + text(goal.point) + " lies in an obstacle of region " +
                            std::to_string(r.summary.id.value()) + " (or closer to one than the robot radius)");
      throw NoPathError("the goal " + text(goal.point) + " lies outside every region");
    }
    case PlanGoal::Kind::Region:
    case PlanGoal::Kind::RegionName: {
      const RegionId id = goal.kind == PlanGoal::Kind::Region ? goal.region : regionNamed(goal.name);
      const RegionEntry& region = entry(id);
      const double reach = (region.view->boxMax - region.view->boxMin).norm() + 1.0;
      const auto p = region.nearestFree(region.toMap(region.view->centroid), reach);
      if (!p) throw NoPathError("region " + std::to_string(id.value()) + " has no free cell the robot fits in");
      return {*p, *p, {id}, std::nullopt};
    }
    case PlanGoal::Kind::Object:
      for (const RegionView& r : map_.regions)
        for (const RectangleObjectView& object : r.objects) {
          if (object.name != goal.name) continue;
          const RegionEntry& region = entry(r.summary.id);
          const Eigen::Vector2d centre = region.toMap({object.pose.x, object.pose.y});
          // In front of it: the free cell nearest to its centre, preferring the side the robot
          // comes from when two are about as near.
          const double reach = 0.5 * std::hypot(object.lengthM, object.widthM) + config_.robotRadiusM + 1.0;
          const Eigen::Vector2d towardStart = centre + (start - centre).normalized() * 1e-3;
          const auto p = region.nearestFree(towardStart, reach);
          if (!p) throw NoPathError("no free pose in front of object \"" + goal.name + "\"");
          const Eigen::Vector2d facing = centre - *p;
          return {*p, *p, {r.summary.id}, std::atan2(facing.y(), facing.x())};
        }
      throw NoPathError("no object is named \"" + goal.name + "\"");
  }
  throw InvalidArgumentError("route planner: unknown goal kind");
}

Plan RoutePlanner::plan(const Pose2D& startPose, const PlanGoal& goal) const {
  const Ends start = startOf(startPose);
  const Ends end = goalOf(goal, start.point);
  const auto& nodes = map_.graph.nodes;
  const std::size_t s = nodes.size(), g = nodes.size() + 1;
  const auto position = [&](std::size_t i) -> Eigen::Vector2d {
    return i == s ? start.point : (i == g ? end.point : nodes[i].position);
  };

  // The region path of a link, cached per region for crossing point pairs. A crossing point in a
  // blocked cell (inflation at a narrow door) is moved to the nearest free cell.
  std::map<std::pair<std::size_t, std::size_t>, std::pair<RegionId, std::optional<Polyline>>> endLinks;
  const auto regionPath = [&](RegionId region, std::size_t a, std::size_t b) -> const std::optional<Polyline>& {
    RegionEntry& r = entry(region);
    const bool crossings = a < s && b < s;
    if (crossings)
      if (const auto it = r.between.find({a, b}); it != r.between.end()) return it->second;
    const auto placed = [&](std::size_t i) -> std::optional<Eigen::Vector2d> {
      return i < s ? r.nearestFree(nodes[i].position, config_.crossingSnapM) : std::optional(position(i));
    };
    std::optional<Polyline> found;
    const auto from = placed(a), to = placed(b);
    if (from && to) found = r.path(*from, *to);
    if (found) {
      if (a < s) found->insert(found->begin(), nodes[a].position);
      if (b < s) found->push_back(nodes[b].position);
    }
    if (crossings) return r.between.emplace(std::pair{a, b}, std::move(found)).first->second;
    return endLinks.insert_or_assign({a, b}, std::pair{region, std::move(found)}).first->second.second;
  };

  // A* over crossing points plus start and goal; costs are discovered as edges are relaxed.
  struct Via {
    std::size_t from = 0;
    RegionId region;  // none: through a gateway
  };
  std::vector<double> cost(nodes.size() + 2, kUnreachable);
  std::vector<std::optional<Via>> via(nodes.size() + 2);
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  const auto heuristic = [&](std::size_t i) { return (position(i) - end.point).norm(); };
  const auto relax = [&](std::size_t from, std::size_t to, double edgeCost, RegionId region) {
    if (!std::isfinite(edgeCost) || cost[from] + edgeCost >= cost[to]) return;
    cost[to] = cost[from] + edgeCost;
    via[to] = Via{from, region};
    open.push({cost[to] + heuristic(to), to});
  };
  const auto linkCost = [&](RegionId region, std::size_t a, std::size_t b) {
    const auto& path = regionPath(region, a, b);
    return path ? polylineLength(*path) : kUnreachable;
  };
  const auto inEnds = [](const Ends& e, RegionId r) { return std::find(e.regions.begin(), e.regions.end(), r) != e.regions.end(); };

  cost[s] = 0.0;
  open.push({heuristic(s), s});
  std::vector<bool> closed(nodes.size() + 2, false);
  while (!open.empty()) {
    const std::size_t u = open.top().second;
    open.pop();
    if (closed[u]) continue;
    closed[u] = true;
    if (u == g) break;
    if (u == s) {
      for (RegionId r : start.regions) {
        if (inEnds(end, r)) relax(s, g, linkCost(r, s, g), r);
        for (std::size_t i = 0; i < nodes.size(); ++i)
          if (nodes[i].region == r) relax(s, i, linkCost(r, s, i), r);
      }
      continue;
    }
    if (inEnds(end, nodes[u].region)) relax(u, g, linkCost(nodes[u].region, u, g), nodes[u].region);
    for (const GraphEdgeView& e : map_.graph.edges) {
      if (e.from != u && e.to != u) continue;
      const std::size_t v = e.from == u ? e.to : e.from;
      if (closed[v]) continue;
      if (e.throughGateway())
        relax(u, v, e.costM, RegionId{});
      else
        relax(u, v, std::max(e.costM, linkCost(e.region, u, v)), e.region);
    }
  }
  if (!via[g]) {
    std::string from, to;
    for (RegionId r : start.regions) from += (from.empty() ? "" : ", ") + std::to_string(r.value());
    for (RegionId r : end.regions) to += (to.empty() ? "" : ", ") + std::to_string(r.value());
    throw NoPathError("no route from region " + from + " to region " + to + " in the RG graph");
  }

  // The legs in driving order.
  std::vector<std::size_t> order{g};
  while (order.back() != s) order.push_back(via[order.back()]->from);
  std::reverse(order.begin(), order.end());
  Plan out;
  out.mapRevision = map_.revision;
  out.startRegion = via[order[1]]->region.isNone() ? start.regions.front() : via[order[1]]->region;
  out.goalRegion = via[g]->region;
  std::vector<PathLeg> legs;
  legs.push_back({out.startRegion, {start.given}});
  for (std::size_t k = 1; k < order.size(); ++k) {
    const std::size_t a = order[k - 1], b = order[k];
    if (b < s) out.route.push_back(nodes[b]);
    const Via& step = *via[b];
    PathLeg leg;
    if (step.region.isNone()) {
      leg = {nodes[b].region, {nodes[a].position, nodes[b].position}};
    } else {
      const std::optional<Polyline>& path = regionPath(step.region, a, b);
      leg = {step.region, *path};
    }
    legs.push_back(std::move(leg));
  }
  for (const PathLeg& leg : legs)
    for (const Eigen::Vector2d& p : leg.points)
      if (out.path.empty() || (p - out.path.back()).norm() > 1e-9) out.path.push_back(p);
  out.lengthM = polylineLength(out.path);
  out.targets = targetsAlong(legs, config_.targetMinSpacingM, config_.targetMaxSpacingM, end.heading);
  return out;
}

}  // namespace rgnav
