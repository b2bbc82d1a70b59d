// The Localization.idl servant (see LocalizationImpl.h).
#include "servers/localization/LocalizationImpl.h"

#include <cmath>

#include "clientlibs/localization/convert.h"
#include "servers/common/WireChecks.h"

namespace rgnav {
namespace {

// Runs work that needs particles; their absence becomes NotLocalized.
template <class F>
auto localized(F&& work) {
  try {
    return work();
  } catch (const NotLocalizedError& e) {
    throw RGNav::NotLocalized(e.what());
  }
}

void requireSigma(double value, const char* field) {
  if (!(std::isfinite(value) && value >= 0.0)) wire::refuse(field, "must be finite and not negative");
}

}  // namespace

LocalizationImpl::LocalizationImpl(ServerRuntime& runtime, LocalizationService& service, std::uint32_t maxParticles)
    : ServiceServant(runtime), service_(service), maxParticles_(maxParticles) {}

RGNav::LocalizationEstimate LocalizationImpl::latestEstimate() {
  return serve(Raises::FailedOnly, [&] { return localized([&] { return toIdl(service_.latestEstimate()); }); });
}

RGNav::LocalizationEstimate LocalizationImpl::estimateByScan(RGNav::DataId scanId) {
  return serve(Raises::InvalidArgument | Raises::NotAvailable, [&] {
    wire::requireId(scanId, "scanId");
    return localized([&] { return toIdl(service_.estimateByScan(scanId)); });
  });
}

RGNav::ParticleSnapshot* LocalizationImpl::particles(CORBA::ULong maxCount) {
  return serve(Raises::InvalidArgument, [&] {
    const std::size_t count = wire::cappedCount(maxCount, maxParticles_, "maxCount");
    return localized([&] { return new RGNav::ParticleSnapshot(toIdl(service_.particles(count))); });
  });
}

void LocalizationImpl::setPose(const RGNav::Pose2D& mapPose, const RGNav::PoseSigma& sigma,
                               RGNav::RegionId regionHint) {
  serve(Raises::InvalidArgument | Raises::NotAvailable, [&] {
    wire::requireFinite(mapPose, "mapPose");
    requireSigma(sigma.x, "sigma.x");
    requireSigma(sigma.y, "sigma.y");
    requireSigma(sigma.theta, "sigma.theta");
    service_.setPose(fromIdl(mapPose), fromIdl(sigma), RegionId(regionHint));
  });
}

void LocalizationImpl::relocalize() {
  serve(Raises::NotAvailable, [&] { service_.relocalize(); });
}

RGNav::LocalizationState LocalizationImpl::filterState() {
  return serve(Raises::FailedOnly, [&] { return toIdl(service_.state()); });
}

}  // namespace rgnav
