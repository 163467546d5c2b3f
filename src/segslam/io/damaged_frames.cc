#include "segslam/io/damaged_frames.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <utility>

#include "segslam/util/error.h"

namespace segslam::io {

DamagedFrames::DamagedFrames(std::filesystem::path dataset, std::size_t frames)
    : dataset_(std::move(dataset)), frames_(frames) {}

void DamagedFrames::skip(std::size_t index, double timestamp, const std::string& damage) {
  if (count_++ == 0) first_damage_ = damage;
  spdlog::warn("frame {} ({:.6f}) skipped: {}", index, timestamp, damage);
  if (2 * count_ > frames_) {
    throw util::Error(fmt::format(
        "{}: more than half of the {} frames have damaged images ({} so far; the first: {})",
        dataset_.string(), frames_, count_, first_damage_));
  }
}

}  // namespace segslam::io
