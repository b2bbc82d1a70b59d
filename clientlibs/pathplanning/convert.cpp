// Conversions between PathPlanning.idl types and the route planner's (see convert.h).
#include "clientlibs/pathplanning/convert.h"

#include "clientlibs/common/convert.h"
#include "clientlibs/gatewaydetection/convert.h"
#include "clientlibs/rgmappingkernel/convert.h"

namespace rgnav {
namespace {

RGNav::PlanGoalKind toIdl(PlanGoal::Kind kind) {
  switch (kind) {
    case PlanGoal::Kind::Point: return RGNav::GOAL_POINT;
    case PlanGoal::Kind::Region: return RGNav::GOAL_REGION;
    case PlanGoal::Kind::RegionName: return RGNav::GOAL_REGION_NAME;
    case PlanGoal::Kind::Object: return RGNav::GOAL_OBJECT;
  }
  throw InvalidArgumentError("unknown goal kind");
}

PlanGoal::Kind fromIdl(RGNav::PlanGoalKind kind) {
  switch (kind) {
    case RGNav::GOAL_POINT: return PlanGoal::Kind::Point;
    case RGNav::GOAL_REGION: return PlanGoal::Kind::Region;
    case RGNav::GOAL_REGION_NAME: return PlanGoal::Kind::RegionName;
    case RGNav::GOAL_OBJECT: return PlanGoal::Kind::Object;
    default: break;
  }
  throw InvalidArgumentError("unknown goal kind " + std::to_string(static_cast<int>(kind)));
}

}  // namespace

RGNav::PlanGoal toIdl(const PlanGoal& goal) {
  return RGNav::PlanGoal{toIdl(goal.kind), toIdl(goal.point), goal.region.value(), goal.name.c_str()};
}

PlanGoal fromIdl(const RGNav::PlanGoal& goal) {
  return {fromIdl(goal.kind), fromIdl(goal.point), RegionId(goal.region), goal.name.in()};
}

RGNav::TargetPose toIdl(const TargetPose& target) { return {toIdl(target.pose), target.region.value()}; }

TargetPose fromIdl(const RGNav::TargetPose& target) { return {fromIdl(target.pose), RegionId(target.region)}; }

RGNav::PlanInfo toIdl(const PlanRecord& p) {
  RGNav::PlanInfo out;
  out.id = p.id;
  out.request = p.request;
  out.mapRevision = p.plan.mapRevision;
  out.start = toIdl(p.start);
  out.goal = toIdl(p.goal);
  out.targets = toIdlSeq<RGNav::TargetPoseSeq>(p.plan.targets, [](const TargetPose& t) { return toIdl(t); });
  out.route = toIdlSeq<RGNav::RgNodeSeq>(p.plan.route, [](const GraphNodeView& n) { return toIdl(n); });
  out.path = toIdl(p.plan.path);
  out.length = p.plan.lengthM;
  out.startRegion = p.plan.startRegion.value();
  out.goalRegion = p.plan.goalRegion.value();
  return out;
}

PlanRecord fromIdl(const RGNav::PlanInfo& p) {
  PlanRecord out;
  out.id = p.id;
  out.request = p.request;
  out.start = fromIdl(p.start);
  out.goal = fromIdl(p.goal);
  out.plan.targets = fromIdlSeq<std::vector<TargetPose>>(p.targets, [](const RGNav::TargetPose& t) { return fromIdl(t); });
  out.plan.route = fromIdlSeq<std::vector<GraphNodeView>>(p.route, [](const RGNav::RgNode& n) { return fromIdl(n); });
  out.plan.path = fromIdl(p.path);
  out.plan.lengthM = p.length;
  out.plan.startRegion = RegionId(p.startRegion);
  out.plan.goalRegion = RegionId(p.goalRegion);
  out.plan.mapRevision = p.mapRevision;
  return out;
}

}  // namespace rgnav
