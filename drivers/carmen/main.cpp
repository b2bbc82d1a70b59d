// rgnav-carmen-playback: serves a recorded log (CARMEN plain/.gz/.xz, or the Intel JSON pair)
// as the Laser and Base modules, at real time, k times real time, or as fast as consumed. At the
// end of the log it writes what it read and skipped to its log (LogEndReport) and its status
// counters say it too (log_skipped_lines, log_truncated).
#include <iostream>

#include "core/logs/OpenLog.h"
#include "core/logs/ReplayMode.h"
#include "drivers/carmen/LogEndReport.h"
#include "drivers/carmen/PlaybackStreams.h"
#include "servers/sensors/SensorServants.h"

namespace po = boost::program_options;

int main(int argc, char** argv) {
  std::string log, corrected, speed, laserObject, baseObject;
  double maxRange = 80.0;
  std::size_t buffer = 0;
  std::uint32_t maxBatch = 0;
  po::options_description options("Log playback options");
  options.add_options()
      ("log", po::value(&log)->required(), "log file: CARMEN (.log, .gz, .xz) or Intel JSON (.json[.xz])")
      ("corrected", po::value(&corrected)->default_value(""), "Intel JSON only: the corrected-pose companion file")
      ("speed", po::value(&speed)->default_value("realtime"), "realtime, x<k> (k times real time) or max (as fast as consumed)")
      ("max-range", po::value(&maxRange)->default_value(80.0), "metres; beams at or beyond mean no return")
      ("buffer", po::value(&buffer)->default_value(20000), "scans and odometry readings held for consumers")
      ("max-batch", po::value(&maxBatch)->default_value(500), "most records one call returns")
      ("laser-object", po::value(&laserObject)->default_value("Laser"), "object name of the Laser interface")
      ("base-object", po::value(&baseObject)->default_value("Base"), "object name of the Base interface");
  return rgnav::runServer(argc, argv, options, [&](rgnav::ServerRuntime& runtime) {
    rgnav::LogReaderOptions reader;
    reader.maxRange = maxRange;
    reader.correctedPosesPath = corrected;
    const rgnav::ReplayMode mode = rgnav::parseReplayMode(speed);
    auto streams = std::make_shared<rgnav::PlaybackStreams>(
        std::make_unique<rgnav::LogEndReport>(rgnav::openLog(log, reader), log, std::cerr), mode, buffer,
        rgnav::PlaybackClock(runtime.server().stateDir, log, rgnav::formatReplayMode(mode)));
    runtime.onShutdown([streams] { streams->clock().discard(); });
    runtime.health().addReporter([streams](rgnav::ModuleHealth& health) { streams->report(health); });
    runtime.activate(laserObject, new rgnav::LaserImpl(runtime, streams, maxBatch));
    runtime.activate(baseObject, new rgnav::BaseImpl(runtime, streams, maxBatch));
    std::cerr << "playback of " << log << " (" << rgnav::formatReplayMode(mode) << ")"
              << (streams->clock().resumed() ? ", resumed" : "") << " serving on " << runtime.server().endpoint.str()
              << std::endl;
  });
}
