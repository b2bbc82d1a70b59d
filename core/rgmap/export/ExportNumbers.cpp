// Rounded numbers of the exports; see ExportNumbers.h.
#include "core/rgmap/export/ExportNumbers.h"

#include <cmath>
#include <cstdio>

#include "core/common/Errors.h"

namespace rgnav {

double roundDecimals(double value, int decimals) {
  if (!std::isfinite(value)) return value;
  // k / 10^d with both exact doubles is the double nearest to the decimal k * 10^-d.
  const double scale = std::pow(10.0, decimals);
  return std::round(value * scale) / scale + 0.0;
}

std::string decimalText(double value, int decimals) {
  if (!std::isfinite(value)) throw InvalidArgumentError("export: cannot write a non-finite number");
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  std::string out(text);
  if (out.find('.') != std::string::npos) {
    out.erase(out.find_last_not_of('0') + 1);
    if (out.back() == '.') out.pop_back();
  }
  return out == "-0" ? "0" : out;
}

}  // namespace rgnav
