// LocalizationClient calls through the retrying connection (see LocalizationClient.h).
#include "clientlibs/localization/LocalizationClient.h"

#include "clientlibs/common/convert.h"
#include "clientlibs/localization/convert.h"

namespace rgnav {

using Localizer = RGNav::Localization_ptr;

namespace {

// The module's answer, or its NotLocalized as NotLocalizedError.
template <class F>
auto localized(const char* operation, F&& call) {
  try {
    return call();
  } catch (const RGNav::NotLocalized& e) {
    throw NotLocalizedError(std::string("Localization.") + operation + ": " + e.message.in());
  }
}

}  // namespace

LocalizationClient::LocalizationClient(ClientSettings settings, std::string objectName)
    : ModuleClientOf(std::move(objectName), std::move(settings)) {}

ScanEstimate LocalizationClient::latestEstimate() {
  return connection_.call("latestEstimate", [](Localizer l) {
    return localized("latestEstimate", [&] { return fromIdl(l->latestEstimate()); });
  });
}

ScanEstimate LocalizationClient::estimateByScan(DataId scanId) {
  return connection_.call("estimateByScan", [&](Localizer l) {
    return localized("estimateByScan", [&] { return fromIdl(l->estimateByScan(scanId)); });
  });
}

ParticleSnapshotView LocalizationClient::particles(std::uint32_t maxCount) {
  return connection_.call("particles", [&](Localizer l) {
    return localized("particles", [&] {
      RGNav::ParticleSnapshot_var snapshot = l->particles(maxCount);
      return fromIdl(snapshot.in());
    });
  });
}

void LocalizationClient::setPose(const Pose2D& mapPose, const Eigen::Vector3d& sigma, RegionId regionHint) {
  connection_.call("setPose",
                   [&](Localizer l) { l->setPose(toIdl(mapPose), toIdlSigma(sigma), regionHint.value()); });
}

void LocalizationClient::relocalize() {
  connection_.call("relocalize", [](Localizer l) { l->relocalize(); });
}

LocalizationStateView LocalizationClient::filterState() {
  return connection_.call("filterState", [](Localizer l) { return fromIdl(l->filterState()); });
}

}  // namespace rgnav
