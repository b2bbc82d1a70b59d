// RevertibleMerges: which merges on request the RG Mapping Kernel can undo (RgMappingKernel.h,
// unmergeRegions). A merge asked for by a user is recorded before it is made (RevertibleMerge,
// RgMapState.h); undoing it restores the absorbed region with its ID, frame, name, scans, object
// names and the gateway sides that named it, and the surviving region as it was.
// An undo is safe only while the merged region is still what the merge made of it: same frame,
// name, object names, gateways and finalisation, the same scans up to the merge, and every gateway
// side that named one of the two regions naming it and no other. Any later change to it (a loop
// closing merging it again, a gateway attached, a repaired traversal splitting it, a name) makes
// the undo refused, since the map would then hold structure learned from the merged region that
// the undo cannot divide between the two.
// Scans taken after the merge: the robot stacks them into the merged region while it stays there.
// They were taken where the robot was when the merge was made, so they go back with that region
// (the absorbed one if the robot was in it), as if the merge had not been made. Once the robot
// has left the merged region after such scans, or entered it later, the undo is refused: scans
// of a later visit cannot be told apart by where the robot entered.
#pragma once

#include <optional>
#include <string>

#include "core/rgmap/kernel/RgMapState.h"

namespace rgnav {

// The record of merging regions `a` and `b` of `state`, taken before the merge (valid IDs).
RevertibleMerge revertibleMerge(const RgMapState& state, RegionId a, RegionId b);

// Why undoing `merge` in `state` is not safe (a sentence naming the change), or nullopt.
std::optional<std::string> whyNotRevertible(const RgMapState& state, const RevertibleMerge& merge);

// Keeps the latest `count` records of state.revertibleMerges.
void keepLatestMerges(RgMapState& state, std::size_t count);

}  // namespace rgnav
