// The two robot pose sources of the High-Level Planning module (see RobotPose.h).
#include "servers/highlevelplanning/RobotPose.h"

#include "clientlibs/localization/LocalizationClient.h"
#include "clientlibs/scanmapper/ScanMapperClient.h"

namespace rgnav {
namespace {

class ScanMapperPose : public RobotPose {
 public:
  ScanMapperPose(const ClientSettings& settings, const std::string& objectName) : client_(settings, objectName) {}
  std::optional<Pose2D> pose() override {
    const DataId newest = client_.latestCorrectedId();
    if (newest == 0) return std::nullopt;
    return client_.correctedPose(newest);
  }

 private:
  ScanMapperClient client_;
};

class LocalizationPose : public RobotPose {
 public:
  LocalizationPose(const ClientSettings& settings, const std::string& objectName) : client_(settings, objectName) {}
  std::optional<Pose2D> pose() override {
    try {
      return client_.latestEstimate().estimate.mapPose;
    } catch (const NotLocalizedError&) {
      return std::nullopt;
    }
  }

 private:
  LocalizationClient client_;
};

}  // namespace

std::unique_ptr<RobotPose> makeRobotPose(const std::string& source, const ClientSettings& settings,
                                         const std::string& objectName) {
  if (source == "scanmapper") return std::make_unique<ScanMapperPose>(settings, objectName.empty() ? "ScanMapper" : objectName);
  if (source == "localization")
    return std::make_unique<LocalizationPose>(settings, objectName.empty() ? "Localization" : objectName);
  throw ConfigError("--pose-source is scanmapper or localization, not '" + source + "'");
}

}  // namespace rgnav
