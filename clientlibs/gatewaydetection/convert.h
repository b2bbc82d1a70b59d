// Conversions between GatewayDetection.idl types and their plain C++ forms.
#pragma once

#include "GatewayDetection.hh"
#include "core/gateways/detection/GatewayEventBatch.h"

namespace rgnav {

RGNav::Point2D toIdl(const Eigen::Vector2d& point);
Eigen::Vector2d fromIdl(const RGNav::Point2D& point);
RGNav::Point2DSeq toIdl(const std::vector<Eigen::Vector2d>& points);
std::vector<Eigen::Vector2d> fromIdl(const RGNav::Point2DSeq& points);
RGNav::ClassProbabilitySeq toIdl(const std::vector<ClassProbability>& classes);
std::vector<ClassProbability> fromIdl(const RGNav::ClassProbabilitySeq& classes);

RGNav::GatewayInfo toIdl(const GatewayRecord& gateway);
GatewayRecord fromIdl(const RGNav::GatewayInfo& gateway);
RGNav::GatewayEvent toIdl(const GatewayEvent& event);
GatewayEvent fromIdl(const RGNav::GatewayEvent& event);
RGNav::GatewayEventBatch toIdl(const GatewayEventBatch& batch);
GatewayEventBatch fromIdl(const RGNav::GatewayEventBatch& batch);

}  // namespace rgnav
