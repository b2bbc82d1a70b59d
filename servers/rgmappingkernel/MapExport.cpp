// The files of RGMappingKernel::exportMap (see MapExport.h).
#include "servers/rgmappingkernel/MapExport.h"

#include <filesystem>

#include "core/common/Errors.h"
#include "core/rgmap/export/MapServerWriter.h"
#include "core/rgmap/export/OccupancyMap.h"
#include "core/rgmap/export/RgMapJson.h"
#include "core/rgmap/export/RgMapPng.h"
#include "core/rgmap/export/RgMapSvg.h"

namespace rgnav {

MapExportData exportDataOf(const RgMappingKernel& kernel, bool occupancy) {
  if (kernel.state().scans.empty()) throw NotAvailableError("exportMap: the map has no scans yet");
  MapExportData data{snapshotOf(kernel), std::nullopt};
  if (occupancy) data.occupancy = occupancyMapOf(kernel.state());
  return data;
}

std::string writeMapExport(const MapExportData& data, const std::string& dir, const std::string& name) {
  const std::string base = (std::filesystem::path(dir) / name).string() + ".rgmap";
  writeRgMapJson(base + ".json", data.map);
  writeRgMapSvg(base + ".svg", data.map);
  exportRgMapPng(base + ".png", data.map);
  std::string files = base + ".json\n" + base + ".svg\n" + base + ".png\n";
  if (data.occupancy) {
    const MapServerFiles grid = writeMapServerMap(dir, name, *data.occupancy);
    files += grid.imagePath + "\n" + grid.yamlPath + "\n";
  }
  return files;
}

}  // namespace rgnav
