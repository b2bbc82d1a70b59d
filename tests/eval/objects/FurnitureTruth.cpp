// Ground-truth furniture blobs from a furnished and an empty floor plan; see FurnitureTruth.h.
#include "tests/eval/objects/FurnitureTruth.h"

#include <cstdint>

#include "core/common/Errors.h"
#include "core/sim/world/Components.h"

namespace rgnav {

FurnitureTruth furnitureTruth(const OccupancyGrid& furnished, const OccupancyGrid& empty, int minCells) {
  if (furnished.width() != empty.width() || furnished.height() != empty.height())
    throw InvalidArgumentError("furniture truth: the furnished and the empty floor plan differ in size");
  const std::vector<Cell>& withFurniture = furnished.cells();
  const std::vector<Cell>& without = empty.cells();
  std::vector<std::uint8_t> mask(withFurniture.size());
  for (std::size_t i = 0; i < mask.size(); ++i) mask[i] = withFurniture[i] != Cell::Free && without[i] == Cell::Free;
  const Components components = connectedComponents(mask, furnished.width(), furnished.height(), 1);

  FurnitureTruth truth;
  truth.width = furnished.width();
  truth.height = furnished.height();
  truth.blobOfCell = components.labels;
  truth.blobs.resize(components.sizes.size());
  for (std::size_t i = 0; i < mask.size(); ++i)
    if (const int label = components.labels[i]; label >= 0) truth.blobs[label].cells.push_back(i);
  for (FurnitureBlob& blob : truth.blobs)
    if (static_cast<int>(blob.cells.size()) < minCells) blob.exclusion = Exclusion::kSpeck;
  return truth;
}

}  // namespace rgnav
