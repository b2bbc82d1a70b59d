// RoutePlanner: the RG route joined with region paths (see the header).
#include "core/nav/planning/RoutePlanner.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <queue>
#include <set>
#include <sstream>

#include "core/common/Errors.h"
#include "core/lines/ScanPoints.h"
#include "core/nav/grid/PlanningErrors.h"
#include "core/nav/planning/CellPoints.h"
#include "core/nav/planning/RegionGrid.h"
#include "core/nav/planning/RegionOverlaps.h"
#include "core/nav/planning/TargetSpacing.h"

namespace rgnav {

namespace {

constexpr double kUnreachable = std::numeric_limits<double>::infinity();

using Polyline = std::vector<Eigen::Vector2d>;

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

// A region's planning grid, its planner and the planner's fields to the route nodes in it.
struct RoutePlanner::RegionEntry {
  const RegionView* view = nullptr;
  RegionGrid grid;
  std::unique_ptr<FramedQuadtreePlanner> planner;
  std::map<std::size_t, std::optional<FramedQuadtreePlanner::Field>> fields;  // by route node
  std::map<std::size_t, std::optional<Eigen::Vector2d>> placements;          // by route node
  std::optional<std::set<std::int32_t>> routeComponents;  // the planner's components holding a route node

  Eigen::Vector2d toRegion(const Eigen::Vector2d& mapPoint) const {
    return transformPoint(inverse(view->summary.frame), mapPoint);
  }
  Eigen::Vector2d toMap(const Eigen::Vector2d& regionPoint) const {
    return transformPoint(view->summary.frame, regionPoint);
  }
  bool freeAt(const Eigen::Vector2d& mapPoint) const { return grid.freeAt(toRegion(mapPoint)); }
  std::optional<Eigen::Vector2d> nearestFree(const Eigen::Vector2d& mapPoint, double maxM, bool overWalls = false,
                                             const std::function<bool(CellIndex)>& usable = nullptr) const {
    const auto p = grid.nearestFree(toRegion(mapPoint), maxM, overWalls, usable);
    if (!p) return std::nullopt;
    return toMap(*p);
  }
  Eigen::Vector2d cells(const Eigen::Vector2d& mapPoint) const { return grid.toCells(toRegion(mapPoint)); }
  // The planner's component of the free cell a point lies in; none off the free cells.
  std::optional<std::int32_t> componentAt(const Eigen::Vector2d& mapPoint) const {
    const auto cell = freeCellAt(grid.grid, cells(mapPoint));
    if (!cell) return std::nullopt;
    return planner->tree().componentOf(*cell);
  }
  // A planner's path in the map frame, its ends exactly `from` and `to`.
  Polyline inMap(const CellUnitPath& path, const Eigen::Vector2d& from, const Eigen::Vector2d& to) const {
    Polyline out;
    out.reserve(path.points.size());
    for (const Eigen::Vector2d& c : path.points) out.push_back(toMap(grid.toRegion(c)));
    out.front() = from;
    out.back() = to;
    return out;
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
  // grids as they are planned on next. The same revision keeps the grids of the regions whose
  // summary is unchanged; scans stacked into the current region change its summary (and its
  // freespace) without a kernel event, so its grid, and the route graph over the regions' free
  // cells, are built anew.
  if (map.revision != map_.revision) {
    map_ = std::move(map);
    regions_.clear();
    routeGraph_.reset();
    return;
  }
  for (auto it = regions_.begin(); it != regions_.end();) {
    const auto view = std::find_if(map.regions.begin(), map.regions.end(),
                                   [&](const RegionView& r) { return r.summary.id == it->first; });
    if (view == map.regions.end() || !(view->summary == it->second->view->summary)) {
      it = regions_.erase(it);
      routeGraph_.reset();
    } else {
      it->second->view = &*view;  // the vector's elements stay where they are when it moves below
      ++it;
    }
  }
  map_ = std::move(map);
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
      const auto p = region.nearestFree(region.toMap(region.view->centroid), reach, true);
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
          const auto p = region.nearestFree(towardStart, reach, true);
          if (!p) throw NoPathError("no free pose in front of object \"" + goal.name + "\"");
          const Eigen::Vector2d facing = centre - *p;
          return {*p, *p, {r.summary.id}, std::atan2(facing.y(), facing.x())};
        }
      throw NoPathError("no object is named \"" + goal.name + "\"");
  }
  throw InvalidArgumentError("route planner: unknown goal kind");
}

bool RoutePlanner::passageFree(const PassageEnd& a, const PassageEnd& b,
                               const std::optional<Eigen::Vector2d>& middle) const {
  // Every half cell along the line (through the door's middle) lies on a free cell of a region
  // (the two ends' first: a hallway area's square may lie in a third), except near the ends,
  // which may lie in the inflation and are placed on free cells, and near a door's middle, where
  // both regions' freespace ends at the door line.
  const RegionEntry &ra = entry(a.region), &rb = entry(b.region);
  const auto freeAlong = [&](const std::vector<Eigen::Vector2d>& line, double endSlack) {
    for (std::size_t i = 1; i < line.size(); ++i) {
      const Eigen::Vector2d from = line[i - 1], to = line[i];
      const int samples = std::max(1, static_cast<int>(std::ceil((to - from).norm() / (0.5 * config_.gridResolutionM))));
      for (int k = 0; k <= samples; ++k) {
        const Eigen::Vector2d p = from + (to - from) * (double(k) / samples);
        if ((p - line.front()).norm() < endSlack || (p - line.back()).norm() < endSlack) continue;
        if (middle && (p - *middle).norm() < config_.robotRadiusM) continue;
        if (!ra.freeAt(p) && !rb.freeAt(p) && regionsAt(p).empty()) return false;
      }
    }
    return true;
  };
  if (a.crossing == b.crossing) {
    // One crossing point near two regions: joined only if the robot gets from where it is placed
    // in one to where it is placed in the other over free cells (a point in the wall between two
    // rooms is near both and joins neither).
    const auto pa = ra.nearestFree(a.position, config_.crossingSnapM, true);
    const auto pb = rb.nearestFree(b.position, config_.crossingSnapM, true);
    return pa && pb && freeAlong({*pa, *pb}, 0.0);
  }
  return freeAlong(middle ? std::vector{a.position, *middle, b.position} : std::vector{a.position, b.position},
                   config_.crossingSnapM);
}

std::optional<Eigen::Vector2d> RoutePlanner::doorMiddle(GatewayId id) const {
  for (const GatewayView& gateway : map_.gateways)
    if (gateway.id == id && gateway.door && gateway.gatewayPoints.size() == 2)
      return 0.5 * (gateway.gatewayPoints[0] + gateway.gatewayPoints[1]);
  return std::nullopt;
}

std::vector<RoutePlanner::Passage> RoutePlanner::findPassages() const {
  std::vector<Passage> out;
  for (std::size_t i = 0; i < map_.regions.size(); ++i)
    for (std::size_t k = i + 1; k < map_.regions.size(); ++k) {
      const RegionView &a = map_.regions[i], &b = map_.regions[k];
      for (const Eigen::Vector2d& p : overlapTransfers(entry(a.summary.id).grid, a.summary.frame, entry(b.summary.id).grid,
                                                       b.summary.frame, config_.overlapSampleM, config_.overlapMinAreaM2))
        out.push_back({GatewayId{}, {{p, a.summary.id, 0}, {p, b.summary.id, 0}}, {{0, 1}}});
    }
  for (const GatewayView& gateway : map_.gateways) {
    if (!gateway.sideA.isNone() && !gateway.sideB.isNone()) continue;  // in the RG graph
    Passage passage{gateway.id, {}, {}};
    for (std::size_t c = 0; c < gateway.crossingPoints.size(); ++c)
      for (const RegionView& r : map_.regions)
        if (entry(r.summary.id).nearestFree(gateway.crossingPoints[c], config_.crossingSnapM, true))
          passage.ends.push_back({gateway.crossingPoints[c], r.summary.id, c});
    const std::optional<Eigen::Vector2d> middle = doorMiddle(gateway.id);
    for (std::size_t i = 0; i < passage.ends.size(); ++i)
      for (std::size_t k = i + 1; k < passage.ends.size(); ++k)
        if (passageFree(passage.ends[i], passage.ends[k], middle)) passage.links.push_back({i, k});
    if (!passage.links.empty()) out.push_back(std::move(passage));
  }
  return out;
}

// The route search's nodes: the RG graph's crossing points, then the ends of every other passage;
// per node, the links that do not pass through a region (gateway edges at their learned cost,
// passage links at their length), and per region the nodes in it. The start and the goal join
// per query.
struct RoutePlanner::RouteGraph {
  struct Node {
    Eigen::Vector2d position;
    RegionId region;
    std::optional<GraphNodeView> crossing;  // a gateway's crossing point (to be placed on a free cell)
  };
  std::vector<Node> nodes;
  std::vector<std::vector<std::pair<std::size_t, double>>> jumps;  // per node: (to, cost)
  std::map<RegionId, std::vector<std::size_t>> members;
  std::map<std::pair<std::size_t, std::size_t>, double> learned;  // region edges' learned costs
};

const RoutePlanner::RouteGraph& RoutePlanner::routeGraph() const {
  if (routeGraph_) return *routeGraph_;
  auto made = std::make_shared<RouteGraph>();
  for (const GraphNodeView& n : map_.graph.nodes) made->nodes.push_back({n.position, n.region, n});
  made->jumps.resize(made->nodes.size());
  for (const GraphEdgeView& e : map_.graph.edges) {
    if (e.throughGateway()) {
      made->jumps[e.from].push_back({e.to, e.costM});
      made->jumps[e.to].push_back({e.from, e.costM});
    } else {
      made->learned[std::minmax(e.from, e.to)] = e.costM;
    }
  }
  for (const Passage& passage : findPassages()) {
    const std::size_t first = made->nodes.size();
    for (const PassageEnd& end : passage.ends) {
      std::optional<GraphNodeView> crossing;
      if (!passage.gateway.isNone()) crossing = GraphNodeView{passage.gateway, end.crossing, end.region, end.position};
      made->nodes.push_back({end.position, end.region, crossing});
    }
    made->jumps.resize(made->nodes.size());
    for (const auto& [i, k] : passage.links) {
      const double length = (passage.ends[i].position - passage.ends[k].position).norm();
      made->jumps[first + i].push_back({first + k, length});
      made->jumps[first + k].push_back({first + i, length});
    }
  }
  for (std::size_t i = 0; i < made->nodes.size(); ++i) made->members[made->nodes[i].region].push_back(i);
  routeGraph_ = made;
  return *routeGraph_;
}

std::optional<Eigen::Vector2d> RoutePlanner::placed(RegionEntry& r, std::size_t node) const {
  const RouteGraph::Node& n = routeGraph().nodes[node];
  if (!n.crossing) return n.position;
  if (const auto it = r.placements.find(node); it != r.placements.end()) return it->second;
  return r.placements.emplace(node, r.nearestFree(n.position, config_.crossingSnapM, true)).first->second;
}

bool RoutePlanner::leadsOn(RegionId region, std::optional<std::int32_t> component, const Ends& goal) const {
  if (!component) return false;
  RegionEntry& r = entry(region);
  if (std::find(goal.regions.begin(), goal.regions.end(), region) != goal.regions.end() &&
      r.componentAt(goal.point) == component)
    return true;
  if (!r.routeComponents) {
    r.routeComponents.emplace();
    if (const auto it = routeGraph().members.find(region); it != routeGraph().members.end())
      for (std::size_t node : it->second)
        if (const auto at = placed(r, node))
          if (const auto c = r.componentAt(*at)) r.routeComponents->insert(*c);
  }
  return r.routeComponents->count(*component) > 0;
}

RoutePlanner::Ends RoutePlanner::startOf(const Pose2D& start, const Ends& goal) const {
  const Eigen::Vector2d p(start.x, start.y);
  if (!p.allFinite()) throw InvalidArgumentError("route planner: the start is not a finite point");
  const std::vector<RegionId> in = regionsAt(p);
  Ends ends{p, p, {}, std::nullopt};
  for (RegionId r : in)
    if (leadsOn(r, entry(r).componentAt(p), goal)) ends.regions.push_back(r);
  if (!ends.regions.empty()) return ends;
  // Placed on the nearest free cell within startSnapM that leads on.
  double best = kUnreachable;
  for (const RegionView& r : map_.regions) {
    const RegionEntry& region = entry(r.summary.id);
    const auto snapped = region.nearestFree(p, config_.startSnapM, false, [&](CellIndex cell) {
      return leadsOn(r.summary.id, region.planner->tree().componentOf(cell), goal);
    });
    if (snapped && (*snapped - p).norm() < best) {
      best = (*snapped - p).norm();
      ends.point = *snapped;
      ends.regions = {r.summary.id};
    }
  }
  if (!ends.regions.empty()) return ends;
  const std::string within = " (none within " + std::to_string(config_.startSnapM) + " m)";
  if (in.empty()) throw NoPathError("the start " + text(p) + " lies outside every region" + within);
  throw NoPathError("the start " + text(p) + " lies in free cells of region " + std::to_string(in.front().value()) +
                    " cut off from its routes and the goal, and no free cell leads on" + within);
}

Plan RoutePlanner::plan(const Pose2D& startPose, const PlanGoal& goal) const {
  const Ends end = goalOf(goal, {startPose.x, startPose.y});
  const Ends start = startOf(startPose, end);

  // The route graph's nodes, then the start and the goal.
  const RouteGraph& graph = routeGraph();
  std::vector<RouteGraph::Node> nodes = graph.nodes;
  const std::size_t s = nodes.size(), g = nodes.size() + 1;
  nodes.push_back({start.point, RegionId{}, std::nullopt});
  nodes.push_back({end.point, RegionId{}, std::nullopt});

  // Links through a region. A node's point is placed on a free cell (a crossing point in a blocked
  // cell, at a narrow door, moves to the nearest free one); a link to a node costs what the
  // planner's field to that node says (one field per node and map revision, built on first use),
  // a link from the start to the goal in one region is planned directly.
  const auto placedNode = [&](RegionEntry& r, std::size_t i) -> std::optional<Eigen::Vector2d> {
    return i < graph.nodes.size() ? placed(r, i) : nodes[i].position;
  };
  const auto fieldOf = [&](RegionEntry& r, std::size_t node) -> const std::optional<FramedQuadtreePlanner::Field>& {
    if (const auto it = r.fields.find(node); it != r.fields.end()) return it->second;
    std::optional<FramedQuadtreePlanner::Field> field;
    if (const auto at = placedNode(r, node)) field = r.planner->fieldTo(r.cells(*at));
    return r.fields.emplace(node, std::move(field)).first->second;
  };
  // The node a link's field leads to, and the link's other end (the goal's links use the field of
  // the node they leave: costs are symmetric).
  const auto fieldEnds = [&](std::size_t a, std::size_t b) { return b == g ? std::pair{a, b} : std::pair{b, a}; };
  std::map<RegionId, std::optional<CellUnitPath>> direct;  // start to goal, by region
  const auto directPath = [&](RegionId region) -> const std::optional<CellUnitPath>& {
    if (const auto it = direct.find(region); it != direct.end()) return it->second;
    RegionEntry& r = entry(region);
    std::optional<CellUnitPath> path;
    try {
      path = r.planner->plan(r.cells(start.point), r.cells(end.point));
    } catch (const Error&) {  // an end blocked in this region, or no connection
    }
    return direct.emplace(region, std::move(path)).first->second;
  };
  const auto linkCost = [&](RegionId region, std::size_t a, std::size_t b) {
    RegionEntry& r = entry(region);
    if (a == s && b == g) {
      const auto& path = directPath(region);
      return path ? path->length * r.grid.grid.resolution() : kUnreachable;
    }
    const auto [target, from] = fieldEnds(a, b);
    const auto& field = fieldOf(r, target);
    const auto point = placedNode(r, from);
    if (!field || !point) return kUnreachable;
    return r.planner->costTo(*field, r.cells(*point)).value_or(kUnreachable) * r.grid.grid.resolution();
  };
  const auto linkPath = [&](RegionId region, std::size_t a, std::size_t b) {
    RegionEntry& r = entry(region);
    if (a == s && b == g) return r.inMap(*directPath(region), start.point, end.point);
    const auto [target, from] = fieldEnds(a, b);
    const Eigen::Vector2d fromAt = *placedNode(r, from), targetAt = *placedNode(r, target);
    Polyline path = r.inMap(r.planner->pathTo(*fieldOf(r, target), r.cells(fromAt)), fromAt, targetAt);
    if (nodes[from].crossing) path.insert(path.begin(), nodes[from].position);
    if (nodes[target].crossing) path.push_back(nodes[target].position);
    if (target != b) std::reverse(path.begin(), path.end());
    return path;
  };

  // Lazy A* (Cohen, Phillips, Likhachev, "Planning Single-Arm Manipulations with n-Arm Robots",
  // SoCS 2014: lazy weighted A*, here unweighted): a link through a region enters the open list
  // with its lower bound (its learned cost or straight-line length) and its cost is looked up
  // only when that entry comes first, so that fields are built for the nodes near the best route,
  // not for every node relaxed.
  struct Entry {
    double f = 0.0, g = 0.0;
    std::size_t node = 0, from = 0;
    RegionId region;        // none: through a gateway or an overlap transfer
    bool verified = false;  // g is the true cost via `from`
    bool operator>(const Entry& o) const { return f > o.f; }
  };
  struct Via {
    std::size_t from = 0;
    RegionId region;
  };
  std::vector<double> best(nodes.size(), kUnreachable);  // best verified g
  std::vector<bool> closed(nodes.size(), false);
  std::vector<std::optional<Via>> via(nodes.size());
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  const auto heuristic = [&](std::size_t i) { return (nodes[i].position - end.point).norm(); };
  const auto push = [&](std::size_t from, std::size_t to, double g, RegionId region, bool verified) {
    if (!std::isfinite(g) || closed[to] || g >= best[to]) return;
    if (verified) best[to] = g;
    open.push({g + heuristic(to), g, to, from, region, verified});
  };
  const auto lowerBound = [&](std::size_t a, std::size_t b) {
    const double straight = (nodes[a].position - nodes[b].position).norm();
    const auto it = graph.learned.find(std::minmax(a, b));
    return it == graph.learned.end() ? straight : std::max(straight, it->second);
  };
  const auto inEnds = [](const Ends& e, RegionId r) { return std::find(e.regions.begin(), e.regions.end(), r) != e.regions.end(); };
  const auto throughRegion = [&](std::size_t u, RegionId r, double at) {
    if (inEnds(end, r)) push(u, g, at + lowerBound(u, g), r, false);
    if (const auto it = graph.members.find(r); it != graph.members.end())
      for (std::size_t v : it->second)
        if (v != u) push(u, v, at + lowerBound(u, v), r, false);
  };

  push(s, s, 0.0, RegionId{}, true);
  while (!open.empty()) {
    const Entry e = open.top();
    open.pop();
    if (closed[e.node]) continue;
    if (!e.verified) {
      push(e.from, e.node, best[e.from] + std::max(e.g - best[e.from], linkCost(e.region, e.from, e.node)), e.region, true);
      continue;
    }
    closed[e.node] = true;
    if (e.node != s) via[e.node] = Via{e.from, e.region};
    if (e.node == g) break;
    const double at = best[e.node];
    if (e.node == s) {
      for (RegionId r : start.regions) throughRegion(s, r, at);
      continue;
    }
    throughRegion(e.node, nodes[e.node].region, at);
    for (const auto& [v, cost] : graph.jumps[e.node]) push(e.node, v, at + cost, RegionId{}, true);
  }
  if (!via[g]) {
    std::string from, to;
    for (RegionId r : start.regions) from += (from.empty() ? "" : ", ") + std::to_string(r.value());
    for (RegionId r : end.regions) to += (to.empty() ? "" : ", ") + std::to_string(r.value());
    throw NoPathError("no route from region " + from + " to region " + to + " in the RG map");
  }

  // The legs in driving order, each as planned in its region (no shortcut across legs: measured
  // on the tuning maps, taut shortcuts across regions brought more paths too close to real walls
  // than the legs' own wall costs do). A door is passed through the middle of its gateway points:
  // the crossing points lie off the door at either side, not necessarily in line with its middle,
  // and the straight line between them can graze a jamb.
  std::vector<std::size_t> order{g};
  while (order.back() != s) order.push_back(via[order.back()]->from);
  std::reverse(order.begin(), order.end());
  Plan out;
  out.mapRevision = map_.revision;
  std::vector<RegionId> regions;  // the regions passed, in driving order
  if (start.given != start.point) out.path.push_back(start.given);
  out.path.push_back(start.point);
  for (std::size_t k = 1; k < order.size(); ++k) {
    const std::size_t a = order[k - 1], b = order[k];
    if (nodes[b].crossing) out.route.push_back(*nodes[b].crossing);
    const Via& step = *via[b];
    const RegionId region = step.region.isNone() ? nodes[b].region : step.region;
    if (regions.empty() || regions.back() != region) regions.push_back(region);
    Polyline leg = step.region.isNone() ? Polyline{nodes[a].position, nodes[b].position} : linkPath(region, a, b);
    const bool acrossGateway = step.region.isNone() && nodes[b].crossing && nodes[a].position != nodes[b].position;
    if (const auto middle = acrossGateway ? doorMiddle(nodes[b].crossing->gateway) : std::nullopt)
      leg.insert(leg.begin() + 1, *middle);
    for (std::size_t i = 1; i < leg.size(); ++i)
      if ((leg[i] - out.path.back()).norm() > 1e-9) out.path.push_back(leg[i]);
  }
  out.lengthM = polylineLength(out.path);
  out.startRegion = regions.front();
  out.goalRegion = regions.back();

  // Targets, each in the first region from the previous target's on whose free cells it lies.
  std::size_t current = 0;
  for (const Pose2D& pose : targetsAlong(out.path, config_.targetMinSpacingM, config_.targetMaxSpacingM, end.heading)) {
    for (std::size_t k = current; k < regions.size(); ++k)
      if (entry(regions[k]).freeAt({pose.x, pose.y})) {
        current = k;
        break;
      }
    out.targets.push_back({pose, regions[current]});
  }
  if (!out.targets.empty()) out.targets.back().region = out.goalRegion;
  return out;
}

}  // namespace rgnav
