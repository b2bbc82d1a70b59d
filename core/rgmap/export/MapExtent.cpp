// Extent of an RG Map in the map frame; see MapExtent.h.
#include "core/rgmap/export/MapExtent.h"

namespace rgnav {

Eigen::AlignedBox2d mapExtent(const RgMapSnapshot& map) {
  Eigen::AlignedBox2d box;
  for (const RegionSnapshot& r : map.regions) {
    const FreespaceBitmap& f = r.description.freespace;
    if (f.width > 0 && f.height > 0) {
      const Eigen::Vector2d size = f.resolutionM * Eigen::Vector2d(f.width, f.height);
      for (const Eigen::Vector2d& corner : {Eigen::Vector2d(0, 0), Eigen::Vector2d(size.x(), 0), size,
                                            Eigen::Vector2d(0, size.y())})
        box.extend(r.toMap(f.originM + corner));
    }
    for (const LineSegment& line : r.lines) {
      box.extend(r.toMap(line.start));
      box.extend(r.toMap(line.end));
    }
  }
  for (const GatewaySnapshot& g : map.gateways) {
    for (const Eigen::Vector2d& p : g.inMap.gatewayPoints) box.extend(p);
    for (const Eigen::Vector2d& p : g.inMap.crossingPoints) box.extend(p);
  }
  return box;
}

Eigen::AlignedBox2d pictureExtent(const RgMapSnapshot& map) {
  Eigen::AlignedBox2d box = mapExtent(map);
  if (box.isEmpty()) box.extend(Eigen::Vector2d::Zero());
  const Eigen::Vector2d margin = Eigen::Vector2d::Constant(kPictureMarginM);
  return {box.min() - margin, box.max() + margin};
}

}  // namespace rgnav
