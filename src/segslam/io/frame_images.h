#pragma once

#include <filesystem>
#include <opencv2/core.hpp>

#include "segslam/core/camera.h"

namespace segslam::io {

// Loading and validation of the images of one RGB-D frame. Every function throws util::Error
// naming the image file when it cannot be decoded or has the wrong type or size.

// Colour image as CV_8UC3 BGR of the camera's size. 8-bit grey images are accepted and
// converted (a grey camera still gives usable frames); 8-bit BGRA loses its alpha channel.
// Anything else (16-bit colour, float) is an error.
cv::Mat readColourImage(const std::filesystem::path& file, const core::Camera& camera);

// Depth image: 16-bit single-channel raw units, converted to CV_32FC1 metres
// (raw / camera.depth_factor; 0 = no measurement stays 0). Must have the colour image's size.
cv::Mat readDepthImage(const std::filesystem::path& file, const core::Camera& camera,
                       cv::Size colour_size);

// Ground-truth dynamic mask: 8-bit single-channel, any non-zero value means dynamic; returned
// normalised to 0 / 255.
cv::Mat readMaskImage(const std::filesystem::path& file, cv::Size colour_size);

// Semantic class ids (core::SemanticClass): 8-bit single-channel.
cv::Mat readLabelImage(const std::filesystem::path& file, cv::Size colour_size);

// Instance ids (0 = none): 16-bit single-channel.
cv::Mat readInstanceImage(const std::filesystem::path& file, cv::Size colour_size);

}  // namespace segslam::io
