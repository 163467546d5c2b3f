#pragma once

#include <cstdint>
#include <opencv2/core.hpp>

#include "segslam/core/camera.h"
#include "segslam/geometry/pose.h"
#include "segslam/synth/depth_noise.h"
#include "segslam/synth/primitives.h"

namespace segslam::synth {

// The images of one rendered frame, as they are written to disk.
struct FrameImages {
  cv::Mat rgb;        // CV_8UC3, BGR
  cv::Mat depth;      // CV_16UC1, round(z * depth_factor), 0 = no depth
  cv::Mat labels;     // CV_8UC1, core::SemanticClass ids
  cv::Mat instances;  // CV_16UC1, instance ids, 0 = nothing seen
  cv::Mat mask;       // CV_8UC1, 255 where the pixel shows a dynamic surface, else 0
};

// Renders `scene` seen from a pinhole camera at T_wc (camera x right, y down, z forward;
// distortion is ignored). Exact: the pixel (u, v) shows the first surface hit by the ray through
// (u, v) with direction ((u - cx) / fx, (v - cy) / fy, 1), and its depth is that point's z in the
// camera frame; surfaces nearer than 1 cm are clipped. Colours are the surfaces' mip-mapped
// textures under a fixed light from above (the same from every viewpoint). Rows are rendered in
// parallel; the result does not depend on the number of threads.
FrameImages renderFrame(const RenderScene& scene, const core::Camera& camera,
                        const geometry::Pose& T_wc, DepthNoise depth_noise,
                        std::uint64_t noise_seed);

}  // namespace segslam::synth
