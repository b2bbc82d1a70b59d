// GatewayConfusionMatrix: counts of (true class, decided class) pairs for the classification
// experiments of thesis 4.1.4 (tables 4.2 and 4.3 report the per-class recognition rate, i.e.
// the diagonal divided by the row sum), with the overall, mean and minimum per-class accuracy.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "core/gateways/classes/GatewayClass.h"

namespace rgnav {

class GatewayConfusionMatrix {
 public:
  // Throws InvalidArgumentError for no classes or a class given twice.
  explicit GatewayConfusionMatrix(std::vector<GatewayClass> classes = {kGatewayClasses.begin(), kGatewayClasses.end()});

  // Throws InvalidArgumentError for a class that is not in the matrix.
  void add(GatewayClass truth, GatewayClass decided);

  const std::vector<GatewayClass>& classes() const { return classes_; }
  std::size_t count(GatewayClass truth, GatewayClass decided) const;
  std::size_t total(GatewayClass truth) const;  // sequences of this true class
  std::size_t total() const;

  // The recognition rate of one class (its row's diagonal share); NotAvailableError without
  // sequences of that class.
  double classAccuracy(GatewayClass truth) const;
  // Correct decisions over all decisions; NotAvailableError when empty.
  double accuracy() const;
  // Mean and minimum of classAccuracy over the classes that have sequences; NotAvailableError
  // when empty.
  double meanClassAccuracy() const;
  double minClassAccuracy() const;

  // A text table: one row per true class with its count and recognition rate, one column per
  // decided class.
  std::string toText() const;

 private:
  Eigen::Index indexOf(GatewayClass c) const;
  Eigen::VectorXd classAccuracies() const;  // of the classes with sequences

  std::vector<GatewayClass> classes_;
  Eigen::Matrix<std::size_t, Eigen::Dynamic, Eigen::Dynamic> counts_;
};

}  // namespace rgnav
