#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

namespace segslam::io {

// The frames of a sequence skipped because an image of theirs is damaged (DamagedImageError),
// counted while the sequence is played or checked. Real recordings have the odd truncated image:
// such a frame is skipped with a warning. A sequence whose frames are mostly damaged gives no
// result worth having, and stops.
class DamagedFrames {
 public:
  // `frames`: how many frames of `dataset` will be played.
  DamagedFrames(std::filesystem::path dataset, std::size_t frames);

  // Logs a warning naming the frame and what is damaged; throws util::Error naming the dataset
  // as soon as more than half of the frames are damaged.
  void skip(std::size_t index, double timestamp, const std::string& damage);

  [[nodiscard]] std::size_t count() const { return count_; }

 private:
  std::filesystem::path dataset_;
  std::size_t frames_;
  std::size_t count_ = 0;
  std::string first_damage_;
};

}  // namespace segslam::io
