// The split of the ten IPA benchmark maps into a tuning set, on which thresholds are chosen, and a
// check set, on which none is (config/eval/ipa-split.yaml, loaded strictly). Every evaluation
// over these maps prints its figures for both sets beside its all-maps figures.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace rgnav {

enum class MapSet { kTuning = 0, kCheck = 1 };

class IpaSplit {
 public:
  IpaSplit(std::vector<std::string> tuning, std::vector<std::string> check);

  // The set of a floor plan given by path (…/lab_a_scan_furnitures.png or …/lab_a_scan.png);
  // ConfigError if the map is in neither set.
  MapSet setOf(const std::string& floorPlanPath) const;

 private:
  std::vector<std::string> tuning_, check_;
};

// Reads the split; ConfigError (naming the key and line) on unknown keys, a missing or empty set,
// or a map named twice. loadIpaSplit adds the file name to the message; FileError if unreadable.
IpaSplit parseIpaSplit(const std::string& yamlText);
IpaSplit loadIpaSplit(const std::string& path);

// The benchmark name of a floor plan: its file stem without "_furnitures".
std::string ipaMapName(const std::string& floorPlanPath);

// Counts (or sums of figures) pooled over all maps and over the maps of each set.
template <class Counts>
struct SplitTotals {
  Counts all, tuning, check;
  std::size_t tuningMaps = 0, checkMaps = 0;
};

// Runs `evaluate(map)` -> Counts (which has add(const Counts&)) once per map and pools the
// results. Every map's set is looked up first, so an unknown map fails before the long run.
template <class Counts, class Evaluate>
SplitTotals<Counts> evaluateMaps(const IpaSplit& split, const std::vector<std::string>& maps, Evaluate evaluate) {
  std::vector<MapSet> sets;
  for (const std::string& map : maps) sets.push_back(split.setOf(map));
  SplitTotals<Counts> totals;
  for (std::size_t i = 0; i < maps.size(); ++i) {
    const Counts counts = evaluate(maps[i]);
    totals.all.add(counts);
    (sets[i] == MapSet::kTuning ? totals.tuning : totals.check).add(counts);
    ++(sets[i] == MapSet::kTuning ? totals.tuningMaps : totals.checkMaps);
  }
  return totals;
}

struct Figure {
  std::string key;
  double value;
};

// Per-set figures of one evaluation, summed or pooled by the caller:
//   "<label>: maps_tuning=N <key>_tuning=<value>… maps_check=M <key>_check=<value>…"
// A set without maps prints its figures as n/a.
std::string splitFiguresLine(const std::string& label, std::size_t tuningMaps, const std::vector<Figure>& tuning,
                             std::size_t checkMaps, const std::vector<Figure>& check);

// The same line with `figures(counts)` of each set.
template <class Counts, class Figures>
std::string splitFiguresLine(const std::string& label, const SplitTotals<Counts>& totals, Figures figures) {
  return splitFiguresLine(label, totals.tuningMaps, figures(totals.tuning), totals.checkMaps, figures(totals.check));
}

}  // namespace rgnav
