// The files of RGMappingKernel::exportMap (see MapExport.h).
#include "servers/rgmappingkernel/MapExport.h"

#include <filesystem>

#include "core/common/Errors.h"
#include "core/rgmap/export/OccupancyMap.h"
#include "core/rgmap/export/RgMapJson.h"
#include "core/rgmap/export/RgMapPng.h"
#include "core/rgmap/export/RgMapSvg.h"

namespace rgnav {

std::string exportMapFiles(const RgMappingKernel& kernel, const std::string& dir, const std::string& name,
                           bool occupancy) {
  if (dir.empty()) throw InvalidArgumentError("exportMap: no directory given");
  if (name.empty() || name.find('/') != std::string::npos)
    throw InvalidArgumentError("exportMap: '" + name + "' is no file name");
  if (kernel.state().scans.empty()) throw NotAvailableError("exportMap: the map has no scans yet");
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) throw FileError(dir + ": cannot create: " + error.message());
  const RgMapSnapshot map = snapshotOf(kernel);
  const std::string base = (std::filesystem::path(dir) / name).string() + ".rgmap";
  writeRgMapJson(base + ".json", map);
  writeRgMapSvg(base + ".svg", map);
  exportRgMapPng(base + ".png", map);
  std::string files = base + ".json\n" + base + ".svg\n" + base + ".png\n";
  if (occupancy) {
    const MapServerFiles grid = exportOccupancyMap(dir, name, kernel.state());
    files += grid.imagePath + "\n" + grid.yamlPath + "\n";
  }
  return files;
}

}  // namespace rgnav
