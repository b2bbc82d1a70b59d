// Test helpers of the RG Map exports; see ExportedFloor.h.
#include "core/rgmap/export/testing/ExportedFloor.h"

#include <vector>

#include "core/rgmap/kernel/testing/SyntheticTour.h"

namespace rgnav::testing {

namespace {

RgMappingKernel mappedTour(const SyntheticTour& tour) { return mapped(tour.inputs(), tour.inputs().size()); }

}  // namespace

RgMappingKernel twoRoomMap() { return mappedTour(twoRoomTour()); }
RgMappingKernel ringMap() { return mappedTour(ringTour()); }

std::string unbalancedTags(const std::string& xml) {
  std::vector<std::string> open;
  std::size_t roots = 0;
  for (std::size_t at = xml.find('<'); at != std::string::npos; at = xml.find('<', at + 1)) {
    const std::size_t end = xml.find('>', at);
    if (end == std::string::npos) return "a tag is not closed";
    const std::string tag = xml.substr(at + 1, end - at - 1);
    if (tag.starts_with('?')) continue;
    const std::size_t nameEnd = tag.find_first_of(" \n/", tag.starts_with('/') ? 1 : 0);
    if (tag.starts_with('/')) {
      const std::string name = tag.substr(1, nameEnd == std::string::npos ? std::string::npos : nameEnd - 1);
      if (open.empty() || open.back() != name) return "</" + name + "> closes nothing open";
      open.pop_back();
      continue;
    }
    if (open.empty()) ++roots;
    if (!tag.ends_with('/')) open.push_back(tag.substr(0, nameEnd));
  }
  if (!open.empty()) return "<" + open.back() + "> is never closed";
  return roots == 1 ? std::string() : std::to_string(roots) + " root elements";
}

}  // namespace rgnav::testing
