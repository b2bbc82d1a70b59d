// LocalizationImpl: the Localization.idl servant: check and convert in, service call, convert
// out; a service that holds no particles yet (NotLocalizedError) answers the typed NotLocalized.
#pragma once

#include "Localization.hh"
#include "servers/common/ServiceServant.h"
#include "servers/localization/LocalizationService.h"

namespace rgnav {

class LocalizationImpl : public ServiceServant<POA_RGNav::Localization> {
 public:
  // maxParticles: the most particles one particles() call returns.
  LocalizationImpl(ServerRuntime& runtime, LocalizationService& service, std::uint32_t maxParticles);

  RGNav::LocalizationEstimate latestEstimate() override;
  RGNav::LocalizationEstimate estimateByScan(RGNav::DataId scanId) override;
  RGNav::ParticleSnapshot* particles(CORBA::ULong maxCount) override;
  void setPose(const RGNav::Pose2D& mapPose, const RGNav::PoseSigma& sigma, RGNav::RegionId regionHint) override;
  void relocalize() override;
  RGNav::LocalizationState filterState() override;

 private:
  LocalizationService& service_;
  std::uint32_t maxParticles_;
};

}  // namespace rgnav
