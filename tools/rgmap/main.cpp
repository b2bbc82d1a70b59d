// rgnav-rgmap: talks to the RG Mapping Kernel module of a running set.
//   rgnav-rgmap build --label demo --out <dir> --name demo
//       follows the map while it is built (a progress line on stderr), waits for the end of the
//       inputs, exports <dir>/<name>.rgmap.json/.svg/.png and prints
//       "<label>: scans=… regions=… gateways=… neutralized=… hypotheses=… scans_per_s=…"
//       (gateways: the map's; hypotheses: detected gateways no region has taken in), for a log
//       playback with " skipped_lines=… truncated=yes|no"; exit 3 if the map is not of the whole
//       log (lines skipped or the log cut short) unless --accept-partial
//   rgnav-rgmap regions | gateways | events
//   rgnav-rgmap name <region> <name> | merge <a> <b> [--force] | unmerge <region>
//   rgnav-rgmap path <region> <x> <y> <region> <x> <y>
//   rgnav-rgmap name-object <region> <x> <y> <name> (x, y in the region frame) | object <name>
//   rgnav-rgmap export <dir> <name> [--occupancy]
// The kernel writes only below its export root (its --export-root): <dir> is relative to it ("":
// the root) or an absolute directory inside it.
// Region IDs and coordinates are checked (StrictArguments.h) before the kernel is asked; a merge
// of regions that share no gateway is refused by the kernel unless --force; `unmerge <region>`
// undoes the latest of the kernel's last merges on request into that region (RevertibleMerges.h)
// and prints the region it restored. Names are printed
// quoted and escaped (QuotedText.h), so no name can forge an output line.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <thread>

#include "clientlibs/rgmappingkernel/RgMappingKernelClient.h"
#include "core/common/Errors.h"
#include "tools/common/CommandLine.h"
#include "tools/common/QuotedText.h"
#include "tools/common/StrictArguments.h"
#include "tools/common/ToolClient.h"
#include "tools/rgmap/LogCompleteness.h"

namespace po = boost::program_options;
using namespace rgnav;

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Exit code of a build whose map is not of the whole log.
constexpr int kPartialMap = 3;

int build(RgMappingKernelClient& kernel, const ClientSettings& settings, const std::string& label, const std::string& out,
          const std::string& name, bool occupancy, bool progress, bool acceptPartial) {
  const auto start = std::chrono::steady_clock::now();
  MapSummaryView s = kernel.summary();
  const DataId first = s.lastScan;
  while (!s.endOfData) {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    s = kernel.summary();
    if (progress) {
      const double rate = double(s.lastScan - first) / std::max(secondsSince(start), 1e-3);
      std::fprintf(stderr, "\r%s: mapping scan %llu (%.0f scans/s), region %llu, %zu regions, %zu gateways   ",
                   label.c_str(), static_cast<unsigned long long>(s.lastScan), rate,
                   static_cast<unsigned long long>(s.current.value()), s.regions, s.gateways);
    }
  }
  const double seconds = secondsSince(start);
  if (progress) std::fprintf(stderr, "\n");
  std::cout << kernel.exportMap(out, name, occupancy);
  const LogCompleteness input = laserLogCompleteness(settings);
  std::printf("%s: scans=%llu regions=%zu gateways=%zu neutralized=%zu hypotheses=%zu scans_per_s=%.1f%s%s\n",
              label.c_str(), static_cast<unsigned long long>(s.lastScan), s.regions, s.gateways, s.neutralised,
              s.hypotheses, double(s.lastScan - first) / std::max(seconds, 1e-3), input.fromLog ? " " : "",
              input.figures.c_str());
  if (input.whole) return 0;
  std::fflush(stdout);
  std::fprintf(stderr, "rgnav-rgmap: the map is not of the whole log (%s; %s)%s\n", input.figures.c_str(),
               input.problem.c_str(), acceptPartial ? ", accepted (--accept-partial)" : "; --accept-partial accepts it");
  return acceptPartial ? 0 : kPartialMap;
}

void printRegions(RgMappingKernelClient& kernel) {
  for (const RegionSummaryView& r : kernel.regions()) {
    std::string name;
    if (!r.name.empty()) name.append(" ").append(quotedText(r.name));
    std::printf("region %llu%s frame=%.2f,%.2f,%.3f scans=%zu gateways=%zu%s\n", static_cast<unsigned long long>(r.id.value()),
                name.c_str(), r.frame.x, r.frame.y, r.frame.theta, r.scans,
                r.gateways.size(), r.finalised ? "" : " (current)");
  }
}

void printGateways(RgMappingKernelClient& kernel) {
  for (const GatewayView& g : kernel.gateways()) {
    std::printf("gateway %llu %s p=%.2f regions=%llu|%llu%s traversals=%zu\n", static_cast<unsigned long long>(g.id.value()),
                g.classes.front().name.c_str(), g.classes.front().probability, static_cast<unsigned long long>(g.sideA.value()),
                static_cast<unsigned long long>(g.sideB.value()), g.neutralised ? " neutralised" : "", g.traversals);
  }
}

void printEvents(RgMappingKernelClient& kernel) {
  for (RgMapEventId after = 0;;) {
    const RgMapEventBatch batch = kernel.eventsSince(after, 500);
    for (const RgMapEvent& e : batch.events) {
      std::printf("event %llu %s region=%llu other=%llu gateway=%llu scan=%llu\n", static_cast<unsigned long long>(e.id),
                  std::string(eventKindName(e.kind)).c_str(), static_cast<unsigned long long>(e.region.value()),
                  static_cast<unsigned long long>(e.other.value()), static_cast<unsigned long long>(e.gateway.value()),
                  static_cast<unsigned long long>(e.scanId));
      after = e.id;
    }
    if (batch.events.empty()) return;
  }
}

