// DrivenPath: the path the navigating demo's robot drove, as the ScanMapper's corrected poses of
// its scans (the map frame, revised by loop closing up to the moment they are read), and its
// exports beside the map's: <name>.path.json (schema below), and <name>.path.svg / .png, the RG
// map's own pictures (RgMapSvg.h, RgMapPng.h, drawn from the exported map) with the path over it.
// JSON: {"frame": "map", "length_m": L, "poses": [{"scan": ID, "x": X, "y": Y, "theta": T}, ...]}.
#pragma once

#include <string>
#include <vector>

#include "clientlibs/scanmapper/ScanMapperClient.h"
#include "core/nav/planning/PlanningMap.h"

namespace rgnav {

struct DrivenPath {
  std::vector<PoseUpdate> poses;  // by scan ID

  double lengthM() const;
};

// The corrected poses of scans firstId..the ScanMapper's latest, fetched in the server's portions.
DrivenPath fetchDrivenPath(ScanMapperClient& scanMapper, DataId firstId);

// `base`: the path without the extensions (e.g. out/demo.path). Throw FileError naming the path.
void writeDrivenPathJson(const std::string& file, const DrivenPath& path);
void writeDrivenPathPictures(const std::string& base, const PlanningMap& map, const DrivenPath& path);

}  // namespace rgnav
