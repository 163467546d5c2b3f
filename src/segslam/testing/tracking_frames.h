#pragma once

// Tracking frames made from a synthetic sequence as SlamSystem makes them (tests only,
// header-only).

#include <memory>
#include <opencv2/imgproc.hpp>
#include <utility>
#include <vector>

#include "segslam/feature/orb_extractor.h"
#include "segslam/map/frame.h"
#include "segslam/synth/sequence.h"

namespace segslam::testing {

// Frame `index` of `sequence`: its ORB features (no dynamic mask) and depth in metres.
inline map::Frame trackingFrame(const synth::SyntheticSequence& sequence, int index,
                                feature::OrbExtractor& extractor,
                                std::shared_ptr<const map::FrameCamera> camera) {
  const synth::FrameImages images = sequence.renderFrame(index);
  cv::Mat gray;
  cv::cvtColor(images.rgb, gray, cv::COLOR_BGR2GRAY);
  cv::Mat depth_m;
  images.depth.convertTo(depth_m, CV_32F, 1.0 / sequence.camera().depth_factor);
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  extractor.extract(gray, cv::Mat(), keypoints, descriptors);
  return {static_cast<std::uint64_t>(index),
          sequence.timestamp(index),
          std::move(keypoints),
          descriptors,
          depth_m,
          cv::Mat(),
          std::move(camera)};
}

}  // namespace segslam::testing
