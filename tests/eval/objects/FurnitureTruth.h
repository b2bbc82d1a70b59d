// FurnitureTruth: the ground-truth furniture of an IPA floor plan (issue 4, "rgctl eval
// objects"): cells occupied in X_furnitures.png but free in X.png; each 8-connected component
// of them is one ground-truth object. Components smaller than a minimum size are specks: they
// are kept as "don't care" areas (a detection on one is neither right nor wrong) and counted.
#pragma once

#include <cstddef>
#include <vector>

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

// Why a ground-truth object does not count towards recall.
enum class Exclusion { kNone, kSpeck, kNotVisible };

struct FurnitureBlob {
  std::vector<std::size_t> cells;  // row-major grid cell indices, ascending
  Exclusion exclusion = Exclusion::kNone;
};

struct FurnitureTruth {
  int width = 0;
  int height = 0;
  std::vector<int> blobOfCell;  // per grid cell: index into blobs, or -1
  std::vector<FurnitureBlob> blobs;
};

// `furnished` and `empty` are the grids of X_furnitures.png and X.png (same size, else
// InvalidArgumentError). Blobs of fewer than minCells cells are marked kSpeck.
FurnitureTruth furnitureTruth(const OccupancyGrid& furnished, const OccupancyGrid& empty, int minCells);

}  // namespace rgnav
