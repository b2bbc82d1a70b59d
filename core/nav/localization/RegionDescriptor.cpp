// Region descriptors of mapped regions and of the local observation (see RegionDescriptor.h).
#include "core/nav/localization/RegionDescriptor.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/rgmap/describe/FreespaceMoments.h"

namespace rgnav {

namespace {

std::string mostProbableClass(const GatewayView& gateway) {
  const auto best = std::max_element(gateway.classes.begin(), gateway.classes.end(),
                                     [](const ClassProbability& a, const ClassProbability& b) {
                                       return a.probability < b.probability;
                                     });
  return best == gateway.classes.end() ? std::string() : best->name;
}

double logRatio(double a, double b) { return std::log(std::max(a, 1e-6) / std::max(b, 1e-6)); }

}  // namespace

RegionDescriptor describeMappedRegion(const RegionView& region, const std::vector<RegionView>& regions,
                                      const std::vector<GatewayView>& gateways) {
  RegionDescriptor d;
  d.region = region.summary.id;
  d.areaM2 = region.areaM2;
  d.centroid = region.centroid;
  d.majorSigmaM = std::sqrt(std::max(region.majorVariance, 0.0));
  d.minorSigmaM = std::sqrt(std::max(region.minorVariance, 0.0));
  d.majorAxisAngleRad = region.majorAxisAngleRad;
  d.mainDirections = region.mainDirections;
  d.freespace = region.freespace;
  std::vector<std::string> classes;
  std::set<RegionId> neighbours;
  for (const GatewayView& g : gateways) {
    if (g.neutralised || (g.sideA != d.region && g.sideB != d.region)) continue;
    classes.push_back(mostProbableClass(g));
    const RegionId other = g.sideA == d.region ? g.sideB : g.sideA;
    if (!other.isNone() && other != d.region) neighbours.insert(other);
  }
  d.gatewayClasses = std::move(classes);
  for (const RegionView& r : regions)
    if (neighbours.count(r.summary.id)) d.neighbourAreaM2 += r.areaM2;
  return d;
}

RegionDescriptor describeObservation(const LocalObservation& observation) {
  RegionDescriptor d;
  const FreespaceMoments m = freespaceMoments(observation.freespace);
  d.areaM2 = m.areaM2;
  d.centroid = m.centroid;
  d.majorSigmaM = std::sqrt(std::max(m.majorVariance, 0.0));
  d.minorSigmaM = std::sqrt(std::max(m.minorVariance, 0.0));
  d.majorAxisAngleRad = m.majorAxisAngleRad;
  d.mainDirections = mainDirections(observation.lines);
  d.freespace = observation.freespace.bitmap();
  return d;
}

double descriptorDistance(const RegionDescriptor& observed, const RegionDescriptor& mapped,
                          const DescriptorWeights& weights) {
  if (mapped.areaM2 <= 0.0) return weights.area * std::max(0.0, logRatio(observed.areaM2, mapped.neighbourAreaM2));
  const double area = std::max(0.0, logRatio(observed.areaM2, mapped.areaM2 + mapped.neighbourAreaM2));
  const double coverage = std::min(1.0, observed.areaM2 / mapped.areaM2);
  const double shape = coverage * (std::abs(logRatio(observed.majorSigmaM, mapped.majorSigmaM)) +
                                   std::abs(logRatio(observed.minorSigmaM, mapped.minorSigmaM)));
  double gateways = 0.0;
  if (observed.gatewayClasses && mapped.gatewayClasses)
    gateways = double(std::max<std::ptrdiff_t>(0, std::ptrdiff_t(observed.gatewayClasses->size()) -
                                                      std::ptrdiff_t(mapped.gatewayClasses->size())));
  return weights.area * area + weights.shape * shape + weights.gateway * gateways;
}

}  // namespace rgnav
