#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "segslam/core/camera.h"

namespace segslam::segmentation {

// How the camera-induced image motion is modelled.
enum class CameraMotionModel {
  kRigid,       // PnP RANSAC on the previous frame's 3D points: exact for any scene with depth
  kHomography,  // one homography by RANSAC (the published method): exact for planes or rotation
};

CameraMotionModel cameraMotionModelFromName(const std::string& name);  // "rigid", "homography"

struct GeometricOptions {
  CameraMotionModel motion_model = CameraMotionModel::kRigid;
  int max_corners = 400;               // Shi-Tomasi corners tracked to the previous frame
  double reprojection_px = 3.0;        // a corner whose motion the camera does not explain moves
  double depth_tolerance = 0.1;        // relative depth disagreement that also counts as motion
  double region_depth_range_m = 0.25;  // objects grown from seeds: depth within this of the seed
  int min_seeds_per_object = 5;        // fewer moving corners in a region: noise, not an object
  double max_object_share = 0.4;       // a region larger than this share of the image is background
  // A region whose tracked corners the camera motion mostly explains is background, whatever a
  // few corners on it say (occlusion edges, aliasing): moving corners must be at least this share.
  double min_seed_share = 0.5;
  // When more than this share of the image seems to move, the camera motion was misestimated:
  // nothing can be told about the frame.
  double max_moving_share = 0.3;
};

// RGB-D frame as the geometric segmenter sees it.
struct DepthFrame {
  cv::Mat gray;   // CV_8UC1
  cv::Mat depth;  // CV_32FC1 metres, 0 = none
  // Of a previous frame: what was found moving in it (CV_8UC1, non-zero = moving; may be empty).
  cv::Mat moving{};
};

// Finds whatever moves between two RGB-D frames, of any class: corners of the current frame are
// tracked back to the previous one (pyramidal Lucas-Kanade), the camera motion is estimated from
// those on static pixels (by default PnP RANSAC on the previous frame's 3D points: the exact
// rigid check RGB-D allows; or a homography, which only holds for planes or pure rotation), and
// corners that the camera motion does not explain become seeds. Each seed grows into a connected
// region of similar depth, so whole objects are masked, not scattered pixels.
class GeometricSegmenter {
 public:
  explicit GeometricSegmenter(const core::Camera& camera, GeometricOptions options = {});

  // Dynamic mask (CV_8UC1, 255 = moving) of `current`. `known_dynamic` (may be empty) marks
  // pixels of `current` already known to move (e.g. people from the semantic network), and
  // `previous.moving` what moved in the previous frame: corners on either are left out of the
  // camera-motion estimate. A person who covers much of the view and has many corners can
  // otherwise outvote the background in RANSAC, so that the camera seems to move with him and the
  // background to move instead. Empty result when too little is tracked to tell.
  cv::Mat segment(const DepthFrame& previous, const DepthFrame& current,
                  const cv::Mat& known_dynamic = cv::Mat()) const;

 private:
  struct Correspondences;
  // Tracked corners of the current frame: those the camera motion does not explain (seeds of
  // moving objects) and those it does.
  struct MotionEvidence {
    std::vector<cv::Point> moving;
    std::vector<cv::Point> explained;
  };
  [[nodiscard]] std::optional<MotionEvidence> rigidMotionEvidence(
      const Correspondences& tracks) const;
  [[nodiscard]] std::optional<MotionEvidence> homographyEvidence(
      const Correspondences& tracks) const;
  // The union of the connected regions of similar depth around the moving corners that hold
  // enough of them, and more of them than of explained corners.
  [[nodiscard]] cv::Mat growObjects(const cv::Mat& depth, const MotionEvidence& evidence) const;

  core::Camera camera_;
  GeometricOptions options_;
};

}  // namespace segslam::segmentation
