// Conversions between Laser.idl types and core types.
#pragma once

#include "Laser.hh"
#include "core/common/DataBuffer.h"

namespace rgnav {

RGNav::ScanBatch toIdl(const DataBatch<LaserScan>& batch);
DataBatch<LaserScan> fromIdl(const RGNav::ScanBatch& batch);

}  // namespace rgnav
