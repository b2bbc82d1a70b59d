// Conversions between ScanMapper.idl types and their plain C++ forms.
#pragma once

#include "ScanMapper.hh"
#include "core/slam/CorrectedScans.h"

namespace rgnav {

RGNav::CorrectedScan toIdl(const CorrectedScan& scan);
CorrectedScan fromIdl(const RGNav::CorrectedScan& scan);
RGNav::CorrectedScanBatch toIdl(const CorrectedBatch& batch);
CorrectedBatch fromIdl(const RGNav::CorrectedScanBatch& batch);
RGNav::PoseUpdate toIdl(const PoseUpdate& update);
PoseUpdate fromIdl(const RGNav::PoseUpdate& update);
RGNav::PoseRevision toIdl(const PoseRevisionInfo& revision);
PoseRevisionInfo fromIdl(const RGNav::PoseRevision& revision);

}  // namespace rgnav
