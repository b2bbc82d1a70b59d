// loadVectorWorld: reads a VectorWorld (VectorWorld.h) from a YAML world file. Strict: an
// unknown, duplicate or missing key, a wrong type or a value out of range is a ConfigError that
// names the file and the key path ("walls[2].thickness"); a missing floor-plan image is a
// FileError naming the world file, the key and the image. Metres and radians throughout.
//
//   resolution: 0.05               # optional, cell size of the rasterized grid (default 0.05)
//   # the extent: exactly one of size, bounds, floor_plan
//   size: [20.0, 12.0]             # the world spans [0, 20] x [0, 12]
//   bounds: {min: [-5, -2], max: [15, 10]}
//   floor_plan:                    # an occupancy image as the base layer (floorplans/SOURCES.md
//     image: office_a.png          #   encoding: gray >= 250 free), relative to this file; one
//     origin: [0, 0]               #   pixel per cell; origin = its bottom-left corner (optional)
//   walls:
//     - name: north                # optional, unique; doors and rectangles refer to it
//       from: [0, 12]
//       to: [20, 12]
//       thickness: 0.2
//       height: 2.5                # optional, default 2.5
//   doors:                         # openings from the floor up to the frame
//     - wall: north
//       offset: 4.0                # wall `from` end to the opening's centre, or instead
//       center: [4, 12]            #   a point on the wall (within one thickness of its centre line)
//       width: 0.9                 # clear width of the opening, inside the wall's length
//       frame_width: 1.01          # optional, outer width of the frame, >= width (default width)
//       frame_height: 2.10         # optional, default 2.10
//       open: true                 # optional, default true; a closed door blocks like the wall
//   boxes:                         # furniture: cabinets, shelves, table tops
//     - center: [3, 4]
//       size: [1.6, 0.8]           # along the yaw direction, across it
//       yaw: 0.0                   # optional
//       height: 0.75
//       elevation: 0.0             # optional, underside above the floor
//   cylinders:                     # table legs, flower pots, bins, people
//     - {center: [5, 5], radius: 0.2, height: 1.0, elevation: 0.0}   # elevation optional
//   rectangles3d:                  # for the camera simulator (door frames come from doors)
//     - label: poster              # optional
//       corners: [[x, y, z], [x, y, z], [x, y, z], [x, y, z]]   # in order around it, or instead
//       wall: north                #   on a wall face:
//       side: left                 #   left or right, walking from `from` to `to`
//       offset: 6.0                #   wall `from` end to the rectangle's centre
//       width: 0.6
//       height: 0.9
//       elevation: 1.2             #   lower edge above the floor (optional, default 0)
//   rooms:                         # optional ground truth
//     - name: office_1             # optional
//       polygon: [[0, 0], [5, 0], [5, 4], [0, 4]]
#pragma once

#include <string>

#include "core/sim/world/VectorWorld.h"

namespace rgnav {

VectorWorld loadVectorWorld(const std::string& yamlPath);

}  // namespace rgnav
