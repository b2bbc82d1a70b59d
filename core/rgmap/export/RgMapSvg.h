// exportRgMapSvg: an RG Map as one SVG picture in the map frame, for people (thesis 2.3.2: global
// metric maps are not kept in an RG Map "but they can be extracted easily on demand"; figure 2.1
// shows an RG Map this way). Drawn, bottom to top:
//   - each region in a group placed at its frame (rotate + translate): its freespace bitmap as one
//     filled path in the region's colour (MapColours.h; one rectangle per run of free cells in a
//     row), its line map as one dark path, its 2D objects as purple outlines;
//   - the RG Graph's edges as thin red lines between its crossing points;
//   - each gateway as one group: a door (narrow passage) as an orange segment between its gateway
//     points, a hallway area as its outlined square (blue), a neutralised gateway grey and dashed;
//     its crossing points as small circles and its class label ("G<id> <label>");
//   - each region's ID (and name) at its freespace centroid, and a scale bar.
// Units are metres (1 user unit = 1 m; the picture is kSvgPixelsPerMetre pixels per metre), y up:
// the map frame's y is negated as coordinates are written, so the text stays upright. Values are
// written with 1 mm (0.01 degree) resolution; the same snapshot gives the same bytes.
// Elements carry classes for scripts and style sheets: region (id "region-<id>"), freespace,
// lines, object, graph, gateway (id "gateway-<id>"), crossing, region-label, gateway-label, scale-bar.
#pragma once

#include <string>

#include "core/rgmap/export/MapOverlay.h"
#include "core/rgmap/export/RgMapSnapshot.h"

namespace rgnav {

inline constexpr double kSvgPixelsPerMetre = 40.0;

// `overlays` are drawn last, each as a group of its class with a polyline and its markers.
std::string exportRgMapSvg(const RgMapSnapshot& map, const std::vector<MapPolyline>& overlays = {});

// Writes exportRgMapSvg(map, overlays) atomically (AtomicFile.h); throws FileError naming the path.
void writeRgMapSvg(const std::string& path, const RgMapSnapshot& map, const std::vector<MapPolyline>& overlays = {});

}  // namespace rgnav
