// Writing and strict reading of HMM model files, format version 1 (see HmmModelFile.h).
#include "core/gateways/classify/HmmModelFile.h"

#include <charconv>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "core/common/AtomicFile.h"
#include "core/common/Errors.h"
#include "core/gateways/classes/GatewayClassNames.h"
#include "core/logs/Fields.h"
#include "core/logs/LineReader.h"

namespace rgnav {

namespace {

constexpr std::string_view kMagic = "rgnav-gateway-hmms";
constexpr std::size_t kVersion = 1;
constexpr std::size_t kMaxCount = 4096;  // bound on dimension, states and components

// The shortest text that reads back to the same double.
std::string formatNumber(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

// Appends one record: the keyword and the values.
template <typename Values>
void appendRecord(std::string& text, std::string_view keyword, const Values& values) {
  text += keyword;
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    text += ' ';
    text += formatNumber(values(i));
  }
  text += '\n';
}

std::string formatModels(const HmmClassifier& classifier) {
  std::string text = std::string(kMagic) + " " + std::to_string(kVersion) + "\n";
  text += "dimension " + std::to_string(classifier.dimension()) + "\n";
  text += "models " + std::to_string(classifier.models().size()) + "\n";
  for (const GatewayClassModel& model : classifier.models()) {
    const GaussianMixtureHmm& hmm = model.hmm;
    text += "model " + std::string(gatewayClassName(model.gatewayClass)) + " " + formatNumber(model.prior) + " " +
            std::to_string(hmm.stateCount()) + "\n";
    appendRecord(text, "prior", hmm.prior);
    for (Eigen::Index i = 0; i < hmm.stateCount(); ++i) appendRecord(text, "transitions", hmm.transitions.row(i));
    for (const HmmState& state : hmm.states) {
      text += "state " + std::to_string(state.components.size()) + "\n";
      for (std::size_t m = 0; m < state.components.size(); ++m) {
        const MultivariateGaussian& g = state.components[m];
        appendRecord(text, "component", state.mixtureWeights.segment(static_cast<Eigen::Index>(m), 1));
        appendRecord(text, "mean", g.mean());
        for (Eigen::Index r = 0; r < g.dimension(); ++r) appendRecord(text, "covariance", g.covariance().row(r));
      }
    }
  }
  return text + "end\n";
}

// The records of a model file, one at a time, with the line they came from.
class RecordReader {
 public:
  explicit RecordReader(const std::string& path) : lines_(path) {}

  FormatError errorAt(std::size_t line, const std::string& what) const {
    return FormatError(lines_.path(), line, what);
  }
  FormatError error(const std::string& what) const { return errorAt(line_, what); }
  std::size_t line() const { return line_; }

  // Moves to the next record; false at the end of the file.
  bool next() {
    while (const auto line = lines_.next()) {
      line_ = line->number;
      if (line->overLong) throw error("line too long");
      fields_.split(line->text);
      if (fields_.size() > 0 && !fields_[0].starts_with('#')) return true;
    }
    return false;
  }

  // The next record, which must be `keyword` followed by `values` fields.
  Fields& expect(std::string_view keyword, std::size_t values) {
    if (!next()) throw error("file ends before '" + std::string(keyword) + "'");
    if (fields_[0] != keyword) throw error("expected '" + std::string(keyword) + "', found " + quoteField(fields_[0]));
    if (fields_.size() != values + 1) {
      throw error("'" + std::string(keyword) + "' needs " + std::to_string(values) + " values, has " +
                  std::to_string(fields_.size() - 1));
    }
    return fields_;
  }

  std::size_t count(std::string_view keyword, std::size_t min) {
    const std::size_t value = expect(keyword, 1).count(1, keyword, kMaxCount);
    check();
    if (value < min) throw error(std::string(keyword) + " is below " + std::to_string(min));
    return value;
  }

  Eigen::VectorXd vector(std::string_view keyword, std::size_t size) {
    expect(keyword, size).numbers(1, size, keyword, numbers_);
    check();
    return Eigen::Map<const Eigen::VectorXd>(numbers_.data(), static_cast<Eigen::Index>(size));
  }

  // Throws the first failure of the current record's typed field access.
  void check() const {
    if (fields_.failed()) throw error(fields_.failure());
  }

 private:
  LineReader lines_;
  Fields fields_;
  std::vector<double> numbers_;
  std::size_t line_ = 0;
};

MultivariateGaussian readComponent(RecordReader& in, Eigen::Index dimension) {
  const Eigen::VectorXd mean = in.vector("mean", static_cast<std::size_t>(dimension));
  Eigen::MatrixXd covariance(dimension, dimension);
  for (Eigen::Index r = 0; r < dimension; ++r) {
    covariance.row(r) = in.vector("covariance", static_cast<std::size_t>(dimension)).transpose();
  }
  try {
    return MultivariateGaussian(mean, covariance);
  } catch (const InvalidArgumentError& e) {
    throw in.error(e.what());
  }
}

GatewayClassModel readModel(RecordReader& in, Eigen::Index dimension) {
  Fields& header = in.expect("model", 3);
  const std::size_t modelLine = in.line();
  const auto gatewayClass = parseGatewayClass(header[1]);
  if (!gatewayClass) throw in.error("unknown gateway class " + quoteField(header[1]));
  const double classPrior = header.finite(2, "class prior");
  const std::size_t q = header.count(3, "state count", kMaxCount);
  in.check();
  if (!(classPrior > 0.0)) throw in.error("class prior is not positive");
  if (q == 0) throw in.error("model without states");

  GatewayClassModel model{*gatewayClass, {}, classPrior};
  GaussianMixtureHmm& hmm = model.hmm;
  hmm.prior = in.vector("prior", q);
  hmm.transitions.resize(static_cast<Eigen::Index>(q), static_cast<Eigen::Index>(q));
  for (Eigen::Index i = 0; i < hmm.transitions.rows(); ++i) {
    hmm.transitions.row(i) = in.vector("transitions", q).transpose();
  }
  for (std::size_t s = 0; s < q; ++s) {
    HmmState state;
    const std::size_t m = in.count("state", 1);
    state.mixtureWeights.resize(static_cast<Eigen::Index>(m));
    for (std::size_t k = 0; k < m; ++k) {
      state.mixtureWeights[static_cast<Eigen::Index>(k)] = in.vector("component", 1)[0];
      state.components.push_back(readComponent(in, dimension));
    }
    hmm.states.push_back(std::move(state));
  }
  try {
    validateHmm(hmm);
  } catch (const InvalidArgumentError& e) {
    throw in.errorAt(modelLine, e.what());
  }
  return model;
}

}  // namespace

void saveHmmModels(const std::string& path, const HmmClassifier& classifier) {
  writeFileAtomically(path, formatModels(classifier));
}

HmmClassifier loadHmmModels(const std::string& path) {
  RecordReader in(path);
  if (in.count(kMagic, 0) != kVersion) throw in.error("unsupported model file version");
  const auto dimension = static_cast<Eigen::Index>(in.count("dimension", 1));
  const std::size_t modelCount = in.count("models", 1);
  std::vector<GatewayClassModel> models;
  for (std::size_t i = 0; i < modelCount; ++i) models.push_back(readModel(in, dimension));
  in.expect("end", 0);
  const std::size_t endLine = in.line();
  if (in.next()) throw in.error("content after 'end'");
  try {
    return HmmClassifier(std::move(models));
  } catch (const InvalidArgumentError& e) {
    throw in.errorAt(endLine, e.what());
  }
}

}  // namespace rgnav
