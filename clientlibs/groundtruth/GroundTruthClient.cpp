// GroundTruthClient calls through the retrying connection (see GroundTruthClient.h).
#include "clientlibs/groundtruth/GroundTruthClient.h"

#include "clientlibs/common/convert.h"
#include "clientlibs/groundtruth/convert.h"

namespace rgnav {

GroundTruthClient::GroundTruthClient(ClientSettings settings, std::string objectName)
    : ModuleClientOf(std::move(objectName), std::move(settings)) {}

Pose2D GroundTruthClient::truePose(DataId scanId) {
  return connection_.call("truePose", [&](RGNav::GroundTruth_ptr g) { return fromIdl(g->truePose(scanId)); });
}

int GroundTruthClient::roomAt(double x, double y) {
  return connection_.call("roomAt", [&](RGNav::GroundTruth_ptr g) { return static_cast<int>(g->roomAt(x, y)); });
}

unsigned GroundTruthClient::roomCount() {
  return connection_.call("roomCount", [](RGNav::GroundTruth_ptr g) { return static_cast<unsigned>(g->roomCount()); });
}

std::vector<DoorLine> GroundTruthClient::doorLines() {
  return connection_.call("doorLines", [](RGNav::GroundTruth_ptr g) {
    RGNav::DoorLineSeq_var doors = g->doorLines();
    return fromIdlSeq<std::vector<DoorLine>>(doors.in(), [](const RGNav::DoorLine& d) { return fromIdl(d); });
  });
}

std::vector<Person> GroundTruthClient::people() {
  return connection_.call("people", [](RGNav::GroundTruth_ptr g) {
    RGNav::PersonSeq_var people = g->people();
    return fromIdlSeq<std::vector<Person>>(people.in(), [](const RGNav::Person& p) { return fromIdl(p); });
  });
}

}  // namespace rgnav
