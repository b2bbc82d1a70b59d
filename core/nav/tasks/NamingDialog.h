// NamingDialog: the naming dialog of the High-Level Planning module (thesis 6.1.3 and chapter 1:
// "if a human operator specifies a region or object that has no name assigned to it, the system
// initiates a dialog ... requesting additional information from the user"). Ours asks without
// waiting for a task to need the name: when the robot is in a region that has no name and that
// was not asked about yet, a question "name this region?" is queued with an ID, the region and
// where the robot was; any user interface answers it by ID with a name, and the caller names the
// region in the RG Mapping Kernel. Nothing waits for an answer. A question whose region is gone
// (merged into another, or removed) or got a name meanwhile is dropped; a region asked about once
// is not asked about again (also after its question was dropped). No middleware: the module
// (servers/highlevelplanning) feeds it the kernel's current region and region list.
#pragma once

#include <optional>
#include <set>
#include <vector>

#include "core/nav/tasks/NamingQuestion.h"
#include "core/rgmap/kernel/RgMapViews.h"

namespace rgnav {

class NamingDialog {
 public:
  NamingDialog() = default;
  // A dialog restored from a checkpoint (its questions waiting, the regions asked about, the ID
  // the next question gets).
  NamingDialog(std::vector<NamingQuestion> waiting, std::set<RegionId> asked, QuestionId nextId);

  // The robot is in region `current` (none: in no region) at `where` (map frame); `regions` are
  // the map's regions now. Drops questions whose region is no longer among them or has a name;
  // asks about `current` if it has no name and was not asked about. Answers the new question.
  std::optional<NamingQuestion> observe(RegionId current, const Eigen::Vector2d& where,
                                        const std::vector<RegionSummaryView>& regions);
  // Whether observe() would ask about `current` now (so the caller fetches the robot's pose only
  // then).
  bool wouldAsk(RegionId current, const std::vector<RegionSummaryView>& regions) const;
  // The question waiting with `id`; NotAvailableError if none waits (answered, dropped, unknown).
  const NamingQuestion& question(QuestionId id) const;
  // The question's region was named: the question is answered and leaves the queue.
  void answered(QuestionId id);

  const std::vector<NamingQuestion>& waiting() const { return waiting_; }  // oldest first
  const std::set<RegionId>& asked() const { return asked_; }
  QuestionId nextId() const { return nextId_; }

 private:
  std::vector<NamingQuestion> waiting_;
  std::set<RegionId> asked_;
  QuestionId nextId_ = 1;
};

}  // namespace rgnav