RegionId regionArgument(const std::string& text) { return RegionId(parseId(text, "region ID")); }

Eigen::Vector2d pointArgument(const std::string& x, const std::string& y) {
  return {parseFiniteNumber(x, "x"), parseFiniteNumber(y, "y")};
}

}  // namespace

int main(int argc, char** argv) {
  std::string command, naming, robot, label, out, name;
  std::vector<std::string> args;
  bool occupancy = false, quiet = false, force = false, acceptPartial = false;
  po::options_description desc("rgnav-rgmap <build|regions|gateways|events|name|name-object|object|merge|unmerge|path|export> [args] [options]");
  desc.add_options()
      ("help", "this text")
      ("command", po::value(&command)->required(), "what to do")
      ("args", po::value(&args)->multitoken(), "the command's arguments")
      ("naming", po::value(&naming)->default_value(""), "naming service host:port (default: RGNAV_NAMING)")
      ("robot", po::value(&robot)->default_value(""), "robot name (default: RGNAV_ROBOT or tumbot)")
      ("label", po::value(&label)->default_value("map"), "build: the summary line's first word")
      ("out", po::value(&out)->default_value(""),
       "build: directory of the exported files, below the kernel's export root (default: the root)")
      ("name", po::value(&name)->default_value("map"), "build: name of the exported files")
      ("occupancy", po::bool_switch(&occupancy), "also export the global metric map (PGM + YAML)")
      ("quiet", po::bool_switch(&quiet), "build: no progress line")
      ("force", po::bool_switch(&force), "merge: also regions that share no gateway")
      ("accept-partial", po::bool_switch(&acceptPartial), "build: exit 0 although the log playback skipped lines or the log ended early");
  po::positional_options_description positional;
  positional.add("command", 1).add("args", -1);
  try {
    if (!parseCommandLine(argc, argv, desc, positional)) return 0;
    ClientSettings settings = toolClientSettings(naming, robot);
    settings.retryBudget = std::chrono::seconds(30);
    RgMappingKernelClient kernel(settings);
    const auto want = [&](std::size_t n) {
      if (args.size() != n) throw InvalidArgumentError(command + " wants " + std::to_string(n) + " arguments");
    };
    if (command == "build") return build(kernel, settings, label, out, name, occupancy, !quiet, acceptPartial);
    if (command == "regions") {
      printRegions(kernel);
    } else if (command == "gateways") {
      printGateways(kernel);
    } else if (command == "events") {
      printEvents(kernel);
    } else if (command == "name") {
      want(2);
      const RegionId region = regionArgument(args[0]);
      kernel.nameRegion(region, args[1]);
    } else if (command == "name-object") {
      want(4);
      const RegionId region = regionArgument(args[0]);
      const Eigen::Vector2d at = pointArgument(args[1], args[2]);
      kernel.nameObject(region, at, args[3]);
    } else if (command == "object") {
      want(1);
      const RgMappingKernel::NamedObject found = kernel.objectByName(args[0]);
      std::printf("object %s region=%llu at=%.2f,%.2f\n", quotedText(args[0]).c_str(),
                  static_cast<unsigned long long>(found.region.value()), found.namedAt.x(), found.namedAt.y());
    } else if (command == "merge") {
      want(2);
      const RegionId a = regionArgument(args[0]), b = regionArgument(args[1]);
      std::printf("merged into region %llu\n", static_cast<unsigned long long>(kernel.mergeRegions(a, b, force).value()));
    } else if (command == "unmerge") {
      want(1);
      const RegionId merged = regionArgument(args[0]);
      const RegionId restored = kernel.unmergeRegions(merged);
      std::printf("region %llu restored from region %llu\n", static_cast<unsigned long long>(restored.value()),
                  static_cast<unsigned long long>(merged.value()));
    } else if (command == "path") {
      want(6);
      const RegionId start = regionArgument(args[0]), goal = regionArgument(args[3]);
      const Eigen::Vector2d from = pointArgument(args[1], args[2]), to = pointArgument(args[4], args[5]);
      const PathView path = kernel.findPath(start, from, goal, to);
      for (const GraphNodeView& n : path.crossings)
        std::printf("crossing gateway=%llu side=%zu region=%llu at=%.2f,%.2f\n", static_cast<unsigned long long>(n.gateway.value()),
                    n.side, static_cast<unsigned long long>(n.region.value()), n.position.x(), n.position.y());
      std::printf("path: cost=%.2f length=%.2f\n", path.costM, path.lengthM);
    } else if (command == "export") {
      want(2);
      std::cout << kernel.exportMap(args[0], args[1], occupancy);
    } else {
      throw InvalidArgumentError("unknown command '" + command + "'");
    }
    return 0;
  } catch (const po::error& e) {
    std::cerr << "rgnav-rgmap: " << e.what() << "\n" << desc << std::endl;
  } catch (const ModuleUnavailableError& e) {
    reportUnreachable("rgnav-rgmap", e, true);
  } catch (const std::exception& e) {
    std::cerr << "rgnav-rgmap: " << e.what() << std::endl;
  }
  return 2;
}
