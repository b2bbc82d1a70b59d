// Conversions between Base.idl types and core types (see convert.h).
#include "clientlibs/base/convert.h"

#include "clientlibs/common/convert.h"

namespace rgnav {

RGNav::OdometryBatch toIdl(const DataBatch<OdometryReading>& batch) {
  return RGNav::OdometryBatch{toIdlSeq<RGNav::OdometrySeq>(batch.records, [](const OdometryReading& r) { return toIdl(r); }), batch.oldestId, batch.latestId,
                              batch.endOfData};
}

DataBatch<OdometryReading> fromIdl(const RGNav::OdometryBatch& batch) {
  return DataBatch<OdometryReading>{fromIdlSeq<std::vector<OdometryReading>>(batch.readings, [](const RGNav::Odometry& r) { return fromIdl(r); }), batch.oldestId,
                                    batch.latestId, static_cast<bool>(batch.endOfData)};
}

}  // namespace rgnav
