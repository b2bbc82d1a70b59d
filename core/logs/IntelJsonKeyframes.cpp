// IntelJsonKeyframes: JSON parsing with nlohmann::json, per-entry checks, line lookup of the
// entries (in file order) and sorting by stamp.
#include "core/logs/IntelJsonKeyframes.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/common/Errors.h"
#include "core/logs/ByteSource.h"
#include "core/logs/Fields.h"
#include "core/logs/LogSource.h"

namespace rgnav {

namespace {

using Json = nlohmann::ordered_json;

std::size_t newlinesIn(std::string_view text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

// Finds the lines of object keys, given in file order, with one forward pass over the text.
class KeyLines {
 public:
  explicit KeyLines(std::string_view text) : text_(text) {}
  // The line of the next occurrence of "key", or 0 if it cannot be found.
  std::size_t lineOf(const std::string& key) {
    const std::size_t at = text_.find('"' + key + '"', offset_);
    if (at == std::string_view::npos) {
      return 0;
    }
    line_ += newlinesIn(text_.substr(offset_, at - offset_));
    offset_ = at;
    return line_;
  }

 private:
  std::string_view text_;
  std::size_t offset_ = 0;
  std::size_t line_ = 1;
};

bool finiteNumber(const Json& entry, const char* name, double& out) {
  const auto it = entry.find(name);
  if (it == entry.end() || !it->is_number()) {
    return false;
  }
  out = it->get<double>();
  return std::isfinite(out);
}

// Fills `keyframe` from one entry, or says what is wrong with it.
std::string readEntry(const std::string& key, const Json& entry, IntelKeyframe& keyframe) {
  const auto stamp = parseNumber(key);
  if (!stamp || !std::isfinite(*stamp)) {
    return "key is not a timestamp";
  }
  keyframe.stamp = *stamp;
  if (!entry.is_object()) {
    return "entry is not an object";
  }
  if (!finiteNumber(entry, "x", keyframe.pose.x) || !finiteNumber(entry, "y", keyframe.pose.y) ||
      !finiteNumber(entry, "theta", keyframe.pose.theta)) {
    return "missing or non-numeric x, y or theta";
  }
  const auto range = entry.find("range");
  if (range == entry.end() || !range->is_array() || range->empty()) {
    return "missing or empty range array";
  }
  if (range->size() > kMaxBeams) {
    return std::to_string(range->size()) + " beams exceed the limit of " +
           std::to_string(kMaxBeams);
  }
  keyframe.ranges.reserve(range->size());
  for (const auto& beam : *range) {
    if (!beam.is_number()) {
      return "range " + std::to_string(keyframe.ranges.size() + 1) + " is not a number";
    }
    keyframe.ranges.push_back(beam.get<double>());
  }
  return {};
}

Json parseJson(const std::string& path, const std::string& text) {
  try {
    return Json::parse(text);
  } catch (const Json::parse_error& e) {
    const std::size_t at = std::min<std::size_t>(e.byte, text.size());
    throw FormatError(path, newlinesIn(std::string_view(text).substr(0, at)) + 1, e.what());
  } catch (const Json::exception& e) {
    throw FormatError(path, 0, e.what());
  }
}

}  // namespace

IntelKeyframeFile loadIntelKeyframes(const std::string& path, LogStats& stats) {
  const std::string text = readDecoded(path, kMaxIntelJsonBytes);
  const Json document = parseJson(path, text);
  const auto map = document.is_object() ? document.find("map") : document.end();
  if (map == document.end() || !map->is_object()) {
    throw FormatError(path, 1, "expected {\"map\": {\"<stamp>\": {...}, ...}}");
  }
  IntelKeyframeFile file;
  file.lines = newlinesIn(text) + (!text.empty() && text.back() != '\n' ? 1 : 0);
  KeyLines keyLines(text);
  for (const auto& [key, entry] : map->items()) {
    IntelKeyframe keyframe;
    keyframe.line = keyLines.lineOf(key);
    const std::string problem = readEntry(key, entry, keyframe);
    if (problem.empty()) {
      file.keyframes.push_back(std::move(keyframe));
    } else {
      stats.addMalformed(path, keyframe.line, "keyframe " + quoteField(key) + ": " + problem);
    }
  }
  auto& keyframes = file.keyframes;
  std::stable_sort(keyframes.begin(), keyframes.end(),
                   [](const auto& a, const auto& b) { return a.stamp < b.stamp; });
  const auto duplicate = std::adjacent_find(keyframes.begin(), keyframes.end(),
                                            [](const auto& a, const auto& b) {
                                              return a.stamp == b.stamp;
                                            });
  if (duplicate != keyframes.end()) {
    throw FormatError(path, std::next(duplicate)->line,
                      "two keyframes with stamp " + std::to_string(duplicate->stamp));
  }
  return file;
}

}  // namespace rgnav
