// rgnav-plan: plans a path on an RG map (thesis 5.4) and prints its target poses.
//   rgnav-plan [--naming H:P --robot NAME] --from x,y[,theta] <goal> [--svg F] [--png F]
//       plans through the PathPlanning module of a running set;
//   rgnav-plan --map F.rgmap.json [--config F] --from x,y[,theta] <goal> [--svg F] [--png F]
//       plans in this process on an exported map (core/rgmap/export/RGMAP_JSON.md) with the
//       module's parameters (default: the code's, which config/modules/pathplanning.yaml holds).
// <goal>: --to x,y (a point of the map frame) | --to-region ID|NAME (digits only: an ID) |
// --to-object NAME (a named object: a free pose in front of it).
// Prints "plan <id>: length=… m targets=… crossings=… regions=<start>-><goal> map_revision=…",
// then one line per target pose in driving order ("target <k>: x=… y=… theta=… region=…") and
// per crossing point passed; --svg/--png write the map with the path and the targets drawn (the
// RG Map's own pictures, PlanPicture.h). Coordinates and IDs are checked (StrictArguments.h)
// before anything is asked. Exit 0 with a plan, 3 when there is no path (the reason on stderr),
// 2 on any other error.
#include <cstdio>
#include <iostream>
#include <optional>

#include "clientlibs/pathplanning/KernelMapCache.h"
#include "clientlibs/pathplanning/PathPlanningClient.h"
#include "core/nav/grid/PlanningErrors.h"
#include "core/nav/planning/PlanningMapJson.h"
#include "core/nav/planning/RoutePlannerConfigYaml.h"
#include "tools/common/CommandLine.h"
#include "tools/common/StrictArguments.h"
#include "tools/common/ToolClient.h"
#include "tools/plan/PlanPicture.h"

namespace po = boost::program_options;
using namespace rgnav;

namespace {

constexpr int kNoPath = 3;

// "x,y" or, where `withTheta`, "x,y,theta": finite numbers.
Pose2D poseArgument(const std::string& text, const std::string& argument, bool withTheta) {
  std::vector<double> values;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t comma = text.find(',', begin);
    values.push_back(parseFiniteNumber(text.substr(begin, comma - begin), argument));
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  if (values.size() != 2 && !(withTheta && values.size() == 3))
    throw ArgumentError(argument, text, withTheta ? "is not x,y or x,y,theta" : "is not x,y");
  return {values[0], values[1], values.size() == 3 ? values[2] : 0.0};
}

PlanGoal goalArgument(const std::string& to, const std::string& toRegion, const std::string& toObject) {
  if (int(!to.empty()) + int(!toRegion.empty()) + int(!toObject.empty()) != 1)
    throw InvalidArgumentError("give exactly one goal: --to x,y, --to-region ID|NAME or --to-object NAME");
  if (!to.empty()) {
    const Pose2D p = poseArgument(to, "--to", false);
    return PlanGoal::at({p.x, p.y});
  }
  if (!toObject.empty()) return PlanGoal::atObject(toObject);
  if (toRegion.find_first_not_of("0123456789") == std::string::npos)
    return PlanGoal::inRegion(RegionId(parseId(toRegion, "--to-region")));
  return PlanGoal::inRegionNamed(toRegion);
}

void print(const PlanRecord& r) {
  const Plan& p = r.plan;
  std::printf("plan %llu: length=%.2f m targets=%zu crossings=%zu regions=%llu->%llu map_revision=%llu\n",
              static_cast<unsigned long long>(r.id), p.lengthM, p.targets.size(), p.route.size(),
              static_cast<unsigned long long>(p.startRegion.value()), static_cast<unsigned long long>(p.goalRegion.value()),
              static_cast<unsigned long long>(p.mapRevision));
  for (std::size_t k = 0; k < p.targets.size(); ++k) {
    const TargetPose& t = p.targets[k];
    std::printf("target %zu: x=%.3f y=%.3f theta=%.3f region=%llu\n", k + 1, t.pose.x, t.pose.y, t.pose.theta,
                static_cast<unsigned long long>(t.region.value()));
  }
  for (const GraphNodeView& n : p.route)
    std::printf("crossing gateway=%llu side=%zu region=%llu at=%.2f,%.2f\n", static_cast<unsigned long long>(n.gateway.value()),
                n.side, static_cast<unsigned long long>(n.region.value()), n.position.x(), n.position.y());
}

}  // namespace

int main(int argc, char** argv) {
  std::string naming, robot, mapFile, configFile, from, to, toRegion, toObject, svg, png;
  po::options_description desc("rgnav-plan --from x,y[,theta] (--to x,y | --to-region ID|NAME | --to-object NAME) [options]");
  desc.add_options()
      ("help", "this text")
      ("naming", po::value(&naming)->default_value(""), "naming service host:port (default: RGNAV_NAMING)")
      ("robot", po::value(&robot)->default_value(""), "robot name (default: RGNAV_ROBOT or tumbot)")
      ("map", po::value(&mapFile)->default_value(""), "plan offline on this exported map (.rgmap.json)")
      ("config", po::value(&configFile)->default_value(""), "--map: the planner's parameters (config/modules/pathplanning.yaml)")
      ("from", po::value(&from)->required(), "start x,y[,theta] (map frame, m, rad)")
      ("to", po::value(&to)->default_value(""), "goal point x,y (map frame, m)")
      ("to-region", po::value(&toRegion)->default_value(""), "goal region: its ID, or its name")
      ("to-object", po::value(&toObject)->default_value(""), "goal: the object of this name")
      ("svg", po::value(&svg)->default_value(""), "write the map with the path as SVG here")
      ("png", po::value(&png)->default_value(""), "write the map with the path as PNG here");
  try {
    if (!parseCommandLine(argc, argv, desc)) return 0;
    const Pose2D start = poseArgument(from, "--from", true);
    const PlanGoal goal = goalArgument(to, toRegion, toObject);
    if (mapFile.empty() && !configFile.empty()) throw InvalidArgumentError("--config goes with --map");
    PlanRecord record;
    std::optional<PlanningMap> map;
    if (!mapFile.empty()) {
      RoutePlanner planner(configFile.empty() ? RoutePlannerConfig{} : loadRoutePlannerConfig(configFile));
      map = loadPlanningMap(mapFile);
      planner.setMap(*map);
      record = {1, 0, start, goal, planner.plan(start, goal)};
    } else {
      const ClientSettings settings = toolClientSettings(naming, robot);
      PathPlanningClient planning(settings);
      record = planning.plan(start, goal);
      if (!svg.empty() || !png.empty()) {
        RgMappingKernelClient kernel(settings);
        KernelMapCache cache(kernel);
        cache.refresh();
        map = cache.map();
      }
    }
    print(record);
    if (!svg.empty()) writePlanSvg(svg, *map, record);
    if (!png.empty()) writePlanPng(png, *map, record);
    return 0;
  } catch (const po::error& e) {
    std::cerr << "rgnav-plan: " << e.what() << "\n" << desc << std::endl;
  } catch (const ModuleUnavailableError& e) {
    reportUnreachable("rgnav-plan", e, true);
  } catch (const Error& e) {
    const bool noPath = dynamic_cast<const NoPathError*>(&e) || dynamic_cast<const StartBlockedError*>(&e) ||
                        dynamic_cast<const GoalBlockedError*>(&e);
    std::cerr << "rgnav-plan: " << (noPath ? "no path: " : "") << e.what() << std::endl;
    if (noPath) return kNoPath;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-plan: " << e.what() << std::endl;
  }
  return 2;
}
