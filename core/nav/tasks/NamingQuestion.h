// NamingQuestion: a question of the naming dialog (thesis 6.1.3, chapter 1: the system asks the
// user for the names of places; idl/HighLevelPlanning.idl): "name this region?" about a region that
// has no name, with where the robot was when it asked. Answered by its ID with a name
// (NamingDialog.h).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>

#include "core/rgmap/graph/RgGraphKeys.h"

namespace rgnav {

using QuestionId = std::uint64_t;  // 1, 2, 3, ... in the order the dialog asked

struct NamingQuestion {
  QuestionId id = 0;
  RegionId region;
  Eigen::Vector2d where = Eigen::Vector2d::Zero();  // map frame
  std::string text;                                 // what a user interface shows

  friend bool operator==(const NamingQuestion&, const NamingQuestion&) = default;
};

}  // namespace rgnav
