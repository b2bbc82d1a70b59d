// ROS map_server maps written; see MapServerWriter.h.
#include "core/rgmap/export/MapServerWriter.h"

#include "core/common/AtomicFile.h"
#include "core/common/Errors.h"
#include "core/raster/ImageFile.h"
#include "core/raster/ImageGrid.h"
#include "core/rgmap/export/ExportNumbers.h"

namespace rgnav {
namespace {

constexpr int kYamlDecimals = 6;

std::uint8_t gray(Cell c) {
  switch (c) {
    case Cell::Free: return kMapFreeGray;
    case Cell::Occupied: return kMapOccupiedGray;
    case Cell::Unknown: break;
  }
  return kMapUnknownGray;
}

}  // namespace

MapServerFiles writeMapServerMap(const std::string& dir, const std::string& name, const OccupancyGrid& grid) {
  if (name.empty() || name.find('/') != std::string::npos)
    throw InvalidArgumentError("map_server map: the name must be non-empty and hold no '/'");
  const std::string prefix = (dir.empty() ? std::string(".") : dir) + "/" + name;
  const MapServerFiles files{prefix + ".yaml", prefix + ".pgm"};
  writeImage(files.imagePath, imageFromGrid(grid, gray));
  writeFileAtomically(files.yamlPath, "image: " + name + ".pgm\nresolution: " +
                                          decimalText(grid.resolution(), kYamlDecimals) + "\norigin: [" +
                                          decimalText(grid.origin().x, kYamlDecimals) + ", " +
                                          decimalText(grid.origin().y, kYamlDecimals) +
                                          ", 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
  return files;
}

}  // namespace rgnav
