// Little-endian binary encoding of SlamState (version 2) and its consistency check.
#include "core/slam/SlamStateCodec.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>

namespace rgnav {

namespace {

constexpr std::string_view kMagic{"RGNSLAM\0", 8};
constexpr std::uint32_t kVersion = 2;

class Writer {
 public:
  void bytes(std::string_view b) { out_.append(b); }
  template <typename T>
  void integer(T value) {
    for (std::size_t i = 0; i < sizeof(T); ++i) out_.push_back(static_cast<char>((static_cast<std::uint64_t>(value) >> (8 * i)) & 0xFF));
  }
  void real(double value) { integer(std::bit_cast<std::uint64_t>(value)); }
  void real(float value) { integer(std::bit_cast<std::uint32_t>(value)); }
  void pose(const Pose2D& p) {
    real(p.x);
    real(p.y);
    real(p.theta);
  }
  std::string take() { return std::move(out_); }

 private:
  std::string out_;
};

class Reader {
 public:
  explicit Reader(std::string_view in) : in_(in) {}

  std::string_view bytes(std::size_t n) {
    need(n);
    const std::string_view b = in_.substr(offset_, n);
    offset_ += n;
    return b;
  }
  template <typename T>
  T integer() {
    need(sizeof(T));
    std::uint64_t value = 0;
    for (std::size_t i = 0; i < sizeof(T); ++i)
      value |= static_cast<std::uint64_t>(static_cast<unsigned char>(in_[offset_ + i])) << (8 * i);
    offset_ += sizeof(T);
    return static_cast<T>(value);
  }
  double real64() { return std::bit_cast<double>(integer<std::uint64_t>()); }
  float real32() { return std::bit_cast<float>(integer<std::uint32_t>()); }
  Pose2D pose() {
    Pose2D p;
    p.x = real64();
    p.y = real64();
    p.theta = real64();
    return p;
  }
  // A count of elements of at least `elementBytes` each that the remaining bytes can hold.
  std::size_t count(std::size_t elementBytes) {
    const std::uint64_t n = integer<std::uint64_t>();
    if (n > (in_.size() - offset_) / elementBytes) fail("a count of " + std::to_string(n) + " exceeds the data");
    return static_cast<std::size_t>(n);
  }
  void finish() const {
    if (offset_ != in_.size()) fail(std::to_string(in_.size() - offset_) + " bytes after the end");
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw CorruptStateError("slam state: byte " + std::to_string(offset_) + ": " + what);
  }

