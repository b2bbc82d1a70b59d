// Conversions between Base.idl types and core types.
#pragma once

#include "Base.hh"
#include "core/common/DataBuffer.h"

namespace rgnav {

RGNav::OdometryBatch toIdl(const DataBatch<OdometryReading>& batch);
DataBatch<OdometryReading> fromIdl(const RGNav::OdometryBatch& batch);

}  // namespace rgnav
