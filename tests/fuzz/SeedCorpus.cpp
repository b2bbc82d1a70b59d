// rgnav-fuzz-seeds <project root> <seed dir>: writes the seed inputs of every fuzz target into
// <seed dir>/<target>/: the heads of the real logs of ${RGNAV_SHARED}/data/laser (plain, and a
// gzip and an xz one), the YAML files of config/, the gateway HMMs of config/gateways reduced to
// one model and a small synthetic one, and checkpoints the real encoders write for mappers,
// detectors and kernels fed real Intel keyframes or the kernel tests' synthetic tour.
#include <Eigen/Core>
#include <cstddef>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/common/Errors.h"
#include "core/config/DescribedConfig.h"
#include "core/gateways/classify/HmmModelFile.h"
#include "core/gateways/classify/testing/SyntheticHmm.h"
#include "core/gateways/detection/DetectionStateCodec.h"
#include "core/logs/ByteSource.h"
#include "core/logs/IntelJsonKeyframes.h"
#include "core/logs/IntelJsonLogReader.h"
#include "core/logs/LineReader.h"
#include "core/logs/LogTestFiles.h"
#include "core/rgmap/export/RgMapJson.h"
#include "core/rgmap/kernel/RgMapCodec.h"
#include "core/rgmap/kernel/testing/SyntheticTour.h"
#include "core/slam/ScanMapper.h"
#include "core/slam/SlamStateCodec.h"

namespace {

namespace fs = std::filesystem;
using rgnav::testing::sharedData;
using rgnav::testing::writeFile;

// The fuzzers' -max_len: heads of logs stay below it.
constexpr std::size_t kHeadBytes = 12 * 1024;

class SeedWriter {
 public:
  explicit SeedWriter(fs::path dir) : dir_(std::move(dir)) {}

  // The path of seed `name` of `target`; its folder is made.
  std::string file(const std::string& target, const std::string& name) const {
    fs::create_directories(dir_ / target);
    return (dir_ / target / name).string();
  }

  void write(const std::string& target, const std::string& name, const std::string& bytes) const {
    writeFile(file(target, name), bytes);
  }

  void copyYaml(const std::string& target, const fs::path& folder) const {
    for (const auto& entry : fs::recursive_directory_iterator(folder)) {
      if (entry.is_regular_file() && entry.path().extension() == ".yaml") {
        fs::create_directories(dir_ / target);
        fs::copy_file(entry.path(), dir_ / target / entry.path().filename(),
                      fs::copy_options::overwrite_existing);
      }
    }
  }