 private:
  void need(std::size_t n) const {
    if (in_.size() - offset_ < n) fail("truncated");
  }
  std::string_view in_;
  std::size_t offset_ = 0;
};

constexpr std::size_t kPoseBytes = 24;

void requireThat(bool condition, const std::string& what) {
  if (!condition) throw InvalidArgumentError("slam state: " + what);
}

}  // namespace

std::string serializeState(const SlamState& state) {
  Writer w;
  w.bytes(kMagic);
  w.integer(kVersion);
  w.integer<std::uint64_t>(state.scans.size());
  for (const ScanRecord& s : state.scans) {
    w.integer<std::uint64_t>(s.id);
    w.real(s.stamp);
    w.pose(s.odometry);
    w.integer(s.keyframe);
    w.integer(s.previousKeyframe);
    w.pose(s.mapped);
  }
  w.integer<std::uint64_t>(state.keyframes.size());
  for (const Keyframe& k : state.keyframes) {
    w.integer<std::uint64_t>(k.scanId);
    w.pose(k.odometry);
    w.pose(k.pose);
    w.integer<std::uint64_t>(k.points.size());
    for (const Eigen::Vector2f& p : k.points) {
      w.real(p.x());
      w.real(p.y());
    }
  }
  w.integer<std::uint64_t>(state.constraints.size());
  for (const Constraint& c : state.constraints) {
    w.integer(static_cast<std::uint8_t>(c.kind));
    w.integer(c.from);
    w.integer(c.to);
    w.pose(c.measurement);
    for (int i = 0; i < 9; ++i) w.real(c.information(i / 3, i % 3));
  }
  w.integer<std::uint64_t>(state.submaps.size());
  for (const SubmapRecord& s : state.submaps) {
    w.integer(s.first);
    w.integer(s.anchor);
    w.integer<std::uint64_t>(s.memberPoses.size());
    for (const Pose2D& p : s.memberPoses) w.pose(p);
  }
  w.real(state.distanceSinceLoop);
  w.integer(state.pendingLoops);
  w.integer(state.keyframesAtLastOptimization);
  w.integer(state.counters.failedRegistrations);
  w.integer(state.counters.loopClosures);
  w.integer(state.counters.optimizations);
  w.integer<std::uint64_t>(state.revisions.size());
  for (const PoseRevision& r : state.revisions) {
    w.integer(r.number);
    w.integer<std::uint64_t>(r.atScan);
    w.integer<std::uint64_t>(r.keyframePoses.size());
    for (const Pose2D& p : r.keyframePoses) w.pose(p);
  }
  return w.take();
}

SlamState deserializeState(std::string_view bytes) {
  Reader r(bytes);
  if (r.bytes(kMagic.size()) != kMagic) r.fail("not a slam state (magic)");
  const auto version = r.integer<std::uint32_t>();
  if (version != kVersion) r.fail("version " + std::to_string(version) + ", expected " + std::to_string(kVersion));
  SlamState state;
  state.scans.resize(r.count(16 + 2 * kPoseBytes + 8));
  for (ScanRecord& s : state.scans) {
    s.id = r.integer<std::uint64_t>();
    s.stamp = r.real64();
    s.odometry = r.pose();
    s.keyframe = r.integer<KeyframeIndex>();
    s.previousKeyframe = r.integer<KeyframeIndex>();
    s.mapped = r.pose();
  }
  state.keyframes.resize(r.count(16 + 2 * kPoseBytes));
  for (Keyframe& k : state.keyframes) {
    k.scanId = r.integer<std::uint64_t>();
    k.odometry = r.pose();
    k.pose = r.pose();
    k.points.resize(r.count(8));
    for (Eigen::Vector2f& p : k.points) {
      p.x() = r.real32();
      p.y() = r.real32();
    }
  }
  state.constraints.resize(r.count(9 + kPoseBytes + 72));
  for (Constraint& c : state.constraints) {
    const auto kind = r.integer<std::uint8_t>();
    if (kind > static_cast<std::uint8_t>(Constraint::Kind::Loop)) r.fail("unknown constraint kind " + std::to_string(kind));
    c.kind = static_cast<Constraint::Kind>(kind);
    c.from = r.integer<KeyframeIndex>();
    c.to = r.integer<KeyframeIndex>();
    c.measurement = r.pose();
    for (int i = 0; i < 9; ++i) c.information(i / 3, i % 3) = r.real64();
  }
  state.submaps.resize(r.count(16));
  for (SubmapRecord& s : state.submaps) {
    s.first = r.integer<KeyframeIndex>();
    s.anchor = r.integer<KeyframeIndex>();
    s.memberPoses.resize(r.count(kPoseBytes));
    for (Pose2D& p : s.memberPoses) p = r.pose();
  }
  state.distanceSinceLoop = r.real64();
  state.pendingLoops = r.integer<std::uint64_t>();
  state.keyframesAtLastOptimization = r.integer<std::uint64_t>();
  state.counters.failedRegistrations = r.integer<std::uint64_t>();
  state.counters.loopClosures = r.integer<std::uint64_t>();
  state.counters.optimizations = r.integer<std::uint64_t>();
  state.revisions.resize(r.count(24));
  for (PoseRevision& revision : state.revisions) {
    revision.number = r.integer<std::uint64_t>();
    revision.atScan = r.integer<std::uint64_t>();
    revision.keyframePoses.resize(r.count(kPoseBytes));
    for (Pose2D& p : revision.keyframePoses) p = r.pose();
  }
  r.finish();
  try {
    validate(state);
  } catch (const InvalidArgumentError& e) {
    throw CorruptStateError(e.what());
  }
  return state;
}

void validate(const SlamState& state) {
  const std::size_t keyframes = state.keyframes.size();
  requireThat(state.scans.empty() == (keyframes == 0), "scans and keyframes must be both empty or both present");
  for (std::size_t i = 0; i < state.scans.size(); ++i) {
    const ScanRecord& s = state.scans[i];
    const std::string name = "scan " + std::to_string(s.id);
    requireThat(s.id > 0 && (i == 0 || s.id > state.scans[i - 1].id), name + ": IDs must increase");
    requireThat(s.previousKeyframe < keyframes, name + ": previous keyframe out of range");
    requireThat(state.keyframes[s.previousKeyframe].scanId <= s.id, name + ": previous keyframe is later");
    if (s.keyframe != kNoKeyframe)
      requireThat(s.keyframe == s.previousKeyframe && state.keyframes[s.keyframe].scanId == s.id,
                  name + ": keyframe does not point back to it");
  }
  for (std::size_t k = 1; k < keyframes; ++k)
    requireThat(state.keyframes[k].scanId > state.keyframes[k - 1].scanId, "keyframe scan IDs must increase");
  for (const Constraint& c : state.constraints)
    requireThat(c.from < keyframes && c.to < keyframes && c.from != c.to,
                "constraint " + std::to_string(c.from) + " -> " + std::to_string(c.to) + " out of range");
  for (const SubmapRecord& s : state.submaps)
    requireThat(!s.memberPoses.empty() && s.first + s.memberPoses.size() <= keyframes && s.anchor >= s.first &&
                    s.anchor < s.first + s.memberPoses.size(),
                "submap at keyframe " + std::to_string(s.first) + " out of range");
  requireThat(state.keyframesAtLastOptimization <= keyframes, "optimisation mark beyond the keyframes");
  requireThat(state.distanceSinceLoop >= 0.0, "negative distance since the last loop");
  for (std::size_t i = 0; i < state.revisions.size(); ++i) {
    const PoseRevision& r = state.revisions[i];
    const std::string name = "revision " + std::to_string(r.number);
    requireThat(r.number > 0 && r.number <= state.counters.optimizations &&
                    (i == 0 || r.number > state.revisions[i - 1].number),
                name + ": numbers must increase up to the optimisations run");
    requireThat(r.atScan > 0 && r.atScan <= state.lastInputId() + 1, name + ": made at an unknown scan");
    requireThat(r.keyframePoses.size() <= keyframes, name + ": more keyframe poses than keyframes");
    const auto before = std::lower_bound(state.scans.begin(), state.scans.end(), r.atScan,
                                         [](const ScanRecord& s, DataId id) { return s.id < id; });
    if (before != state.scans.begin())
      requireThat(std::prev(before)->previousKeyframe < r.keyframePoses.size(),
                  name + ": lacks the keyframes of the scans before it");
  }
}

}  // namespace rgnav
