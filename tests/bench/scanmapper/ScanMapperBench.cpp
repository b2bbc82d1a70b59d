// rgnav-bench-scanmapper: end-to-end throughput of the mapping data path on a real server set:
// log playback (as fast as consumed) -> ScanMapper -> this consumer, over a whole log (default:
// the Intel keyframes with their raw odometry). The clock runs from the first request to the
// last corrected scan. Last line: scanmapper: log=… scans=… seconds=… scans_per_s=…
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "clientlibs/scanmapper/ScanMapperClient.h"
#include "tests/support/cluster/Interruption.h"
#include "tests/support/cluster/TestCluster.h"
#include "tools/common/CommandLine.h"

namespace po = boost::program_options;
using namespace rgnav;
using namespace rgnav::testing;

int main(int argc, char** argv) {
  std::string log = TestCluster::shared("data/laser/derived/xiaofeng-intel_gfs.json.xz");
  std::string corrected = TestCluster::shared("data/laser/derived/xiaofeng-intel_corrected_log.json.xz");
  po::options_description desc("rgnav-bench-scanmapper [options]");
  desc.add_options()
      ("help", "this text")
      ("log", po::value(&log)->default_value(log), "log to replay")
      ("corrected", po::value(&corrected)->default_value(corrected), "Intel JSON companion ('' for none)");
  try {
    if (!parseCommandLine(argc, argv, desc)) return 0;
    catchInterruptions();  // a stopped run still shuts its server set down and removes its directory
    std::vector<std::string> playback{TestCluster::program("rgnav-carmen-playback"), "--log", log, "--speed", "max"};
    if (!corrected.empty()) playback.insert(playback.end(), {"--corrected", corrected});
    TestCluster cluster({{"LogPlayback", playback, {"Laser", "Base"}},
                         {"ScanMapper",
                          {TestCluster::program("rgnav-scanmapper"), "--config", TestCluster::moduleConfig("scanmapper")},
                          {"ScanMapper"},
                          {"LogPlayback"}}});
    cluster.start();
    ClientSettings settings = cluster.clientSettings();
    settings.consumer = "bench";
    ScanMapperClient mapper(settings);
    const auto start = std::chrono::steady_clock::now();
    DataId last = 0;
    for (;;) {
      throwIfInterrupted();
      const CorrectedBatch batch = mapper.correctedSince(last, 500);
      if (!batch.scans.empty()) last = batch.scans.back().scan.id;
      if (batch.scans.empty() && batch.endOfData) break;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("scanmapper: log=%s scans=%llu seconds=%.2f scans_per_s=%.1f\n",
                std::filesystem::path(log).filename().c_str(), static_cast<unsigned long long>(last), seconds,
                double(last) / seconds);
    return 0;
  } catch (const po::error& e) {
    std::cerr << "rgnav-bench-scanmapper: " << e.what() << "\n" << desc << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-bench-scanmapper: " << e.what() << std::endl;
  }
  return 2;
}
