// loadSimulationConfig: the simulator's parameters from YAML (config/sim/*.yaml), strict: an
// unknown key is a ConfigError naming its path. Units are in the key names (DESIGN.md, Config).
//   step_s: 0.05            steps_per_scan: 2            seed: 1
//   robot:    {radius_m, max_velocity_mps, max_rotation_radps, max_acceleration_mps2, max_rotation_acceleration_radps2,
//              footprint: {shape: disk, radius_m} or {shape: rectangle, length_m, width_m, center_offset_m}}
//             (radius_m is short for a disk footprint; give one of radius_m and footprint)
//   odometry: {alpha1, alpha2, alpha3, alpha4, translation_scale_error, rotation_bias_rad_per_m}
//   laser:    {field_of_view_deg, resolution_deg, max_range_m, mounting_height_m, forward_offset_m,
//              range_noise_sigma_m, dropout_probability}
//   people:   {count, radius_m, min_speed_mps, max_speed_mps, seed}   (walking people; seed
//              defaults to one derived from the simulation's)
// Every key is optional; missing ones keep the defaults of SimulationConfig.
#pragma once

#include <string>

#include "core/sim/Simulation.h"

namespace rgnav {

SimulationConfig parseSimulationConfig(const std::string& yamlText);
// FileError if the file cannot be read; ConfigError messages start with the path.
SimulationConfig loadSimulationConfig(const std::string& path);

}  // namespace rgnav
