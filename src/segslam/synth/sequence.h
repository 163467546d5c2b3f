#pragma once

#include <cstdint>
#include <vector>

#include "segslam/core/camera.h"
#include "segslam/geometry/pose.h"
#include "segslam/synth/renderer.h"
#include "segslam/synth/scene.h"
#include "segslam/synth/synth_options.h"

namespace segslam::synth {

// A synthetic sequence in memory: the scene, the camera and its path, and a renderer for any
// frame. Frames can be rendered in any order and from several threads; equal options give
// identical frames.
class SyntheticSequence {
 public:
  // Validates the options (util::Error on bad ones) and builds the scene and its textures.
  explicit SyntheticSequence(const SynthOptions& options);

  [[nodiscard]] const SynthOptions& options() const { return options_; }
  [[nodiscard]] const core::Camera& camera() const { return camera_; }
  [[nodiscard]] const Scene& scene() const { return scene_; }
  [[nodiscard]] int frameCount() const { return options_.frames; }
  [[nodiscard]] double timestamp(int frame) const { return frameTimestamp(frame); }
  [[nodiscard]] const geometry::Pose& cameraPose(int frame) const { return poses_.at(frame); }
  [[nodiscard]] const std::vector<geometry::Pose>& cameraPoses() const { return poses_; }

  [[nodiscard]] FrameImages renderFrame(int frame) const;

 private:
  SynthOptions options_;
  core::Camera camera_;
  std::vector<geometry::Pose> poses_;
  Scene scene_;
  DepthNoise depth_noise_;
};

}  // namespace segslam::synth
