// GroundTruthClient: the simulator's ground truth for evaluation programs (GroundTruth.idl).
#pragma once

#include <vector>

#include "GroundTruth.hh"
#include "clientlibs/common/ModuleClient.h"
#include "core/common/Pose2D.h"
#include "core/common/SensorData.h"
#include "core/sim/GroundTruth.h"
#include "core/sim/people/Person.h"

namespace rgnav {

class GroundTruthClient : public ModuleClientOf<RGNav::GroundTruth> {
 public:
  explicit GroundTruthClient(ClientSettings settings = ClientSettings::fromEnvironment(),
                             std::string objectName = "GroundTruth");

  // NotAvailableError for a scan the simulator does not (or no longer) know.
  Pose2D truePose(DataId scanId);
  // BadArgumentError naming "x" or "y" for a NaN or infinite coordinate.
  int roomAt(double x, double y);
  unsigned roomCount();
  std::vector<DoorLine> doorLines();
  // The people walking through the world now (empty if there are none).
  std::vector<Person> people();
};

}  // namespace rgnav
