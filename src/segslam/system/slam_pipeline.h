#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>

#include "segslam/core/camera.h"
#include "segslam/dense/map_builder.h"
#include "segslam/io/tum_dataset.h"
#include "segslam/system/map_keyframe_feed.h"
#include "segslam/system/map_persistence.h"
#include "segslam/system/mask_source.h"
#include "segslam/system/slam_system.h"

namespace segslam::system {

struct SlamPipelineOptions {
  SlamOptions slam;
  // Dense map of the keyframes; its mask dilation is the SLAM one.
  bool build_map = true;
  dense::MapBuilderOptions map;
  // With a segmentation network, local mapping waits at most this many frames for each
  // keyframe's own network output (SlamOptions::mapper.own_mask_wait_frames).
  int keyframe_mask_wait_frames = 20;
  // Loading and saving the SLAM map (segslam run --load-map, --save-map, --localize-only).
  MapFileOptions map_file;
  // Where the run writes its dense map, recorded in a saved map file (empty: nowhere).
  std::filesystem::path dense_map_folder;
};

// The pipeline behind a frame's masks, shared by `segslam run` (runSequence) and StreamingSlam:
// late network outputs to local mapping and the dense map, the frame to SLAM, a new keyframe to
// keyframe segmentation and the dense map, in that order; with a map file, the saved map
// restored before the first frame (and its dense map carried on) and the final map saved.
class SlamPipeline {
 public:
  // `masks` must outlive the pipeline. Throws util::Error (one line naming the file) for a map
  // file that cannot be loaded into this camera's SLAM.
  SlamPipeline(const core::Camera& camera, FrameMaskSource& masks,
               const SlamPipelineOptions& options);
  SlamPipeline(const SlamPipeline&) = delete;
  SlamPipeline& operator=(const SlamPipeline&) = delete;

  // Tracks `frame` with the masks the mask source made for it as its frame `mask_frame_id`,
  // which took the calling thread `mask_ms` (counted in the stats' tracking time).
  FrameStats track(const io::RgbdFrame& frame, const FrameMasks& masks, std::uint64_t mask_frame_id,
                   double mask_ms);
  // Network outputs still on their way, the dense map's keyframes, then local mapping and loop
  // closing: tracking ends here. Calls after the first do nothing.
  void finish();
  [[nodiscard]] bool finished() const { return finished_; }

  // Writes the SLAM map to `file` (finishes first) and returns its size (see saveMapOf).
  std::uintmax_t saveMap(const std::filesystem::path& file);

  [[nodiscard]] SlamSystem& slam() { return slam_; }
  [[nodiscard]] const SlamSystem& slam() const { return slam_; }
  // None without build_map.
  [[nodiscard]] dense::MapBuilder* mapBuilder() { return map_builder_ ? &*map_builder_ : nullptr; }
  [[nodiscard]] const std::optional<LoadedMap>& loadedMap() const { return loaded_; }
  // Map points on what late network outputs showed moving, culled so far.
  [[nodiscard]] int pointsCulledByLateMasks() const { return points_culled_by_late_masks_; }

 private:
  void handOverLateOutputs(const std::vector<segmentation::LateOutput>& outputs);

  FrameMaskSource& masks_;
  SlamPipelineOptions options_;
  SlamSystem slam_;
  std::optional<LoadedMap> loaded_;
  std::optional<dense::MapBuilder> map_builder_;
  std::optional<MapKeyFrameFeed> map_feed_;
  int points_culled_by_late_masks_ = 0;
  bool finished_ = false;
};

}  // namespace segslam::system
