// The RG Map's objects against the furniture; see ObjectScoring.h.
#include "tests/eval/rooms/ObjectScoring.h"

#include <set>

#include "core/lines/ScanPoints.h"
#include "core/objects/RectangleDetector.h"
#include "tests/eval/objects/Detection.h"

namespace rgnav {

Polygon objectOutlineInWorld(const RegionView& region, const RectangleObjectView& o, const Pose2D& mapToWorld) {
  const Pose2D regionInWorld = compose(mapToWorld, region.summary.frame);
  Polygon outline;
  for (const Eigen::Vector2d& p : rectangleOutline({o.pose, o.lengthM, o.widthM, o.confidence, {}}))
    outline.push_back(transformPoint(regionInWorld, p));
  return outline;
}

ObjectScore scoreObjects(const FinalMap& map, const Pose2D& mapToWorld, const OccupancyGrid& world,
                         const FurnitureTruth& furniture) {
  ObjectScore score;
  for (const FurnitureBlob& blob : furniture.blobs)
    if (blob.exclusion != Exclusion::kSpeck) ++score.blobs;
  std::set<int> found;
  for (const RegionView& region : map.regions) {
    const Pose2D regionInWorld = compose(mapToWorld, region.summary.frame);
    for (const RectangleObjectView& o : region.objects) {
      const Eigen::Vector2d centre = transformPoint(regionInWorld, {o.pose.x, o.pose.y});
      const std::vector<std::size_t> footprint = rasterize(objectOutlineInWorld(region, o, mapToWorld), {centre}, world);
      std::set<int> blobs;
      std::size_t furnitureCells = 0;
      for (const std::size_t cell : footprint) {
        const int blob = furniture.blobOfCell[cell];
        if (blob < 0 || furniture.blobs[std::size_t(blob)].exclusion == Exclusion::kSpeck) continue;
        ++furnitureCells;
        blobs.insert(blob);
      }
      ++score.objects;
      if (double(furnitureCells) < kMinFurnitureShare * double(footprint.size())) continue;
      ++score.onFurniture;
      found.insert(blobs.begin(), blobs.end());
    }
  }
  score.blobsFound = found.size();
  return score;
}

}  // namespace rgnav
