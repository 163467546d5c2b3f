#include "segslam/tracking/keyframe_database.h"

#include <stdexcept>
#include <utility>

namespace segslam::tracking {

KeyFrameDatabase::KeyFrameDatabase(std::shared_ptr<const place::Vocabulary> vocabulary)
    : vocabulary_(std::move(vocabulary)) {
  if (!vocabulary_) throw std::invalid_argument("KeyFrameDatabase: no vocabulary");
}

void KeyFrameDatabase::add(const std::shared_ptr<map::KeyFrame>& keyframe) {
  forgetCulled();
  keyframes_[database_.add(vocabulary_->transform(keyframe->descriptors))] = keyframe;
}

void KeyFrameDatabase::forgetCulled() {
  for (auto it = keyframes_.begin(); it != keyframes_.end();) {
    if (it->second->bad) {
      database_.remove(it->first);
      it = keyframes_.erase(it);
    } else {
      ++it;
    }
  }
}

std::vector<std::shared_ptr<map::KeyFrame>> KeyFrameDatabase::candidates(
    const map::Frame& frame, std::size_t max_candidates) const {
  const auto hits = database_.query(
      vocabulary_->transform(frame.descriptors), max_candidates,
      [this](place::BowDatabase::EntryId entry) { return keyframes_.at(entry)->bad; });
  std::vector<std::shared_ptr<map::KeyFrame>> keyframes;
  keyframes.reserve(hits.size());
  for (const auto& hit : hits) keyframes.push_back(keyframes_.at(hit.entry));
  return keyframes;
}

}  // namespace segslam::tracking
