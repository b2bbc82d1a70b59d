// LocalizationClient: the pose of the Localization module (idl/Localization.idl): the latest
// estimate and the estimate of a scan by ID, the particles, an initial guess (setPose), a global
// relocalization and the module's state, with core types in and out. Calls are retried as every
// client's (ClientConnection.h); setPose and relocalize too (a repeated one draws the particles
// again from the same arguments). Errors: NotLocalizedError before the module holds particles,
// BadArgumentError naming the field, NotAvailableError (no map yet, a scan not in the history),
// ModuleFailedError, ModuleUnavailableError.
#pragma once

#include <Eigen/Core>

#include "Localization.hh"
#include "clientlibs/common/ModuleClient.h"
#include "clientlibs/localization/LocalizationViews.h"

namespace rgnav {

class LocalizationClient : public ModuleClientOf<RGNav::Localization> {
 public:
  explicit LocalizationClient(ClientSettings settings = ClientSettings::fromEnvironment(),
                              std::string objectName = "Localization");

  ScanEstimate latestEstimate();
  ScanEstimate estimateByScan(DataId scanId);
  ParticleSnapshotView particles(std::uint32_t maxCount);
  // sigma: x, y in m, theta in rad; `regionHint` none: no preference.
  void setPose(const Pose2D& mapPose, const Eigen::Vector3d& sigma, RegionId regionHint = RegionId());
  void relocalize();
  LocalizationStateView filterState();
};

}  // namespace rgnav
