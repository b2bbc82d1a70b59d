// Test helpers of the RG Map exports: the maps of the kernel's tours (SyntheticTour.h), and a
// check that a piece of XML has balanced tags.
#pragma once

#include <string>

#include "core/rgmap/kernel/RgMappingKernel.h"

namespace rgnav::testing {

// A fresh kernel fed the whole twoRoomTour(): a hallway, two rooms behind doors 11 and 12; three
// regions and two gateways. The same map at every call.
RgMappingKernel twoRoomMap();
// A fresh kernel fed the whole ringTour(): one ring-shaped region, its door neutralised.
RgMappingKernel ringMap();

// Empty if every start tag of `xml` has its end tag in the right order and there is exactly one
// root element; otherwise what is wrong. Comments, CDATA and '>' inside attribute values are not
// supported (the exports write none).
std::string unbalancedTags(const std::string& xml);

}  // namespace rgnav::testing
