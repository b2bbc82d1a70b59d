// MapPolyline: a line drawn over the RG Map's pictures (RgMapSvg.h, RgMapPng.h) on top of
// everything else, in the map frame: a planned path with its target poses (rgnav-plan), say. The
// map's own JSON export knows nothing of it.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/rgmap/export/MapColours.h"

namespace rgnav {

struct MapPolyline {
  std::vector<Eigen::Vector2d> points;  // map frame
  Rgb colour;
  double widthM = 0.05;    // the PNG draws it at least 1 pixel wide
  double markerRadiusM = 0.0;  // a dot of this radius at every point; 0: none
  std::string cssClass;    // the SVG group's class
};

}  // namespace rgnav
