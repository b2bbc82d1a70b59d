// PlanStore: the PathPlanning module's latest plans (idl/PathPlanning.idl): numbered from 1 in the
// order they were made, found by ID (for followers: the motion module, the GUI) and by the request
// that made them (a repeated request ID gets its plan back instead of a new one, RequestLog.h's
// rule, kept here with the plans because it must survive a restart like them). It keeps the
// latest `kept` plans; the numbering goes on from the last plan's ID after a restart.
// Its checkpoint is a JSON text ({"format": "rgnav-plans", "version": 1, "nextId", "plans"}) with
// every number written so that it reads back to exactly the same double (JsonForms.h), so a plan
// served after a restart is the very plan served before it. Not thread-safe: the module's lock
// guards it.
#pragma once

#include <cstddef>
#include <deque>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>

#include "core/nav/planning/PlanRecord.h"

namespace rgnav {

// A plan's goal in the checkpoint's form (also the Collision Avoidance's drive checkpoint);
// planGoalFrom throws FormatError for an unknown kind (and the JSON errors readingJson reports).
nlohmann::json planGoalJson(const PlanGoal& goal);
PlanGoal planGoalFrom(const nlohmann::json& j);

class PlanStore {
 public:
  static constexpr std::size_t kKeptPlans = 32;

  explicit PlanStore(std::size_t kept = kKeptPlans);

  // The ID the next plan gets.
  PlanId nextId() const { return nextId_; }
  // Keeps `plan` (its ID must be nextId()), forgetting the oldest beyond the bound.
  void add(PlanRecord plan);

  const PlanRecord* byId(PlanId id) const;
  const PlanRecord* byRequest(std::uint64_t request) const;
  const PlanRecord* last() const { return plans_.empty() ? nullptr : &plans_.back(); }
  std::size_t size() const { return plans_.size(); }

  std::string serialize() const;
  // Throws FormatError naming `source` for a text that is not such a checkpoint.
  static PlanStore deserialize(const std::string& text, const std::string& source, std::size_t kept = kKeptPlans);

 private:
  std::size_t kept_;
  PlanId nextId_ = 1;
  std::deque<PlanRecord> plans_;  // ascending ID
};

}  // namespace rgnav
