#pragma once

#include <filesystem>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "segslam/core/camera.h"
#include "segslam/util/error.h"

namespace segslam::io {

// An image file that is damaged: its data stops early (a JPEG without its end marker FF D9, a PNG
// without its IEND chunk; libjpeg decodes a truncated JPEG half grey and says no more than
// "Premature end of JPEG file") or it cannot be decoded at all. Real recordings have such frames;
// a player skips them (io::DamagedFrames) where a wrong type or size stops the sequence.
class DamagedImageError : public util::Error {
 public:
  using util::Error::Error;
};

// Why the file's JPEG or PNG data is cut short, or nothing when it is whole (or of another
// format): the end marker must end the file, allowing trailing zero and whitespace padding.
std::optional<std::string> imageTruncation(const std::filesystem::path& file);

// Loading and validation of the images of one RGB-D frame. Every function throws util::Error
// naming the image file when it has the wrong type or size, and DamagedImageError naming it when
// it is damaged.

// Colour image as CV_8UC3 BGR of the camera's size. 8-bit grey images are accepted and
// converted (a grey camera still gives usable frames); 8-bit BGRA loses its alpha channel.
// Anything else (16-bit colour, float) is an error.
cv::Mat readColourImage(const std::filesystem::path& file, const core::Camera& camera);

// Depth image: 16-bit single-channel raw units, converted to CV_32FC1 metres
// (raw / camera.depth_factor; 0 = no measurement stays 0). Must have the colour image's size.
cv::Mat readDepthImage(const std::filesystem::path& file, const core::Camera& camera,
                       cv::Size colour_size);

// The size of an image (decoded whole: OpenCV 4.6 has no header-only reader).
cv::Size readImageSize(const std::filesystem::path& file);

// Ground-truth dynamic mask: 8-bit single-channel, any non-zero value means dynamic; returned
// normalised to 0 / 255.
cv::Mat readMaskImage(const std::filesystem::path& file, cv::Size colour_size);

// Semantic class ids (core::SemanticClass): 8-bit single-channel.
cv::Mat readLabelImage(const std::filesystem::path& file, cv::Size colour_size);

// Instance ids (0 = none): 16-bit single-channel.
cv::Mat readInstanceImage(const std::filesystem::path& file, cv::Size colour_size);

}  // namespace segslam::io
