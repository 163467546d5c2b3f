#include "segslam/system/frame_log.h"

#include <system_error>

#include "segslam/util/error.h"

namespace segslam::system {

namespace {

fmt::ostream openLog(const std::filesystem::path& file) {
  try {
    return fmt::output_file(file.string());
  } catch (const std::system_error& error) {
    throw util::Error(file.string() + ": cannot write: " + error.code().message());
  }
}

const char* stateName(tracking::TrackingState state) {
  switch (state) {
    case tracking::TrackingState::kOk:
      return "ok";
    case tracking::TrackingState::kLost:
      return "lost";
    case tracking::TrackingState::kNotInitialised:
      break;
  }
  return "not_initialised";
}

}  // namespace

FrameLog::FrameLog(const std::filesystem::path& file) : out_(openLog(file)) {
  out_.print(
      "frame,timestamp,mask_ms,extraction_ms,tracking_ms,keypoints,matches,state,keyframe,"
      "live_keyframes,live_map_points\n");
}

void FrameLog::add(const FrameStats& s) {
  out_.print("{},{:.6f},{:.3f},{:.3f},{:.3f},{},{},{},{},{},{}\n", s.frame_id, s.timestamp,
             s.mask_ms, s.extraction_ms, s.tracking_ms, s.keypoints, s.matches, stateName(s.state),
             s.keyframe ? 1 : 0, s.live_keyframes, s.live_map_points);
  tracking_ms_.push_back(s.tracking_ms);
  extraction_ms_.push_back(s.extraction_ms);
  if (s.state == tracking::TrackingState::kLost) ++lost_frames_;
}

void FrameLog::close() { out_.close(); }

}  // namespace segslam::system