 private:
  fs::path dir_;
};

// The whole lines of the decoded log `path` that fit in kHeadBytes.
std::string logHead(const std::string& path) {
  rgnav::LineReader lines(path);
  std::string head;
  while (const auto line = lines.next()) {
    if (head.size() + line->text.size() + 1 > kHeadBytes) break;
    head.append(line->text).push_back('\n');
  }
  return head;
}

void carmenSeeds(const SeedWriter& seeds) {
  const std::vector<std::string> logs = {
      "laser/corrected/intel-corrected.log.gz",     "laser/corrected/freiburg-079-corrected.log.gz",
      "laser/corrected/freiburg-101-corrected.log.gz", "laser/corrected/seattle-corrected.log.gz",
      "laser/corrected/orebro-corrected.log.gz",    "laser/graph/flirtlib-intel-lab.log.xz",
      "laser/graph/flirtlib-fr079.log.xz"};
  for (const std::string& log : logs) {
    seeds.write("carmen_reader", fs::path(log).stem().stem().string() + ".log", logHead(sharedData(log)));
  }
  const std::string intel = logHead(sharedData(logs[0]));
  seeds.write("carmen_reader", "intel-head.log.gz", rgnav::testing::gzipCompress(intel.substr(0, 4096)));
  seeds.write("carmen_reader", "intel-head.log.xz", rgnav::testing::xzCompress(intel.substr(0, 4096)));
}

// The first `count` keyframes of an Intel JSON file, in its own form.
std::string intelJsonHead(const std::string& path, std::size_t count) {
  const nlohmann::json all = nlohmann::json::parse(rgnav::readDecoded(path, rgnav::kMaxIntelJsonBytes));
  nlohmann::json head = {{"map", nlohmann::json::object()}};
  for (auto it = all.at("map").begin(); it != all.at("map").end() && head["map"].size() < count; ++it) {
    head["map"][it.key()] = it.value();
  }
  return head.dump(1);
}

void intelJsonSeeds(const SeedWriter& seeds) {
  const std::string raw = intelJsonHead(sharedData("laser/derived/xiaofeng-intel_gfs.json.xz"), 3);
  seeds.write("intel_json_reader", "intel_gfs.json", raw);
  seeds.write("intel_json_reader", "intel_corrected.json",
              intelJsonHead(sharedData("laser/derived/xiaofeng-intel_corrected_log.json.xz"), 2));
  seeds.write("intel_json_reader", "intel_gfs.json.xz", rgnav::testing::xzCompress(raw));
}

std::vector<rgnav::LaserScan> intelScans(std::size_t count) {
  rgnav::IntelJsonLogReader reader(sharedData("laser/derived/xiaofeng-intel_gfs.json.xz"));
  std::vector<rgnav::LaserScan> scans;
  while (scans.size() < count) {
    const auto record = reader.next();
    if (!record) break;
    if (const auto* scan = std::get_if<rgnav::LaserScan>(&*record)) scans.push_back(*scan);
  }
  return scans;
}

void slamSeeds(const SeedWriter& seeds, const std::vector<rgnav::LaserScan>& scans) {
  seeds.write("slam_checkpoint", "empty.slam", rgnav::serializeState({}));
  rgnav::ScanMapper mapper;
  for (std::size_t i = 0; i < scans.size(); ++i) {
    mapper.addScan(scans[i]);
    if (i == 2 || i + 1 == scans.size()) {
      seeds.write("slam_checkpoint", "intel-" + std::to_string(i + 1) + ".slam", rgnav::serializeState(mapper.state()));
    }
  }
}

void detectionSeeds(const SeedWriter& seeds, const std::vector<rgnav::LaserScan>& scans,
                    const rgnav::HmmClassifier& classifier) {
  rgnav::GatewayDetector detector({}, classifier);
  std::vector<rgnav::GatewayEvent> events;
  seeds.write("detection_checkpoint", "empty.json", rgnav::serializeDetection({detector.state(), {}}));
  for (const rgnav::LaserScan& scan : scans) {
    const auto added = detector.addScan(scan, scan.sensorPose);
    events.insert(events.end(), added.begin(), added.end());
  }
  seeds.write("detection_checkpoint", "intel.json", rgnav::serializeDetection({detector.state(), events}));
}

void rgMapSeeds(const SeedWriter& seeds) {
  const auto inputs = rgnav::testing::twoRoomTour().inputs();
  for (const std::size_t count : {std::size_t(2), std::size_t(8), std::size_t(20)}) {
    const rgnav::RgMappingKernel kernel = rgnav::testing::mapped(inputs, count);
    std::string bytes = rgnav::serializeRgMap(kernel.state());
    bytes.push_back('\0');
    bytes += rgnav::scanJournalLines(kernel.state());
    seeds.write("rgmap_checkpoint", "tour-" + std::to_string(count) + ".rgmap", bytes);
  }
}

void rgMapJsonSeeds(const SeedWriter& seeds) {
  const auto inputs = rgnav::testing::twoRoomTour().inputs();
  for (const std::size_t count : {std::size_t(8), std::size_t(inputs.size())})
    seeds.write("rgmap_json", "tour-" + std::to_string(count) + ".rgmap.json",
                rgnav::exportRgMapJson(rgnav::snapshotOf(rgnav::testing::mapped(inputs, count))));
}

void hmmSeeds(const SeedWriter& seeds, const rgnav::HmmClassifier& classifier) {
  rgnav::saveHmmModels(seeds.file("hmm_model_file", "config-first-class.txt"),
                       classifier.subset({classifier.classes().front()}));
  const rgnav::GaussianMixtureHmm small =
      rgnav::testing::leftRightHmm({Eigen::Vector2d(0.0, 1.0), Eigen::Vector2d(2.0, 0.5)}, 0.5, 0.8);
  rgnav::saveHmmModels(seeds.file("hmm_model_file", "synthetic.txt"),
                       rgnav::HmmClassifier({{rgnav::GatewayClass::Hallway, small, 1.0}}));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: rgnav-fuzz-seeds <project root> <seed dir>\n";
    return 2;
  }
  const fs::path root = argv[1];
  try {
    const SeedWriter seeds(argv[2]);
    carmenSeeds(seeds);
    intelJsonSeeds(seeds);
    seeds.copyYaml("set_config", root / "config/sets");
    seeds.copyYaml("set_config", root / "core/supervision/testdata");
    seeds.copyYaml("vector_world", root / "config/worlds");
    seeds.copyYaml("simulation_config", root / "config/sim");
    // The module_config target's first byte picks the module.
    const std::vector<std::string> modules = {"scanmapper", "gatewaydetection", "rgmappingkernel", "pathplanning",
                                                  "lowleveldrive"};
    for (std::size_t m = 0; m < modules.size(); ++m)
      seeds.write("module_config", modules[m],
                  std::string(1, char(m)) + rgnav::readConfigFile((root / "config/modules" / (modules[m] + ".yaml")).string()));
    const std::vector<rgnav::LaserScan> scans = intelScans(40);
    slamSeeds(seeds, std::vector<rgnav::LaserScan>(scans.begin(), scans.begin() + 12));
    const rgnav::HmmClassifier classifier = rgnav::loadHmmModels((root / "config/gateways/gateway-hmms.txt").string());
    detectionSeeds(seeds, scans, classifier);
    rgMapSeeds(seeds);
    rgMapJsonSeeds(seeds);
    hmmSeeds(seeds, classifier);
  } catch (const std::exception& e) {
    std::cerr << "rgnav-fuzz-seeds: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
