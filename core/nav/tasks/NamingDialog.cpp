// NamingDialog: asking about unnamed regions, dropping questions overtaken by the map, answers
// (see NamingDialog.h).
#include "core/nav/tasks/NamingDialog.h"

#include <algorithm>
#include <cstdio>

#include "core/common/Errors.h"

namespace rgnav {

NamingDialog::NamingDialog(std::vector<NamingQuestion> waiting, std::set<RegionId> asked, QuestionId nextId)
    : waiting_(std::move(waiting)), asked_(std::move(asked)), nextId_(nextId) {}

namespace {

bool unnamed(RegionId id, const std::vector<RegionSummaryView>& regions) {
  auto it = std::find_if(regions.begin(), regions.end(), [&](const RegionSummaryView& r) { return r.id == id; });
  return it != regions.end() && it->name.empty();
}

}  // namespace

bool NamingDialog::wouldAsk(RegionId current, const std::vector<RegionSummaryView>& regions) const {
  return !current.isNone() && !asked_.count(current) && unnamed(current, regions);
}

std::optional<NamingQuestion> NamingDialog::observe(RegionId current, const Eigen::Vector2d& where,
                                                    const std::vector<RegionSummaryView>& regions) {
  std::erase_if(waiting_, [&](const NamingQuestion& q) { return !unnamed(q.region, regions); });
  if (!wouldAsk(current, regions)) return std::nullopt;
  asked_.insert(current);
  char text[96];
  std::snprintf(text, sizeof text, "name this region? (region %llu, robot at %.1f %.1f)",
                static_cast<unsigned long long>(current.value()), where.x(), where.y());
  waiting_.push_back({nextId_++, current, where, text});
  return waiting_.back();
}

const NamingQuestion& NamingDialog::question(QuestionId id) const {
  auto it = std::find_if(waiting_.begin(), waiting_.end(), [&](const NamingQuestion& q) { return q.id == id; });
  if (it == waiting_.end()) throw NotAvailableError("no question " + std::to_string(id) + " waits for an answer");
  return *it;
}

void NamingDialog::answered(QuestionId id) {
  std::erase_if(waiting_, [&](const NamingQuestion& q) { return q.id == id; });
}

}  // namespace rgnav
