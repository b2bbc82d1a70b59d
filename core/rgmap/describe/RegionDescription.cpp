// Description of one region from its evidence; see RegionDescription.h.
#include "core/rgmap/describe/RegionDescription.h"

namespace rgnav {

RegionDescription describeRegion(const RegionEvidence& evidence, std::span<const LineSegment> lines,
                                 std::span<const GatewaySegment> gateways, const DescriptionParams& params) {
  RegionDescription d;
  d.boundingBox = axisAlignedBox(evidence.hull().vertices());
  d.minimumAreaBox = minimumAreaRectangle(evidence.hull().vertices());
  d.freespace = evidence.freespace().bitmap();
  d.moments = freespaceMoments(evidence.freespace());
  if (!d.boundingBox.isEmpty() && d.moments.areaM2 > 0.0) {
    const Eigen::Vector2d size = d.boundingBox.sizes(), offset = d.moments.centroid - d.boundingBox.min();
    for (int k = 0; k < 2; ++k) d.centroidInBox[k] = size[k] > 0.0 ? offset[k] / size[k] : 0.5;
  }
  d.mainDirections = mainDirections(lines, params.directions);
  d.accuracy = lineMapAccuracy(evidence.sample().points(), lines, params.accuracy);
  d.completeness = freespaceCompleteness(evidence.freespace(), gateways);
  d.objects = detectRegionObjects(std::vector<LineSegment>(lines.begin(), lines.end()), d.freespace, params.objects);
  d.scanCount = evidence.freespace().scanCount();
  return d;
}

}  // namespace rgnav
