// TruePoseProbe: where the simulated robot truly is, for the evaluation programs: the ground-truth
// pose of the latest scan (GroundTruth::truePose of Laser::latestId). One probe per thread (its
// clients are not thread-safe).
#pragma once

#include "clientlibs/groundtruth/GroundTruthClient.h"
#include "clientlibs/laser/LaserClient.h"

namespace rgnav {

struct TrueSample {
  DataId scan = 0;
  Pose2D pose;
};

class TruePoseProbe {
 public:
  explicit TruePoseProbe(const ClientSettings& settings);
  // The latest scan's true pose; NotAvailableError before the first scan.
  TrueSample latest();

 private:
  LaserClient laser_;
  GroundTruthClient truth_;
};

}  // namespace rgnav
