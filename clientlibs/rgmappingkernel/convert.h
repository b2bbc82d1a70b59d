// Conversions between RGMappingKernel.idl types and the kernel's plain views (RgMapViews.h).
#pragma once

#include "RGMappingKernel.hh"
#include "core/rgmap/kernel/RgMapViews.h"

namespace rgnav {

RGNav::RegionSummary toIdl(const RegionSummaryView& summary);
RegionSummaryView fromIdl(const RGNav::RegionSummary& summary);
RGNav::RegionInfo toIdl(const RegionView& region);
RegionView fromIdl(const RGNav::RegionInfo& region);
RGNav::NamedObject toIdl(const RgMappingKernel::NamedObject& object);
RgMappingKernel::NamedObject fromIdl(const RGNav::NamedObject& object);
RGNav::RgGateway toIdl(const GatewayView& gateway);
GatewayView fromIdl(const RGNav::RgGateway& gateway);
RGNav::RgNode toIdl(const GraphNodeView& node);
GraphNodeView fromIdl(const RGNav::RgNode& node);
RGNav::RgGraphInfo toIdl(const GraphView& graph);
GraphView fromIdl(const RGNav::RgGraphInfo& graph);
RGNav::RgPath toIdl(const PathView& path);
PathView fromIdl(const RGNav::RgPath& path);
RGNav::RgMapSummary toIdl(const MapSummaryView& summary);
MapSummaryView fromIdl(const RGNav::RgMapSummary& summary);
RGNav::RgMapEventBatch toIdl(const RgMapEventBatch& batch);
// Throws FormatError for an event kind this program does not know.
RgMapEventBatch fromIdl(const RGNav::RgMapEventBatch& batch);

}  // namespace rgnav
