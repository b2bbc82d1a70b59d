// RevisionFollowers: which pose revisions the ScanMapper module may forget. Each kept revision
// holds every keyframe pose of its time, so keeping the latest 256 of a large map costs tens of
// megabytes in memory and in every checkpoint. A follower (the RG Mapping Kernel module) names
// itself and the last revision it has applied durably (in its own checkpoint) whenever it asks
// for revisions; once every follower that asked within kIdleSeconds is past a revision, no one
// can need it again, not even a follower that restarts from its checkpoint. Only the followers
// the module is configured with count: any other caller (or an anonymous one) only reads, so an
// unknown caller can neither make the module forget revisions nor hold them, nor grow this table.
// A follower idle longer than kIdleSeconds is forgotten. With no active follower nothing is
// forgotten here (the mapper's own bound, SlamConfig graph.keptRevisions, still holds). Times are
// seconds on any monotonic clock the caller chooses.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>

namespace rgnav {

class RevisionFollowers {
 public:
  static constexpr double kIdleSeconds = 60.0;

  explicit RevisionFollowers(std::set<std::string> known);

  // `follower` has durably applied every revision up to `applied`; ignored unless it is known.
  void asked(const std::string& follower, std::uint64_t applied, double now);

  // The highest revision every follower active at `now` has applied; none without one.
  std::optional<std::uint64_t> appliedByAll(double now) const;
  // Followers remembered (active or not forgotten yet).
  std::size_t size() const { return cursors_.size(); }

 private:
  struct Cursor {
    std::uint64_t applied = 0;
    double lastAsked = 0.0;
  };
  std::set<std::string> known_;
  std::map<std::string, Cursor> cursors_;
};

}  // namespace rgnav
