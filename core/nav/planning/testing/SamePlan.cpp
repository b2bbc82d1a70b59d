// What differs between two plan records (see SamePlan.h).
#include "core/nav/planning/testing/SamePlan.h"

namespace rgnav::testing {
namespace {

bool sameGoal(const PlanGoal& a, const PlanGoal& b) {
  return a.kind == b.kind && a.point == b.point && a.region == b.region && a.name == b.name;
}

}  // namespace

std::string planDifference(const PlanRecord& a, const PlanRecord& b) {
  std::string out;
  const auto differs = [&](bool same, const char* what) {
    if (!same) out += std::string(out.empty() ? "" : ", ") + what;
  };
  differs(a.id == b.id, "id");
  differs(a.request == b.request, "request");
  differs(a.start == b.start, "start");
  differs(sameGoal(a.goal, b.goal), "goal");
  differs(a.plan.targets == b.plan.targets, "targets");
  differs(a.plan.route == b.plan.route, "route");
  differs(a.plan.path == b.plan.path, "path");
  differs(a.plan.lengthM == b.plan.lengthM, "length");
  differs(a.plan.startRegion == b.plan.startRegion && a.plan.goalRegion == b.plan.goalRegion, "regions");
  differs(a.plan.mapRevision == b.plan.mapRevision, "map revision");
  return out;
}

}  // namespace rgnav::testing
