#pragma once

#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "segslam/map/keyframe.h"

namespace segslam::loop {

// Place recognition for loop closing: proposes old keyframes that may show the same place as a
// query keyframe. It only proposes; LoopVerifier decides. add() and candidates() are called by the
// loop closer with the map mutex held, so implementations may read the keyframes.
class LoopCandidateDetector {
 public:
  virtual ~LoopCandidateDetector() = default;
  // Short name for logs and summary.json.
  [[nodiscard]] virtual std::string name() const = 0;
  // Heavy per-keyframe work (a CNN descriptor), called on the loop-closing thread WITHOUT the map
  // mutex, before candidates() and add() for that keyframe, so that tracking is never held up by
  // it. May read only what never changes after the keyframe is made (image, dynamic mask).
  virtual void describe(const map::KeyFrame& /*keyframe*/) {}
  // Remembers a keyframe as a future candidate.
  virtual void add(const map::KeyFrame& keyframe) = 0;
  // Forgets a keyframe (culled from the map): it is no candidate again and what was kept of it is
  // freed, so that the detector's memory follows the live map. Called with the map mutex held.
  virtual void forget(std::uint64_t keyframe_id) = 0;
  // What a map file keeps of a remembered keyframe for this detector (empty: nothing; bags of
  // words are recomputed from the keyframe's descriptors), and a keyframe restored from a map file
  // with it. Called with the map mutex held, the loop-closing thread stopped.
  [[nodiscard]] virtual std::string savedDescription(std::uint64_t /*keyframe_id*/) const {
    return {};
  }
  virtual void addRestored(const map::KeyFrame& keyframe, const std::string& /*description*/) {
    add(keyframe);
  }
  // Up to `max_candidates` keyframe ids, best first. `covisible` are the query's covisible
  // keyframes: never candidates (they are no loop), but they tell how similar a keyframe that
  // truly sees the same place scores.
  [[nodiscard]] virtual std::vector<std::uint64_t> candidates(
      const map::KeyFrame& query, const std::set<std::uint64_t>& covisible,
      std::size_t max_candidates) const = 0;
};

}  // namespace segslam::loop
