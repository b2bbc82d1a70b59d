// Stable topological sort of a server set's modules, with cycle reporting.
#include "core/supervision/StartOrder.h"

#include <algorithm>
#include <map>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

std::string describeCycle(const std::vector<ModuleSpec>& modules, const std::map<std::string, std::size_t>& index,
                          const std::vector<bool>& placed) {
  // Every unplaced module waits for another unplaced one, so walking "waits for" must repeat.
  std::vector<std::size_t> walk;
  std::size_t current = static_cast<std::size_t>(std::find(placed.begin(), placed.end(), false) - placed.begin());
  while (std::find(walk.begin(), walk.end(), current) == walk.end()) {
    walk.push_back(current);
    for (const std::string& dep : modules[current].after) {
      const std::size_t d = index.at(dep);
      if (!placed[d]) {
        current = d;
        break;
      }
    }
  }
  std::string text;
  for (auto it = std::find(walk.begin(), walk.end(), current); it != walk.end(); ++it) {
    text += modules[*it].name + " -> ";
  }
  return text + modules[current].name;
}

}  // namespace

std::vector<std::string> startOrder(const std::vector<ModuleSpec>& modules) {
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < modules.size(); ++i) {
    if (!index.emplace(modules[i].name, i).second) {
      throw ConfigError("duplicate module name '" + modules[i].name + "'");
    }
  }
  for (const ModuleSpec& m : modules) {
    for (const std::string& dep : m.after) {
      if (!index.count(dep)) throw ConfigError("module " + m.name + ": after names unknown module '" + dep + "'");
    }
  }
  std::vector<bool> placed(modules.size(), false);
  std::vector<std::string> order;
  while (order.size() < modules.size()) {
    const auto ready = [&](std::size_t i) {
      return !placed[i] && std::all_of(modules[i].after.begin(), modules[i].after.end(),
                                       [&](const std::string& dep) { return placed[index.at(dep)]; });
    };
    std::size_t next = 0;
    while (next < modules.size() && !ready(next)) ++next;
    if (next == modules.size()) {
      throw ConfigError("dependency cycle in after: " + describeCycle(modules, index, placed));
    }
    placed[next] = true;
    order.push_back(modules[next].name);
  }
  return order;
}

std::vector<std::string> stopOrder(const std::vector<ModuleSpec>& modules) {
  std::vector<std::string> order = startOrder(modules);
  std::reverse(order.begin(), order.end());
  return order;
}

}  // namespace rgnav
