// Text tables of the crossing evaluation; see Tables.h.
#include "tests/eval/crossings/Tables.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

namespace rgnav {
namespace {

constexpr std::size_t kLabelWidth = 26;
constexpr std::size_t kColumnWidth = 13;
constexpr std::size_t kPairColumnWidth = 15;

bool holds(const GatewayConfusionMatrix& m, GatewayClass c) {
  return std::find(m.classes().begin(), m.classes().end(), c) != m.classes().end();
}

// The class's recognition rate, "-" if the matrix has no sequences of it.
std::string rate(const GatewayConfusionMatrix& m, GatewayClass c) {
  if (!holds(m, c) || m.total(c) == 0) return "-";
  char text[16];
  std::snprintf(text, sizeof text, "%.1f%%", 100.0 * m.classAccuracy(c));
  return text;
}

void cell(std::ostream& out, const std::string& text, std::size_t width = kColumnWidth) {
  out << std::string(text.size() < width ? width - text.size() : 1, ' ') << text;
}

void label(std::ostream& out, const std::string& text) {
  out << text << std::string(text.size() < kLabelWidth ? kLabelWidth - text.size() : 1, ' ');
}

// "n/N" test sequences out of approaches; the counter-class only counts sequences.
std::string sequenceCount(const EnvironmentData& data, const EnvironmentResults& r, GatewayClass c) {
  const std::size_t n = holds(r.hmm, c) ? r.hmm.total(c) : 0;
  const auto driven = data.testApproaches.find(c);
  char text[48];
  if (driven == data.testApproaches.end() || c == GatewayClass::Hallway) {
    std::snprintf(text, sizeof text, "%zu", n);
  } else {
    std::snprintf(text, sizeof text, "%zu/%zu", n, driven->second);
  }
  return text;
}

}  // namespace

void printTable42(std::ostream& out, const CrossingData& data, const CrossingResults& results) {
  out << "Table 4.2: recognition rate per class on the test sequences (SOC, ASC; multi-class HMM added);\n"
      << "first row of an environment: test sequences / approaches driven (Hallway: counter-class sequences)\n";
  label(out, "gateway class");
  for (const GatewayClass c : kGatewayClasses) cell(out, std::string(gatewayClassName(c)));
  out << "\n";
  const auto& environments = thesisEnvironments();
  for (std::size_t e = 0; e < environments.size(); ++e) {
    const EnvironmentResults& r = results.environments[e];
    label(out, environments[e].name);
    for (const GatewayClass c : kGatewayClasses) cell(out, sequenceCount(data.environments[e], r, c));
    out << "\n";
    const std::pair<const char*, const GatewayConfusionMatrix*> rows[] = {
        {"  ASC", &r.asc}, {"  SOC - last obs", &r.socLast}, {"  SOC - last but one", &r.socLastButOne},
        {"  HMM", &r.hmm}};
    for (const auto& [name, matrix] : rows) {
      label(out, name);
      for (const GatewayClass c : kGatewayClasses) cell(out, rate(*matrix, c));
      out << "\n";
    }
  }
  out << "\n";
}

void printTable43(std::ostream& out, const CrossingResults& results) {
  out << "Table 4.3: pairwise HMM classification (rate of the first / the second class)\n";
  const auto& environments = thesisEnvironments();
  for (std::size_t e = 0; e < environments.size(); ++e) {
    char name[128];
    std::snprintf(name, sizeof name, "(%zu) %s", e + 1, environments[e].name.c_str());
    label(out, e == 0 ? "environments" : "");
    out << name << "\n";
  }
  label(out, "pair \\ environment");
  for (std::size_t e = 0; e < environments.size(); ++e) {
    char number[32];
    std::snprintf(number, sizeof number, "(%zu)", e + 1);
    cell(out, number, kPairColumnWidth);
  }
  out << "\n";
  for (std::size_t p = 0; p < kTable43Pairs.size(); ++p) {
    const auto& [a, b] = kTable43Pairs[p];
    char pair[64];
    std::snprintf(pair, sizeof pair, "%s/%s", std::string(gatewayClassName(a)).c_str(),
                  std::string(gatewayClassName(b)).c_str());
    label(out, pair);
    for (const EnvironmentResults& r : results.environments) {
      char rates[32];
      std::snprintf(rates, sizeof rates, "%s/%s", rate(r.pairs[p], a).c_str(), rate(r.pairs[p], b).c_str());
      cell(out, rates, kPairColumnWidth);
    }
    out << "\n";
  }
  out << "\n";
}

void printConfusionMatrices(std::ostream& out, const CrossingResults& results) {
  const auto print = [&out](const std::string& title, const GatewayConfusionMatrix& m) {
    out << "Multi-class HMM confusion matrix, " << title << " (rows: true class, columns: decided class)\n"
        << m.toText() << "\n";
  };
  print("all environments", results.hmmAll);
  print("2m slightly + strongly cluttered", results.hmm2mCluttered);
  const auto& environments = thesisEnvironments();
  for (std::size_t e = 0; e < environments.size(); ++e) print(environments[e].name, results.environments[e].hmm);
}

void printLayoutErrors(std::ostream& out, const CrossingResults& results) {
  out << "Multi-class HMM errors per test gateway (one clutter layout of a class): wrong of its test sequences, "
         "and the classes decided instead\n";
  const auto& environments = thesisEnvironments();
  for (std::size_t e = 0; e < environments.size(); ++e) {
    for (const GatewayDecisions& gateway : results.environments[e].gateways) {
      if (gateway.wrong.empty()) continue;
      char line[160];
      std::snprintf(line, sizeof line, "  %-24s %-12s layout %2d: %2zu of %2zu wrong, decided",
                    environments[e].name.c_str(), std::string(gatewayClassName(gateway.truth)).c_str(), gateway.layout,
                    gateway.wrongCount(), gateway.sequences);
      out << line;
      for (const auto& [c, n] : gateway.wrong) out << " " << gatewayClassName(c) << " " << n;
      out << "\n";
    }
  }
  out << "\n";
}

void printFusion(std::ostream& out, const CrossingResults& results) {
  out << "Bayes fusion per gateway (thesis 4.1.4): every test gateway classified once from the sequences of all\n"
      << "its approaches; rate = gateways recognised / gateways (not comparable with the per-sequence rates)\n";
  label(out, "gateway class");
  for (const GatewayClass c : gatewayClassesOnly()) cell(out, std::string(gatewayClassName(c)));
  out << "\n";
  const auto& environments = thesisEnvironments();
  for (std::size_t e = 0; e < environments.size(); ++e) {
    const GatewayConfusionMatrix& fused = results.environments[e].fused;
    label(out, environments[e].name);
    for (const GatewayClass c : gatewayClassesOnly()) {
      char text[48];
      std::snprintf(text, sizeof text, "%s of %zu", rate(fused, c).c_str(), holds(fused, c) ? fused.total(c) : 0);
      cell(out, text);
    }
    out << "\n";
  }
  out << "\n";
}

}  // namespace rgnav
