// renderRgMap / exportRgMapPng: the picture of RgMapSvg.h as a raster image (PNG, drawn on a
// MapCanvas and written with core/raster/ImageFile.h), for viewers without SVG and for quick looks at large maps: over pictureExtent
// (MapExtent.h) at resolutionM metres per pixel, y up, each region's freespace in its colour
// (MapColours.h; a pixel is the region's if its centre lies in a free cell, FreespaceRaster.h,
// and later regions paint over earlier ones where freespaces overlap), the RG Graph's edges in
// red, line maps in dark grey, doors as thick orange segments, hallway areas as blue outlined
// squares (neutralised gateways grey), crossing points as black dots and each region's ID in
// small digits just above its freespace centroid.
// Deliberate difference from the SVG: no names, gateway labels or scale bar (no fonts here); the
// resolution is the scale.
#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "core/rgmap/export/MapOverlay.h"
#include "core/rgmap/export/RgMapSnapshot.h"

namespace rgnav {

// Throws InvalidArgumentError for a non-positive resolution or a picture wider or taller than
// MapCanvas::kMaxSidePixels. CV_8UC3, BGR. `overlays` are drawn last.
cv::Mat renderRgMap(const RgMapSnapshot& map, double resolutionM = 0.05, const std::vector<MapPolyline>& overlays = {});

// Writes renderRgMap(map, resolutionM, overlays) atomically; throws FileError naming the path.
void exportRgMapPng(const std::string& path, const RgMapSnapshot& map, double resolutionM = 0.05,
                    const std::vector<MapPolyline>& overlays = {});

}  // namespace rgnav
