// Ground-truth furniture blobs from a furnished and an empty floor plan; see FurnitureTruth.h.
#include "tests/eval/objects/FurnitureTruth.h"

#include <cstdint>
#include <opencv2/core.hpp>

#include "core/common/Errors.h"
#include "core/raster/Components.h"
#include "core/raster/GridMat.h"

namespace rgnav {

FurnitureTruth furnitureTruth(const OccupancyGrid& furnished, const OccupancyGrid& empty, int minCells) {
  if (furnished.width() != empty.width() || furnished.height() != empty.height())
    throw InvalidArgumentError("furniture truth: the furnished and the empty floor plan differ in size");
  constexpr int kFree = static_cast<int>(Cell::Free);
  const cv::Mat furniture = (cellMat(furnished) != kFree) & (cellMat(empty) == kFree);
  const Components components = connectedComponents(furniture, 1);

  FurnitureTruth truth;
  truth.width = furnished.width();
  truth.height = furnished.height();
  truth.blobOfCell = components.labels;
  truth.blobs.resize(components.sizes.size());
  for (std::size_t i = 0; i < components.labels.size(); ++i)
    if (const int label = components.labels[i]; label >= 0) truth.blobs[label].cells.push_back(i);
  for (FurnitureBlob& blob : truth.blobs)
    if (static_cast<int>(blob.cells.size()) < minCells) blob.exclusion = Exclusion::kSpeck;
  return truth;
}

}  // namespace rgnav
