#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "segslam/map/frame.h"
#include "segslam/map/keyframe.h"
#include "segslam/map/map_point.h"

namespace segslam::tracking {

// Descriptor distance thresholds (Hamming distance of 256-bit ORB descriptors).
inline constexpr int kMaxDistanceHigh = 100;
inline constexpr int kMaxDistanceLow = 50;

// Where a map point should appear in a frame, if it can be seen there at all.
struct ProjectedPoint {
  std::shared_ptr<map::MapPoint> point;
  double u = 0.0;
  double v = 0.0;
  double right_u = -1.0;
  int predicted_level = 0;
  double view_cosine = 1.0;
};

// Projects a map point with the frame's pose: it must be in front of the camera, inside the
// undistorted image, not on a dynamic area of the frame, within the distance range at which
// its descriptor is valid, and seen at less than acos(min_view_cosine) from its mean direction.
std::optional<ProjectedPoint> projectIntoFrame(const std::shared_ptr<map::MapPoint>& point,
                                               const map::Frame& frame, double min_view_cosine);

// Matches projected local-map points to the frame's free keypoints within
// radius_factor * scale(predicted level) pixels (ratio test 0.8 between the two best keypoints
// on the same level). Returns the number of new matches written to frame.map_points.
int searchLocalPoints(map::Frame& frame, const std::vector<ProjectedPoint>& projections,
                      double radius_factor);

// Matches the last frame's map points to the current frame, projected with current.T_cw,
// within radius * scale(level) pixels; keeps matches consistent in keypoint rotation.
int searchFromLastFrame(map::Frame& current, const map::Frame& last, double radius);

// Brute-force descriptor matching of the frame's keypoints against a keyframe's map points
// with Lowe's ratio test and rotation consistency; writes matches into frame.map_points.
int searchByDescriptors(map::Frame& frame, const map::KeyFrame& keyframe, double ratio);

// Keeps only the keypoint pairs whose rotation difference falls into the three most populated
// bins of a 30-bin histogram: a cheap rejection of matches that disagree with the rest.
// `angle_differences[i]` belongs to match i; returns the indices of matches to drop.
std::vector<std::size_t> rotationInconsistentMatches(const std::vector<float>& angle_differences);

}  // namespace segslam::tracking
