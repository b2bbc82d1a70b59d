// AnchoredRun: what the localization fault test (issue 28, `rgctl faulttest localization`) knows
// of the run it replays: each scan of the log (raw odometry, as the playback serves it) with its
// corrected pose from the companion file (matched by stamp, tests/eval/localization
// StampedPoses.h), and the RG Mapping Kernel's checkpoint of the RG map made in process from the
// corrected poses (as `rgctl eval localization` makes it, RunMap.h), to be loaded by the kernel
// module of the server set (as tests/integration/LocalizationIntegration_test.cpp does).
// The map and the corrected poses are moved into the frame in which the first scan's corrected
// pose IS its raw odometry pose (a rigid motion of both, which changes no error): the module's
// own start at the first scan's odometry pose (--start-at-odometry) is then exactly the initial
// guess "the first scan's corrected pose", taken on the first scan before any other. A setPose
// call from outside cannot be placed on the first scan: while the module waits for it, it follows
// the Laser's latest scan, and a playback paced by its consumers advances with each look.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/common/SensorData.h"

namespace rgnav::testing {

struct AnchoredScan {
  DataId id = 0;
  Pose2D odometry;  // raw, as the playback serves it
  Pose2D truth;     // the corrected pose, anchored frame
};

struct AnchoredRun {
  std::vector<AnchoredScan> scans;  // the first maxScans of the log, in ID order (1, 2, ...)
  // The map made of all scans of the log: the kernel's rgmap.state and rgmap.state.scans.
  std::string kernelState, kernelJournal;
  std::size_t regions = 0;
};

// `maxScans`: the scans to localize (0: all); the map is made of all. Throws InvalidArgumentError
// when a scan has no corrected pose within 1 ms (every scan must be scored) and what the readers
// and the mapping chain throw.
AnchoredRun anchoredRun(const std::string& log, const std::string& corrected, const std::string& models,
                        std::size_t maxScans);

}  // namespace rgnav::testing
