// Floor-plan images (floorplans/SOURCES.md, the IPA room segmentation benchmark of Bormann et
// al., ICRA 2016): 8-bit gray, gray >= 250 free, everything else (walls, unknown) occupied,
// 0.05 m per pixel, the image's bottom-left corner at the world origin.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

constexpr double kFloorPlanResolution = 0.05;  // m per pixel
constexpr std::uint8_t kFloorPlanFreeGray = 250;

inline bool isFloorPlanFree(std::uint8_t gray) { return gray >= kFloorPlanFreeGray; }

// The floor-plan grid of an 8-bit gray image (CV_8UC1) already in memory; `origin` is its bottom-left corner.
OccupancyGrid floorPlanFromImage(const cv::Mat& image, double resolution, WorldPoint origin);

// Loads a PNG or PGM floor plan. FileError / FormatError name the path; a non-positive
// resolution is an InvalidArgumentError.
OccupancyGrid loadFloorPlan(const std::string& imagePath, double resolution = kFloorPlanResolution,
                            WorldPoint origin = {});

}  // namespace rgnav
