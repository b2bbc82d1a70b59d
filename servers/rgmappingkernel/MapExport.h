// What RGMappingKernel::exportMap writes: <dir>/<name>.rgmap.json, .svg and .png, and on request
// the global metric map <dir>/<name>.pgm + .yaml (ROS map_server). In two steps, so that the
// files are written without holding the kernel's lock: the export's data is taken from the
// kernel under the lock (MapExportData), then written outside it.
#pragma once

#include <optional>
#include <string>

#include "core/rgmap/export/RgMapSnapshot.h"
#include "core/rgmap/kernel/RgMappingKernel.h"
#include "core/raster/OccupancyGrid.h"

namespace rgnav {

struct MapExportData {
  RgMapSnapshot map;
  std::optional<OccupancyGrid> occupancy;
};

// NotAvailableError for a map without scans.
MapExportData exportDataOf(const RgMappingKernel& kernel, bool occupancy);

// Writes the files into the existing directory `dir` (ExportRoot.h) and returns their paths, one
// per line; FileError when a file cannot be written.
std::string writeMapExport(const MapExportData& data, const std::string& dir, const std::string& name);

}  // namespace rgnav
