// The Collision Avoidance module's drive checkpoint (see DriveCheckpoint.h).
#include "servers/collisionavoidance/DriveCheckpoint.h"

#include <nlohmann/json.hpp>

#include "core/common/JsonForms.h"
#include "servers/pathplanning/PlanStore.h"

namespace rgnav {
namespace {

using nlohmann::json;

constexpr const char* kFormat = "rgnav-drive";
constexpr int kVersion = 1;

DrivePhase phaseFrom(const json& j) {
  const int phase = integerFrom(j);
  if (phase < 0 || phase > static_cast<int>(DrivePhase::Failed))
    throw FormatError("<checkpoint>", 0, "unknown drive phase " + std::to_string(phase));
  return static_cast<DrivePhase>(phase);
}

}  // namespace

std::string serializeDrive(const DriveRecord& d) {
  const DriveProgress& p = d.progress;
  json targets = json::array();
  for (const TargetPose& t : d.targets) targets.push_back({{"pose", jsonPose(t.pose)}, {"region", t.region}});
  return json{{"format", kFormat},
              {"version", kVersion},
              {"request", p.request},
              {"phase", static_cast<int>(p.phase)},
              {"hasGoal", p.hasGoal},
              {"goal", planGoalJson(p.goal)},
              {"plan", p.plan},
              {"targetIndex", p.targetIndex},
              {"distanceLeft", jsonNumber(p.distanceLeftM)},
              {"chainsSent", p.chainsSent},
              {"replans", p.replans},
              {"reason", p.reason},
              {"targets", targets}}
             .dump() +
         "\n";
}

DriveRecord deserializeDrive(const std::string& text, const std::string& source) {
  return readingJson(source, [&] {
    const json j = json::parse(text);
    if (j.at("format") != kFormat || j.at("version") != kVersion)
      throw FormatError(source, 0, std::string("not a ") + kFormat + " version " + std::to_string(kVersion) + " file");
    DriveRecord d;
    DriveProgress& p = d.progress;
    p.request = integerFrom(j.at("request"));
    p.phase = phaseFrom(j.at("phase"));
    p.hasGoal = j.at("hasGoal").get<bool>();
    p.goal = planGoalFrom(j.at("goal"));
    p.plan = integerFrom(j.at("plan"));
    p.targetIndex = static_cast<std::uint32_t>(integerFrom(j.at("targetIndex")));
    p.distanceLeftM = numberFrom(j.at("distanceLeft"));
    p.chainsSent = integerFrom(j.at("chainsSent"));
    p.replans = static_cast<std::uint32_t>(integerFrom(j.at("replans")));
    p.reason = j.at("reason").get<std::string>();
    for (const json& t : j.at("targets")) d.targets.push_back({poseFrom(t.at("pose")), integerFrom(t.at("region"))});
    p.targetCount = static_cast<std::uint32_t>(d.targets.size());
    if (p.targetIndex > p.targetCount) throw FormatError(source, 0, "target index beyond the targets");
    return d;
  });
}

}  // namespace rgnav
