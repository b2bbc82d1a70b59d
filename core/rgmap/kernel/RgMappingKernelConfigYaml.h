// The RG Mapping Kernel module's parameters from YAML (config/modules/rgmappingkernel.yaml): every
// key of RgMappingKernelConfig (its describe() functions) required, no other key allowed,
// validated as the kernel validates them. Errors are ConfigErrors naming the file, the key path
// and the line.
#pragma once

#include <string>

#include "core/rgmap/kernel/RgMappingKernel.h"

namespace rgnav {

// `path` names the text in errors.
RgMappingKernelConfig parseRgMappingKernelConfig(const std::string& yamlText, const std::string& path);
// FileError if the file cannot be read.
RgMappingKernelConfig loadRgMappingKernelConfig(const std::string& file);

}  // namespace rgnav
