// Conversions between ScanMapper.idl types and their plain C++ forms (see convert.h).
#include "clientlibs/scanmapper/convert.h"

#include "clientlibs/common/convert.h"

namespace rgnav {

RGNav::CorrectedScan toIdl(const CorrectedScan& scan) {
  return RGNav::CorrectedScan{toIdl(scan.scan), toIdl(scan.corrected), toIdl(scan.mapped), scan.keyframe};
}

CorrectedScan fromIdl(const RGNav::CorrectedScan& scan) {
  return CorrectedScan{fromIdl(scan.scan), fromIdl(scan.corrected), fromIdl(scan.mapped),
                       static_cast<bool>(scan.keyframe)};
}

RGNav::CorrectedScanBatch toIdl(const CorrectedBatch& batch) {
  return RGNav::CorrectedScanBatch{
      toIdlSeq<RGNav::CorrectedScanSeq>(batch.scans, [](const CorrectedScan& s) { return toIdl(s); }), batch.latestId,
      batch.revision, batch.endOfData};
}

CorrectedBatch fromIdl(const RGNav::CorrectedScanBatch& batch) {
  return CorrectedBatch{
      fromIdlSeq<std::vector<CorrectedScan>>(batch.scans, [](const RGNav::CorrectedScan& s) { return fromIdl(s); }),
      batch.latestId, batch.revision, static_cast<bool>(batch.endOfData)};
}

RGNav::PoseUpdate toIdl(const PoseUpdate& update) { return RGNav::PoseUpdate{update.id, toIdl(update.corrected)}; }

PoseUpdate fromIdl(const RGNav::PoseUpdate& update) { return PoseUpdate{update.id, fromIdl(update.corrected)}; }

RGNav::PoseRevision toIdl(const PoseRevisionInfo& revision) {
  return RGNav::PoseRevision{revision.revision, revision.atScan};
}

PoseRevisionInfo fromIdl(const RGNav::PoseRevision& revision) { return {revision.revision, revision.atScan}; }

}  // namespace rgnav
