// Confusion matrix and recognition rates (thesis 4.1.4; see GatewayConfusionMatrix.h).
#include "core/gateways/classify/GatewayConfusionMatrix.h"

#include <algorithm>
#include <cstdio>
#include <utility>

#include "core/common/Errors.h"

namespace rgnav {

GatewayConfusionMatrix::GatewayConfusionMatrix(std::vector<GatewayClass> classes) : classes_(std::move(classes)) {
  if (classes_.empty()) throw InvalidArgumentError("confusion matrix without classes");
  for (auto it = classes_.begin(); it != classes_.end(); ++it) {
    if (std::find(classes_.begin(), it, *it) != it) {
      throw InvalidArgumentError("confusion matrix lists " + std::string(gatewayClassName(*it)) + " twice");
    }
  }
  const auto n = static_cast<Eigen::Index>(classes_.size());
  counts_.setZero(n, n);
}

Eigen::Index GatewayConfusionMatrix::indexOf(GatewayClass c) const {
  const auto it = std::find(classes_.begin(), classes_.end(), c);
  if (it == classes_.end()) {
    throw InvalidArgumentError(std::string(gatewayClassName(c)) + " is not a class of the confusion matrix");
  }
  return it - classes_.begin();
}

void GatewayConfusionMatrix::add(GatewayClass truth, GatewayClass decided) {
  ++counts_(indexOf(truth), indexOf(decided));
}

std::size_t GatewayConfusionMatrix::count(GatewayClass truth, GatewayClass decided) const {
  return counts_(indexOf(truth), indexOf(decided));
}

std::size_t GatewayConfusionMatrix::total(GatewayClass truth) const { return counts_.row(indexOf(truth)).sum(); }

std::size_t GatewayConfusionMatrix::total() const { return counts_.sum(); }

double GatewayConfusionMatrix::classAccuracy(GatewayClass truth) const {
  const std::size_t n = total(truth);
  if (n == 0) throw NotAvailableError("no sequences of class " + std::string(gatewayClassName(truth)));
  return static_cast<double>(count(truth, truth)) / static_cast<double>(n);
}

double GatewayConfusionMatrix::accuracy() const {
  if (total() == 0) throw NotAvailableError("empty confusion matrix");
  return static_cast<double>(counts_.diagonal().sum()) / static_cast<double>(total());
}

Eigen::VectorXd GatewayConfusionMatrix::classAccuracies() const {
  std::vector<double> rates;
  for (const GatewayClass c : classes_) {
    if (total(c) > 0) rates.push_back(classAccuracy(c));
  }
  if (rates.empty()) throw NotAvailableError("empty confusion matrix");
  return Eigen::Map<const Eigen::VectorXd>(rates.data(), static_cast<Eigen::Index>(rates.size()));
}

double GatewayConfusionMatrix::meanClassAccuracy() const { return classAccuracies().mean(); }

double GatewayConfusionMatrix::minClassAccuracy() const { return classAccuracies().minCoeff(); }

std::string GatewayConfusionMatrix::toText() const {
  char cell[64];
  std::string text = "true \\ decided";
  for (const GatewayClass c : classes_) {
    std::snprintf(cell, sizeof cell, " %12s", std::string(gatewayClassName(c)).c_str());
    text += cell;
  }
  text += "        n   rate\n";
  for (const GatewayClass truth : classes_) {
    std::snprintf(cell, sizeof cell, "%-14s", std::string(gatewayClassName(truth)).c_str());
    text += cell;
    for (const GatewayClass decided : classes_) {
      std::snprintf(cell, sizeof cell, " %12zu", count(truth, decided));
      text += cell;
    }
    const std::size_t n = total(truth);
    if (n > 0) {
      std::snprintf(cell, sizeof cell, " %8zu %5.1f%%\n", n, 100.0 * classAccuracy(truth));
    } else {
      std::snprintf(cell, sizeof cell, " %8zu      -\n", n);
    }
    text += cell;
  }
  return text;
}

}  // namespace rgnav
