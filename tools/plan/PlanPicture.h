// PlanPicture: rgnav-plan's pictures of a plan: the planning map drawn by the RG Map's own SVG and
// PNG exports (RgMapSvg.h, RgMapPng.h: regions, line maps, objects, gateways, the RG graph) with
// the planned path over it (MapOverlay.h) and a dot at every target pose. The map is turned into
// the exports' snapshot with what a PlanningMap holds: a gateway drawn as a door or a hallway
// area as the map says, without its detector record.
#pragma once

#include <string>

#include "core/nav/planning/PlanRecord.h"
#include "core/rgmap/export/RgMapSnapshot.h"

namespace rgnav {

RgMapSnapshot snapshotOf(const PlanningMap& map);

// Write atomically; throw FileError naming the path.
void writePlanSvg(const std::string& path, const PlanningMap& map, const PlanRecord& plan);
void writePlanPng(const std::string& path, const PlanningMap& map, const PlanRecord& plan);

}  // namespace rgnav
