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

struct Figure {
  std::string key;
  double value;
};

// Per-set figures of one evaluation, summed or pooled by the caller:
//   "<label>: maps_tuning=N <key>_tuning=<value>… maps_check=M <key>_check=<value>…"
// A set without maps prints its figures as n/a.
std::string splitFiguresLine(const std::string& label, std::size_t tuningMaps, const std::vector<Figure>& tuning,
                             std::size_t checkMaps, const std::vector<Figure>& check);

}  // namespace rgnav
