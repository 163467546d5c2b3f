#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <vector>

#include "segslam/map/frame.h"
#include "segslam/map/keyframe.h"
#include "segslam/place/bow_database.h"
#include "segslam/place/vocabulary.h"

namespace segslam::tracking {

// The keyframes' bags of words, to find the keyframes that may show what a lost frame shows
// wherever in the map they are (relocalisation after the camera was carried elsewhere). Filled
// and queried by the tracker only, on its thread. The bag of words holds a keyframe's ORB
// descriptors, which were extracted on its static area only.
class KeyFrameDatabase {
 public:
  explicit KeyFrameDatabase(std::shared_ptr<const place::Vocabulary> vocabulary);

  // Also forgets the keyframes culled since the last add(), so that the database holds only live
  // keyframes however long the run.
  void add(const std::shared_ptr<map::KeyFrame>& keyframe);
  // Up to max_candidates live (not culled) keyframes that share words with the frame, most
  // similar first.
  [[nodiscard]] std::vector<std::shared_ptr<map::KeyFrame>> candidates(
      const map::Frame& frame, std::size_t max_candidates) const;

  // Keyframes held (live when the last one was added).
  [[nodiscard]] std::size_t size() const { return keyframes_.size(); }

 private:
  void forgetCulled();

  std::shared_ptr<const place::Vocabulary> vocabulary_;
  place::BowDatabase database_;
  std::map<place::BowDatabase::EntryId, std::shared_ptr<map::KeyFrame>> keyframes_;
};

}  // namespace segslam::tracking
