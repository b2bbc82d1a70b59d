// The hostile calls of the bad-clients fault test (see HostileClient.h).
#include "tests/fault/HostileClient.h"

#include <cmath>
#include <limits>
#include <type_traits>

#include "core/common/Errors.h"

namespace rgnav::testing {
namespace {

constexpr std::uint64_t kHugeId = std::numeric_limits<std::uint64_t>::max();
constexpr CORBA::ULong kHugeCount = std::numeric_limits<CORBA::ULong>::max();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::size_t kKeptNotes = 20;

const std::string kOverlong(4096, 'x');  // over every name and path bound of WireChecks.h
const char* const kControl = "bad\nname\x1b[2J";

// Frees what an IDL operation returned to its caller.
template <class T>
void release(T* returned) {
  delete returned;
}
void release(char* returned) { CORBA::string_free(returned); }
template <class T>
void release(const T&) {}

// Adds one call: `f` gets the narrowed reference and makes the raw IDL call.
template <class Iface, class F>
void add(std::vector<HostileCall>& calls, TypedConnection<Iface>& connection, std::string what, F f,
         Idempotence idempotence = Idempotence::Idempotent) {
  const std::string operation = what.substr(what.find('.') + 1);  // the connection names the object
  calls.push_back({std::move(what), [&connection, operation, f, idempotence] {
                     connection.call(
                         operation.c_str(),
                         [&](typename Iface::_ptr_type object) {
                           if constexpr (std::is_void_v<decltype(f(object))>)
                             f(object);
                           else
                             release(f(object));
                         },
                         idempotence);
                   }});
}

}  // namespace

void HostileTally::note(const std::string& what) {
  std::lock_guard lock(mutex_);
  if (notes_.size() < kKeptNotes) notes_.push_back(what);
}

std::vector<std::string> HostileTally::notes() const {
  std::lock_guard lock(mutex_);
  return notes_;
}

HostileClient::HostileClient(const ClientSettings& settings, const HostPort& watchdog, ExportTraps traps,
                             bool groundTruth, bool demoModules, unsigned seed)
    : laser_("Laser", settings),
      base_("Base", settings),
      groundTruth_("GroundTruth", settings),
      scanMapper_("ScanMapper", settings),
      detection_("GatewayDetection", settings),
      kernel_("RGMappingKernel", settings),
      planning_("PathPlanning", settings),
      drive_("LowLevelDrive", settings),
      localization_("Localization", settings),
      watchdog_("Watchdog", settings, watchdog),
      requests_(std::uint64_t(seed) << 32) {
  addSensorCalls();
  if (groundTruth) addGroundTruthCalls();
  addScanMapperCalls();
  addDetectionCalls();
  addKernelCalls(traps);
  if (demoModules) {
    addPathPlanningCalls();
    addLowLevelDriveCalls();
    addLocalizationCalls();
  }
  addWatchdogCalls();
  next_ = seed % calls_.size();
}

void HostileClient::addSensorCalls() {
  std::vector<HostileCall>& c = calls_;
  using L = RGNav::Laser_ptr;
  using B = RGNav::Base_ptr;
  add(c, laser_, "Laser.ping", [](L l) { l->ping(); });
  add(c, laser_, "Laser.status", [](L l) { return l->status(); });
  add(c, laser_, "Laser.latestId", [](L l) { return l->latestId(); });
  add(c, laser_, "Laser.oldestId", [](L l) { return l->oldestId(); });
  add(c, laser_, "Laser.scansSince(huge)", [](L l) { return l->scansSince(kHugeId, kHugeCount, ""); });
  add(c, laser_, "Laser.scansSince(overlong consumer)", [](L l) { return l->scansSince(0, 0, kOverlong.c_str()); });
  add(c, laser_, "Laser.scansSince(control consumer)", [](L l) { return l->scansSince(0, kHugeCount, kControl); });
  add(c, laser_, "Laser.scan(0)", [](L l) { return l->scan(0); });
  add(c, laser_, "Laser.scan(huge)", [](L l) { return l->scan(kHugeId); });
  add(c, base_, "Base.latestOdometryId", [](B b) { return b->latestOdometryId(); });
  add(c, base_, "Base.odometrySince(huge)", [](B b) { return b->odometrySince(kHugeId, kHugeCount, kControl); });
  add(c, base_, "Base.odometryAt(bad nsec)", [](B b) { return b->odometryAt(RGNav::Time{-1, 2000000000u}); });
  add(c, base_, "Base.odometryAt(far past)",
      [](B b) { return b->odometryAt(RGNav::Time{std::numeric_limits<CORBA::LongLong>::min(), 0}); });
  add(c, base_, "Base.setVelocity(NaN)", [](B b) { b->setVelocity(kNaN, kInf); }, Idempotence::NotIdempotent);
  add(c, base_, "Base.setVelocity(-inf)", [](B b) { b->setVelocity(-kInf, 0.0); }, Idempotence::NotIdempotent);
  // A well-formed command that neither a log playback nor a touring simulator carries out.
  add(c, base_, "Base.setVelocity(while touring)", [](B b) { b->setVelocity(0.2, 0.1); }, Idempotence::NotIdempotent);
}

void HostileClient::addGroundTruthCalls() {
  std::vector<HostileCall>& c = calls_;
  using T = RGNav::GroundTruth_ptr;
  add(c, groundTruth_, "GroundTruth.ping", [](T t) { t->ping(); });
  add(c, groundTruth_, "GroundTruth.status", [](T t) { return t->status(); });
  add(c, groundTruth_, "GroundTruth.truePose(0)", [](T t) { return t->truePose(0); });
  add(c, groundTruth_, "GroundTruth.truePose(huge)", [](T t) { return t->truePose(kHugeId); });
  add(c, groundTruth_, "GroundTruth.roomAt(NaN)", [](T t) { return t->roomAt(kNaN, 0.0); });
  add(c, groundTruth_, "GroundTruth.roomAt(inf)", [](T t) { return t->roomAt(kInf, -kInf); });
  add(c, groundTruth_, "GroundTruth.roomAt(far)", [](T t) { return t->roomAt(1e308, -1e308); });
  add(c, groundTruth_, "GroundTruth.roomCount", [](T t) { return t->roomCount(); });
  add(c, groundTruth_, "GroundTruth.doorLines", [](T t) { return t->doorLines(); });
  add(c, groundTruth_, "GroundTruth.people", [](T t) { return t->people(); });
}

void HostileClient::addScanMapperCalls() {
  std::vector<HostileCall>& c = calls_;
  using S = RGNav::ScanMapper_ptr;
  add(c, scanMapper_, "ScanMapper.ping", [](S s) { s->ping(); });
  add(c, scanMapper_, "ScanMapper.status", [](S s) { return s->status(); });
  add(c, scanMapper_, "ScanMapper.latestCorrectedId", [](S s) { return s->latestCorrectedId(); });
  add(c, scanMapper_, "ScanMapper.revision", [](S s) { return s->revision(); });
  add(c, scanMapper_, "ScanMapper.correctedSince(huge)",
      [](S s) { return s->correctedSince(kHugeId, kHugeCount, kOverlong.c_str()); });
  add(c, scanMapper_, "ScanMapper.correctedSince(control)", [](S s) { return s->correctedSince(0, 0, kControl); });
  add(c, scanMapper_, "ScanMapper.poses(0, 0)", [](S s) { return s->poses(0, 0); });
  add(c, scanMapper_, "ScanMapper.poses(reversed)", [](S s) { return s->poses(5, 1); });
  add(c, scanMapper_, "ScanMapper.poses(all)", [](S s) { return s->poses(1, kHugeId); });
  add(c, scanMapper_, "ScanMapper.revisionsSince(huge)", [](S s) { return s->revisionsSince(kHugeId, kControl); });
  add(c, scanMapper_, "ScanMapper.revisionsSince(overlong)", [](S s) { return s->revisionsSince(0, kOverlong.c_str()); });
  add(c, scanMapper_, "ScanMapper.revisedPoses(huge)", [](S s) { return s->revisedPoses(kHugeId, 1, 2); });
  add(c, scanMapper_, "ScanMapper.revisedPoses(reversed)", [](S s) { return s->revisedPoses(0, 2, 1); });
  add(c, scanMapper_, "ScanMapper.correctedPose(0)", [](S s) { return s->correctedPose(0); });
  add(c, scanMapper_, "ScanMapper.correctedPose(huge)", [](S s) { return s->correctedPose(kHugeId); });
  add(c, scanMapper_, "ScanMapper.odomToMap(NaN)", [](S s) { return s->odomToMap(1, RGNav::Pose2D{kNaN, 0.0, 0.0}); });
  add(c, scanMapper_, "ScanMapper.odomToMap(inf)",
      [](S s) { return s->odomToMap(kHugeId, RGNav::Pose2D{kInf, -kInf, kNaN}); });
}

void HostileClient::addDetectionCalls() {
  std::vector<HostileCall>& c = calls_;
  using G = RGNav::GatewayDetection_ptr;
  add(c, detection_, "GatewayDetection.ping", [](G g) { g->ping(); });
  add(c, detection_, "GatewayDetection.status", [](G g) { return g->status(); });
  add(c, detection_, "GatewayDetection.eventsSince(huge)",
      [](G g) { return g->eventsSince(kHugeId, kHugeCount, kOverlong.c_str()); });
  add(c, detection_, "GatewayDetection.eventsSince(control)", [](G g) { return g->eventsSince(0, 0, kControl); });
  add(c, detection_, "GatewayDetection.gateways", [](G g) { return g->gateways(); });
  add(c, detection_, "GatewayDetection.gatewayById(0)", [](G g) { return g->gatewayById(0); });
  add(c, detection_, "GatewayDetection.gatewayById(huge)", [](G g) { return g->gatewayById(kHugeId); });
  add(c, detection_, "GatewayDetection.lastProcessedScan", [](G g) { return g->lastProcessedScan(); });
  add(c, detection_, "GatewayDetection.detectsHallways", [](G g) { return g->detectsHallways(); });
}

void HostileClient::addKernelCalls(const ExportTraps& traps) {
  std::vector<HostileCall>& c = calls_;
  using K = RGNav::RGMappingKernel_ptr;
  const RGNav::Point2D nan{kNaN, 0.0}, inf{kInf, -kInf}, origin{0.0, 0.0};
  constexpr auto once = Idempotence::NotIdempotent;
  add(c, kernel_, "RGMappingKernel.ping", [](K k) { k->ping(); });
  add(c, kernel_, "RGMappingKernel.status", [](K k) { return k->status(); });
  add(c, kernel_, "RGMappingKernel.summary", [](K k) { return k->summary(); });
  add(c, kernel_, "RGMappingKernel.currentRegion", [](K k) { return k->currentRegion(); });
  add(c, kernel_, "RGMappingKernel.regionById(0)", [](K k) { return k->regionById(0); });
  add(c, kernel_, "RGMappingKernel.regionById(huge)", [](K k) { return k->regionById(kHugeId); });
  add(c, kernel_, "RGMappingKernel.regions", [](K k) { return k->regions(); });
  add(c, kernel_, "RGMappingKernel.gateways", [](K k) { return k->gateways(); });
  add(c, kernel_, "RGMappingKernel.graph", [](K k) { return k->graph(); });
  add(c, kernel_, "RGMappingKernel.findPath(NaN)", [=](K k) { return k->findPath(1, nan, 1, origin); });
  add(c, kernel_, "RGMappingKernel.findPath(unknown, inf)", [=](K k) { return k->findPath(kHugeId, origin, 1, inf); });
  add(c, kernel_, "RGMappingKernel.findPath(far)",
      [=](K k) { return k->findPath(1, RGNav::Point2D{1e308, -1e308}, 2, origin); });
  add(c, kernel_, "RGMappingKernel.nameRegion(request 0)", [](K k) { k->nameRegion(0, 1, "kitchen"); }, once);
  add(c, kernel_, "RGMappingKernel.nameRegion(control)", [this](K k) { k->nameRegion(requestId(), 1, kControl); }, once);
  add(c, kernel_, "RGMappingKernel.nameRegion(overlong)",
      [this](K k) { k->nameRegion(requestId(), 1, kOverlong.c_str()); }, once);
  add(c, kernel_, "RGMappingKernel.nameRegion(unknown)",
      [this](K k) { k->nameRegion(requestId(), kHugeId, "nowhere"); }, once);
  add(c, kernel_, "RGMappingKernel.regionByName(empty)", [](K k) { return k->regionByName(""); });
  add(c, kernel_, "RGMappingKernel.regionByName(control)", [](K k) { return k->regionByName(kControl); });
  add(c, kernel_, "RGMappingKernel.regionByName(overlong)", [](K k) { return k->regionByName(kOverlong.c_str()); });
  add(c, kernel_, "RGMappingKernel.nameObject(NaN)",
      [this, nan](K k) { k->nameObject(requestId(), 1, nan, "cabinet"); }, once);
  add(c, kernel_, "RGMappingKernel.nameObject(unknown)",
      [this, origin](K k) { k->nameObject(requestId(), kHugeId, origin, "desk"); }, once);
  add(c, kernel_, "RGMappingKernel.nameObject(control)",
      [this, origin](K k) { k->nameObject(requestId(), 1, origin, kControl); }, once);
  add(c, kernel_, "RGMappingKernel.objectByName(empty)", [](K k) { return k->objectByName(""); });
  add(c, kernel_, "RGMappingKernel.objectByName(unknown)", [](K k) { return k->objectByName("nothing is named so"); });
  add(c, kernel_, "RGMappingKernel.objectByName(overlong)", [](K k) { return k->objectByName(kOverlong.c_str()); });
  // Every thread merges region 1 with itself and with regions that do not exist, at once.
  add(c, kernel_, "RGMappingKernel.mergeRegions(same)", [this](K k) { return k->mergeRegions(requestId(), 1, 1, false); }, once);
  add(c, kernel_, "RGMappingKernel.mergeRegions(unknown)",
      [this](K k) { return k->mergeRegions(requestId(), 1, kHugeId, false); }, once);
  add(c, kernel_, "RGMappingKernel.mergeRegions(0)", [this](K k) { return k->mergeRegions(requestId(), 0, 1, false); }, once);
  add(c, kernel_, "RGMappingKernel.mergeRegions(request 0)", [](K k) { return k->mergeRegions(0, 1, 2, false); }, once);
  add(c, kernel_, "RGMappingKernel.unmergeRegions(unknown)",
      [this](K k) { return k->unmergeRegions(requestId(), kHugeId); }, once);
  add(c, kernel_, "RGMappingKernel.unmergeRegions(0)", [this](K k) { return k->unmergeRegions(requestId(), 0); }, once);
  add(c, kernel_, "RGMappingKernel.unmergeRegions(request 0)", [](K k) { return k->unmergeRegions(0, 1); }, once);
  add(c, kernel_, "RGMappingKernel.reportDoorState(unknown)",
      [this](K k) { k->reportDoorState(requestId(), kHugeId, false); }, once);
  add(c, kernel_, "RGMappingKernel.reportDoorState(0)", [this](K k) { k->reportDoorState(requestId(), 0, false); }, once);
  add(c, kernel_, "RGMappingKernel.reportTraversal(unknown)",
      [this](K k) { k->reportTraversal(requestId(), kHugeId, 1, 2, 1); }, once);
  add(c, kernel_, "RGMappingKernel.reportTraversal(0)", [this](K k) { k->reportTraversal(requestId(), 0, 1, 2, 1); }, once);
  add(c, kernel_, "RGMappingKernel.reportTraversal(same region)",
      [this](K k) { k->reportTraversal(requestId(), 1, 1, 1, 1); }, once);
  add(c, kernel_, "RGMappingKernel.eventsSince(huge)",
      [](K k) { return k->eventsSince(kHugeId, kHugeCount, kOverlong.c_str()); });
  add(c, kernel_, "RGMappingKernel.eventsSince(control)", [](K k) { return k->eventsSince(0, 0, kControl); });
  add(c, kernel_, "RGMappingKernel.exportMap(/etc)", [](K k) { return k->exportMap("/etc", "badclients", false); }, once);
  add(c, kernel_, "RGMappingKernel.exportMap(up)", [](K k) { return k->exportMap("../..", "badclients", false); }, once);
  add(c, kernel_, "RGMappingKernel.exportMap(link dir)",
      [dir = traps.linkToOutside](K k) { return k->exportMap(dir.c_str(), "badclients", false); }, once);
  add(c, kernel_, "RGMappingKernel.exportMap(link file)",
      [name = traps.linkFile](K k) { return k->exportMap("", name.c_str(), false); }, once);
  add(c, kernel_, "RGMappingKernel.exportMap(name with /)",
      [](K k) { return k->exportMap("", "../../etc/badclients", false); }, once);
  add(c, kernel_, "RGMappingKernel.exportMap(empty name)", [](K k) { return k->exportMap("", "", false); }, once);
  add(c, kernel_, "RGMappingKernel.exportMap(overlong)",
      [](K k) { return k->exportMap(kOverlong.c_str(), "badclients", false); }, once);
  add(c, kernel_, "RGMappingKernel.exportMap(control)", [](K k) { return k->exportMap(kControl, "badclients", false); },
      once);
}

// No call makes a plan (each is refused before planning, or finds none made), so none can end in
// NoPath, and none reports a door.
void HostileClient::addPathPlanningCalls() {
  std::vector<HostileCall>& c = calls_;
  using P = RGNav::PathPlanning_ptr;
  constexpr auto once = Idempotence::NotIdempotent;
  const RGNav::Pose2D origin{0.0, 0.0, 0.0}, nan{kNaN, 0.0, kInf};
  const RGNav::PlanGoal point{RGNav::GOAL_POINT, {1.0, 1.0}, 0, ""};
  add(c, planning_, "PathPlanning.ping", [](P p) { p->ping(); });
  add(c, planning_, "PathPlanning.status", [](P p) { return p->status(); });
  add(c, planning_, "PathPlanning.plan(NaN start)", [=, this](P p) { return p->plan(requestId(), nan, point); }, once);
  add(c, planning_, "PathPlanning.plan(request 0)", [=](P p) { return p->plan(0, origin, point); }, once);
  add(c, planning_, "PathPlanning.plan(inf goal)", [=, this](P p) {
    return p->plan(requestId(), origin, RGNav::PlanGoal{RGNav::GOAL_POINT, {kInf, kNaN}, 0, ""});
  }, once);
  add(c, planning_, "PathPlanning.plan(region 0)", [=, this](P p) {
    return p->plan(requestId(), origin, RGNav::PlanGoal{RGNav::GOAL_REGION, {0.0, 0.0}, 0, ""});
  }, once);
  add(c, planning_, "PathPlanning.plan(overlong name)", [=, this](P p) {
    return p->plan(requestId(), origin, RGNav::PlanGoal{RGNav::GOAL_OBJECT, {0.0, 0.0}, 0, kOverlong.c_str()});
  }, once);
  add(c, planning_, "PathPlanning.plan(control name)", [=, this](P p) {
    return p->plan(requestId(), origin, RGNav::PlanGoal{RGNav::GOAL_REGION_NAME, {0.0, 0.0}, 0, kControl});
  }, once);
  add(c, planning_, "PathPlanning.plan(empty name)", [=, this](P p) {
    return p->plan(requestId(), origin, RGNav::PlanGoal{RGNav::GOAL_OBJECT, {0.0, 0.0}, 0, ""});
  }, once);
  add(c, planning_, "PathPlanning.lastPlan", [](P p) { return p->lastPlan(); });
  add(c, planning_, "PathPlanning.planById(0)", [](P p) { return p->planById(0); });
  add(c, planning_, "PathPlanning.planById(huge)", [](P p) { return p->planById(kHugeId); });
  add(c, planning_, "PathPlanning.replanDoorBlocked(request 0)", [](P p) { return p->replanDoorBlocked(0, 1); }, once);
  add(c, planning_, "PathPlanning.replanDoorBlocked(door 0)",
      [this](P p) { return p->replanDoorBlocked(requestId(), 0); }, once);
  add(c, planning_, "PathPlanning.replanDoorBlocked(no plan)",
      [this](P p) { return p->replanDoorBlocked(requestId(), kHugeId); }, once);
}

void HostileClient::addLocalizationCalls() {
  std::vector<HostileCall>& c = calls_;
  using Z = RGNav::Localization_ptr;
  const RGNav::Pose2D pose{1.5, 7.0, 0.0};
  const RGNav::PoseSigma sigma{0.1, 0.1, 0.05};
  add(c, localization_, "Localization.ping", [](Z z) { z->ping(); });
  add(c, localization_, "Localization.status", [](Z z) { return z->status(); });
  add(c, localization_, "Localization.filterState", [](Z z) { return z->filterState(); });
  // Before its first estimate the module answers NotLocalized, its own typed exception: counted as
  // NotAvailable.
  const auto localized = [](auto call) {
    return [call](Z z) {
      try {
        return call(z);
      } catch (const RGNav::NotLocalized& e) {
        throw NotAvailableError(std::string("NotLocalized: ") + e.message.in());
      }
    };
  };
  add(c, localization_, "Localization.latestEstimate", localized([](Z z) { return z->latestEstimate(); }));
  add(c, localization_, "Localization.estimateByScan(0)", localized([](Z z) { return z->estimateByScan(0); }));
  add(c, localization_, "Localization.estimateByScan(huge)",
      localized([](Z z) { return z->estimateByScan(kHugeId); }));
  add(c, localization_, "Localization.particles(0)", localized([](Z z) { return z->particles(0); }));
  add(c, localization_, "Localization.particles(huge)", localized([](Z z) { return z->particles(kHugeCount); }));
  // setPose with arguments no guess can have; none of them may change the particles.
  add(c, localization_, "Localization.setPose(NaN)", [=](Z z) { z->setPose({kNaN, 7.0, 0.0}, sigma, 0); });
  add(c, localization_, "Localization.setPose(inf theta)", [=](Z z) { z->setPose({1.5, 7.0, kInf}, sigma, 0); });
  add(c, localization_, "Localization.setPose(negative sigma)", [=](Z z) { z->setPose(pose, {-0.1, 0.1, 0.05}, 0); });
  add(c, localization_, "Localization.setPose(NaN sigma)", [=](Z z) { z->setPose(pose, {0.1, 0.1, kNaN}, 0); });
  add(c, localization_, "Localization.setPose(inf sigma)", [=](Z z) { z->setPose(pose, {0.1, kInf, 0.05}, 0); });
}

void HostileClient::addLowLevelDriveCalls() {
  std::vector<HostileCall>& c = calls_;
  using D = RGNav::LowLevelDrive_ptr;
  const RGNav::TrajectorySegment straight{{1.5, 7.0, 0.0}, 1.0, 0.0, 0.0};
  // A chain of `segments` (the straight by default), with one field of it spoilt by `spoil`.
  auto chain = [straight](std::function<void(RGNav::DriveChain&)> spoil, CORBA::ULong segments = 1) {
    RGNav::DriveChain out{kHugeId, {}, 0.0, {0, 0}, 0.0};
    out.segments.length(segments);
    for (CORBA::ULong i = 0; i < segments; ++i) out.segments[i] = straight;
    spoil(out);
    return out;
  };
  const std::vector<std::pair<std::string, RGNav::DriveChain>> chains{
      {"id 0", chain([](RGNav::DriveChain& d) { d.id = 0; })},
      {"NaN start", chain([](RGNav::DriveChain& d) { d.segments[0].start.x = kNaN; })},
      {"inf curvature", chain([](RGNav::DriveChain& d) { d.segments[0].curvature = kInf; })},
      {"negative length", chain([](RGNav::DriveChain& d) { d.segments[0].length = -1.0; })},
      {"no segments", chain([](RGNav::DriveChain&) {}, 0)},
      {"too many segments", chain([](RGNav::DriveChain&) {}, RGNav::MAX_CHAIN_SEGMENTS + 1)},
      {"gap", chain([](RGNav::DriveChain&) {}, 2)},  // the second straight starts where the first did
      {"inf start speed", chain([](RGNav::DriveChain& d) { d.startSpeed = kInf; })},
      {"start speed beyond the limits", chain([](RGNav::DriveChain& d) { d.startSpeed = 1e6; })},
      {"negative cruise speed", chain([](RGNav::DriveChain& d) { d.cruiseSpeed = -0.5; })},
      {"bad nsec", chain([](RGNav::DriveChain& d) { d.startTime.nsec = 2000000000u; })}};
  add(c, drive_, "LowLevelDrive.ping", [](D d) { d->ping(); });
  add(c, drive_, "LowLevelDrive.status", [](D d) { return d->status(); });
  add(c, drive_, "LowLevelDrive.driveStatus", [](D d) { return d->driveStatus(); });
  add(c, drive_, "LowLevelDrive.limits", [](D d) { return d->limits(); });
  // Stopping a drive that stands by changes nothing.
  add(c, drive_, "LowLevelDrive.stop", [](D d) { d->stop(); });
  for (const auto& [what, bad] : chains)
    add(c, drive_, "LowLevelDrive.setChain(" + what + ")", [bad](D d) { d->setChain(bad); });
}

void HostileClient::addWatchdogCalls() {
  std::vector<HostileCall>& c = calls_;
  using W = RGNav::Watchdog_ptr;
  constexpr auto once = Idempotence::NotIdempotent;
  add(c, watchdog_, "Watchdog.ping", [](W w) { w->ping(); });
  add(c, watchdog_, "Watchdog.status", [](W w) { return w->status(); });
  add(c, watchdog_, "Watchdog.modules", [](W w) { return w->modules(); });
  add(c, watchdog_, "Watchdog.describeModule(empty)", [](W w) { return w->describeModule(""); });
  add(c, watchdog_, "Watchdog.describeModule(unknown)", [](W w) { return w->describeModule("Nope"); });
  add(c, watchdog_, "Watchdog.describeModule(overlong)", [](W w) { return w->describeModule(kOverlong.c_str()); });
  add(c, watchdog_, "Watchdog.stopModule(unknown)", [](W w) { w->stopModule("Nope"); }, once);
  add(c, watchdog_, "Watchdog.startModule(empty)", [](W w) { w->startModule(""); }, once);
  add(c, watchdog_, "Watchdog.restartModule(control)", [](W w) { w->restartModule(kControl); }, once);
  add(c, watchdog_, "Watchdog.eventsSince(huge)", [](W w) { return w->eventsSince(kHugeId, kHugeCount); });
  add(c, watchdog_, "Watchdog.eventsSince(0, 0)", [](W w) { return w->eventsSince(0, 0); });
}

void HostileClient::callNext(HostileTally& tally) {
  const HostileCall& call = calls_[next_];
  next_ = (next_ + 1) % calls_.size();
  ++tally.calls;
  try {
    call.run();
    ++tally.accepted;
  } catch (const InvalidArgumentError&) {
    ++tally.invalidArgument;
  } catch (const NotAvailableError&) {
    ++tally.notAvailable;
  } catch (const NotSupportedError&) {
    ++tally.notSupported;
  } catch (const ModuleFailedError& e) {
    ++tally.failed;
    tally.note("failed: " + call.what + ": " + e.what());
  } catch (const ModuleUnavailableError& e) {
    ++tally.unanswered;
    tally.note("unanswered: " + call.what + ": " + e.what());
  } catch (const std::exception& e) {
    ++tally.unknown;
    tally.note("unknown: " + call.what + ": " + e.what());
  }
}

}  // namespace rgnav::testing
