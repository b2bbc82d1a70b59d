// Conversions between Laser.idl types and core types (see convert.h).
#include "clientlibs/laser/convert.h"

#include "clientlibs/common/convert.h"

namespace rgnav {

RGNav::ScanBatch toIdl(const DataBatch<LaserScan>& batch) {
  return RGNav::ScanBatch{toIdlSeq<RGNav::LaserScanSeq>(batch.records, [](const LaserScan& r) { return toIdl(r); }), batch.oldestId, batch.latestId, batch.endOfData};
}

DataBatch<LaserScan> fromIdl(const RGNav::ScanBatch& batch) {
  return DataBatch<LaserScan>{fromIdlSeq<std::vector<LaserScan>>(batch.scans, [](const RGNav::LaserScan& r) { return fromIdl(r); }), batch.oldestId, batch.latestId,
                              static_cast<bool>(batch.endOfData)};
}

}  // namespace rgnav
