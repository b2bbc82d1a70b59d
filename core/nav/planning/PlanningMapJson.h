// planningMapFromJson: an exported RG map (core/rgmap/export/RGMAP_JSON.md, format "rgnav-rgmap",
// version 2) read back into a PlanningMap, so that rgnav-plan plans offline on a map file as the
// PathPlanning module plans on the kernel's map: the regions with their frames, names, line maps,
// freespace bitmaps, descriptions and objects with names; the map's gateways (not the hypotheses);
// the RG graph's nodes and edges with their current costs (node keys resolved to indices); the
// map revision is the file's lastEventId. Values come back as the export rounded them (1 mm,
// 0.1 mrad). Fields a version-2 reader does not need are ignored, as the format asks.
#pragma once

#include <string>

#include "core/nav/planning/PlanningMap.h"

namespace rgnav {

// Throws FormatError naming `source` for text that is not such a map (another format or
// version, a missing or mistyped field, a freespace whose size and bits disagree, an edge naming
// an unknown node).
PlanningMap planningMapFromJson(const std::string& text, const std::string& source);
// FileError if the file cannot be read.
PlanningMap loadPlanningMap(const std::string& file);

}  // namespace rgnav
