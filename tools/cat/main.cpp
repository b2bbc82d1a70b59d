// rgnav-cat: follows a module's data by ID through its client library and prints or records it:
// the first real consumer of the data path. It resumes after restarts of the producer (the
// client library reconnects), checks that IDs arrive once and in order, and ends with a summary:
//   cat laser: received=910 first=1 last=910 gaps=0 duplicates=0 reconnects=3
// For the gateway events of the GatewayDetection module it then lists the gateways and counts
// them by class: "gateways: total=… narrow_passages=… hallway=… <class>=…".
#include <chrono>
#include <fstream>
#include <iostream>
#include <map>
#include <thread>

#include "clientlibs/base/BaseClient.h"
#include "clientlibs/gatewaydetection/GatewayDetectionClient.h"
#include "clientlibs/laser/LaserClient.h"
#include "clientlibs/scanmapper/ScanMapperClient.h"
#include "tools/cat/IdSequenceCheck.h"
#include "tools/cat/RecordFormat.h"
#include "tools/common/CommandLine.h"
#include "tools/common/StrictArguments.h"
#include "tools/common/ToolClient.h"

namespace po = boost::program_options;

namespace {

struct Options {
  std::string stream;
  rgnav::DataId after = 0;
  std::uint32_t batch = 100;
  bool follow = false;
  bool quiet = false;
  std::string record;
  int pollMs = 20;
  int retryBudgetMs = 15000;
};

// Follows one stream until its end (or forever with --follow); returns the exit code.
template <class Fetch, class Format>
int follow(const Options& options, Fetch fetch, Format format, const std::function<std::uint64_t()>& reconnects) {
  std::ofstream record;
  if (!options.record.empty()) {
    record.open(options.record, std::ios::trunc);
    if (!record) throw rgnav::FileError(options.record + ": cannot write");
  }
  rgnav::IdSequenceCheck check(options.after);
  for (;;) {
    const auto batch = fetch(check.last(), options.batch);
    for (const auto& item : batch.records) {
      check.observe(recordId(item));
      const std::string line = format(item);
      if (!options.quiet) std::cout << line << '\n';
      if (record) record << line << '\n';
    }
    if (batch.records.empty()) {
      if (batch.endOfData && !options.follow && check.last() >= batch.latestId) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(options.pollMs));
    }
  }
  std::cout.flush();
  std::cout << "cat " << options.stream << ": " << check.summary() << " reconnects=" << reconnects() << std::endl;
  return check.clean() ? 0 : 1;
}

// The gateways with their classes, and a count by class.
void printGatewaySummary(const std::vector<rgnav::GatewayRecord>& gateways) {
  std::map<std::string, std::size_t> byClass;
  std::size_t passages = 0;
  for (const rgnav::GatewayRecord& g : gateways) {
    std::cout << "  " << rgnav::formatGateway(g) << '\n';
    ++byClass[g.label()];
    passages += g.kind == rgnav::GatewayKind::NarrowPassage;
  }
  std::cout << "gateways: total=" << gateways.size() << " narrow_passages=" << passages
            << " hallway=" << gateways.size() - passages;
  for (const auto& [name, count] : byClass) std::cout << ' ' << name << '=' << count;
  std::cout << std::endl;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  std::string naming, robot, consumer;
  po::options_description desc("rgnav-cat <laser|odometry|corrected|gateways> [options]");
  desc.add_options()
      ("help", "this text")
      ("stream", po::value(&options.stream)->required(), "laser, odometry, corrected (ScanMapper) or gateways (GatewayDetection events)")
      ("naming", po::value(&naming)->default_value(""), "naming service host:port (default: RGNAV_NAMING or 127.0.0.1:2809)")
      ("robot", po::value(&robot)->default_value(""), "robot name (default: RGNAV_ROBOT or tumbot)")
      ("consumer", po::value(&consumer)->default_value("rgnav-cat"),
       "name this reader gives the producer; a producer replaying as fast as consumed waits for it ('' for none)")
      ("after", rgnav::strictOption(&options.after, "--after")->default_value("0"), "start after this ID")
      ("batch", rgnav::strictOption(&options.batch, "--batch")->default_value("100"), "records per request")
      ("follow", po::bool_switch(&options.follow), "keep following after the end of data")
      ("quiet", po::bool_switch(&options.quiet), "print only the summary")
      ("record", po::value(&options.record)->default_value(""), "also write every record to this file")
      ("poll-ms", rgnav::strictOption(&options.pollMs, "--poll-ms")->default_value("20"), "wait between empty requests")
      ("retry-budget-ms", rgnav::strictOption(&options.retryBudgetMs, "--retry-budget-ms")->default_value("15000"),
       "give up on a module that stops answering after this (one never reached: after 1.5 s)");
  po::positional_options_description positional;
  positional.add("stream", 1);
  try {
    if (!rgnav::parseCommandLine(argc, argv, desc, positional)) return 0;
    rgnav::ClientSettings settings = rgnav::toolClientSettings(naming, robot);
    settings.retryBudget = std::chrono::milliseconds(options.retryBudgetMs);
    settings.consumer = consumer;
    if (options.stream == "laser") {
      rgnav::LaserClient laser(settings);
      return follow(options, [&](rgnav::DataId after, std::uint32_t n) { return laser.scansSince(after, n); },
                    rgnav::formatScan, [&] { return laser.reconnects(); });
    }
    if (options.stream == "corrected") {
      rgnav::ScanMapperClient mapper(settings);
      return follow(
          options,
          [&](rgnav::DataId after, std::uint32_t n) {
            rgnav::CorrectedBatch batch = mapper.correctedSince(after, n);
            return rgnav::DataBatch<rgnav::CorrectedScan>{std::move(batch.scans), 0, batch.latestId, batch.endOfData};
          },
          rgnav::formatCorrected, [&] { return mapper.reconnects(); });
    }
    if (options.stream == "odometry") {
      rgnav::BaseClient base(settings);
      return follow(options, [&](rgnav::DataId after, std::uint32_t n) { return base.odometrySince(after, n); },
                    rgnav::formatOdometry, [&] { return base.reconnects(); });
    }
    if (options.stream == "gateways") {
      rgnav::GatewayDetectionClient detection(settings);
      const int code = follow(
          options,
          [&](rgnav::DataId after, std::uint32_t n) {
            rgnav::GatewayEventBatch batch = detection.eventsSince(after, n);
            return rgnav::DataBatch<rgnav::GatewayEvent>{std::move(batch.events), 0, batch.latestId, batch.endOfData};
          },
          rgnav::formatGatewayEvent, [&] { return detection.reconnects(); });
      printGatewaySummary(detection.gateways());
      return code;
    }
    throw rgnav::InvalidArgumentError("unknown stream '" + options.stream +
                                      "' (laser, odometry, corrected or gateways)");
  } catch (const po::error& e) {
    std::cerr << "rgnav-cat: " << e.what() << "\n" << desc << std::endl;
  } catch (const rgnav::ModuleUnavailableError& e) {
    rgnav::reportUnreachable("rgnav-cat", e, true);
  } catch (const std::exception& e) {
    std::cerr << "rgnav-cat: " << e.what() << std::endl;
  }
  return 2;
}
