// The RG Mapping Kernel's checkpoint: its whole state (RgMapState.h) as two texts.
//   - The map, versioned JSON ({"format": "rgnav-rg-map", "version": 4, ...}): regions, gateways,
//     events, learned costs, the merges on request that can still be undone (RevertibleMerges.h;
//     so an undo survives a restart), and every stored scan by ID with its corrected pose only.
//   - The scan journal: one JSON line per stored scan with its laser data, in ID order. A scan's
//     laser data never change once it is stored, so a checkpoint appends the new scans' lines and
//     rewrites only the map. Scans are the bulk of the state (2 to 4 kB per 361-beam scan): one
//     text holding them all made every checkpoint of a large map cost seconds (lab_b, 19 000
//     scans: 41 MB, 1.9 s), and the kernel module wrote one after nearly every batch.
// The RGMappingKernel server writes both after every change and resumes from them (with
// lastScanId, lastGatewayEventId and lastPoseRevision it knows where to go on in its input
// streams); a resumed kernel goes on exactly as if it had not stopped, and the same state always
// gives the same bytes.
// Numbers: doubles in the shortest form that reads back to the same double; laser ranges in the
// shortest form that reads back to the same float (at most 9 significant digits instead of 17;
// centimetre ranges take 4 or 5 characters); non-finite values as "inf", "-inf" and null (NaN).
#pragma once

#include <string>

#include "core/rgmap/kernel/RgMapState.h"

namespace rgnav {

// The map: the state without the scans' laser data.
std::string serializeRgMap(const RgMapState& state);
// The scan journal's lines of the scans of `state` with IDs above `afterId`, in ID order (each
// line ends in a newline): afterId 0 gives the whole journal, the last checkpoint's lastScanId what
// to append to it.
std::string scanJournalLines(const RgMapState& state, DataId afterId = 0);

// The state from a map and a scan journal. Journal lines of scans the map does not hold (appended
// before a crash, ahead of the map) and a part of a line at its end are ignored. Throws FormatError
// (file "<checkpoint>", line 0) for anything that is not a checkpoint of this format and version,
// a scan of the map that the journal lacks, a state that fails checkConsistency
// (RgMapConsistency.h) or learned costs the cost table refuses.
RgMapState deserializeRgMap(const std::string& text, const std::string& journal);

}  // namespace rgnav
