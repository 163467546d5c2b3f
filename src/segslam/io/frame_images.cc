#include "segslam/io/frame_images.h"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string_view>
#include <system_error>

#include "segslam/util/error.h"

namespace segslam::io {

namespace {

constexpr std::string_view kJpegStart = "\xFF\xD8\xFF";
constexpr std::string_view kJpegEnd = "\xFF\xD9";
constexpr std::string_view kPngSignature = "\x89PNG\r\n\x1A\n";
// The IEND chunk in full: zero length, type, CRC.
constexpr std::string_view kPngEnd{"\0\0\0\0IEND\xAE\x42\x60\x82", 12};
// Enough of the file's end to see past any padding written after the end marker.
constexpr std::streamoff kTailBytes = 4096;

struct HeadAndTail {
  std::string head;
  std::string tail;  // trailing zero and whitespace padding removed
};

HeadAndTail headAndTail(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  const std::streamoff size = in ? static_cast<std::streamoff>(in.tellg()) : 0;
  HeadAndTail bytes{std::string(static_cast<std::size_t>(std::min<std::streamoff>(size, 8)), '\0'),
                    std::string(static_cast<std::size_t>(std::min(size, kTailBytes)), '\0')};
  in.seekg(0);
  in.read(bytes.head.data(), static_cast<std::streamsize>(bytes.head.size()));
  in.seekg(size - static_cast<std::streamoff>(bytes.tail.size()));
  in.read(bytes.tail.data(), static_cast<std::streamsize>(bytes.tail.size()));
  const std::size_t end = bytes.tail.find_last_not_of(std::string_view("\0 \t\r\n", 5));
  bytes.tail.resize(end == std::string::npos ? 0 : end + 1);
  return bytes;
}

// Decodes the file as stored (no conversion), so that its bit depth and channels can be checked.
cv::Mat decodeImage(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) util::failAt(file, "image file not found");
  if (const auto truncation = imageTruncation(file)) {
    throw DamagedImageError(fmt::format("{}: damaged image: {}", file.string(), *truncation));
  }
  cv::Mat image;
  try {
    image = cv::imread(file.string(), cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& e) {
    throw DamagedImageError(
        fmt::format("{}: cannot decode the image: {}", file.string(), e.what()));
  }
  if (image.empty()) {
    throw DamagedImageError(
        fmt::format("{}: cannot decode the image (unreadable or corrupt file)", file.string()));
  }
  return image;
}

// "8-bit 3-channel", "16-bit 1-channel", ... for messages.
std::string describeType(int type) {
  static constexpr std::string_view kDepthNames[] = {
      "8-bit",         "8-bit signed", "16-bit",       "16-bit signed",
      "32-bit signed", "32-bit float", "64-bit float", "16-bit float"};
  return fmt::format("{} {}-channel", kDepthNames[CV_MAT_DEPTH(type)], CV_MAT_CN(type));
}

void requireType(const cv::Mat& image, int type, const std::filesystem::path& file,
                 std::string_view what) {
  if (image.type() != type) {
    util::failAt(file, fmt::format("{} must be {} but is {}", what, describeType(type),
                                   describeType(image.type())));
  }
}

void requireSize(const cv::Mat& image, cv::Size size, const std::filesystem::path& file,
                 std::string_view what, std::string_view size_source) {
  if (image.size() != size) {
    util::failAt(file, fmt::format("{} is {}x{} but {} is {}x{}", what, image.cols, image.rows,
                                   size_source, size.width, size.height));
  }
}

cv::Mat toBgr(const cv::Mat& image, const std::filesystem::path& file) {
  if (image.depth() != CV_8U ||
      (image.channels() != 1 && image.channels() != 3 && image.channels() != 4)) {
    util::failAt(file, fmt::format("colour image must be 8-bit with 1, 3 or 4 channels but is {}",
                                   describeType(image.type())));
  }
  if (image.channels() == 3) return image;
  cv::Mat bgr;
  cv::cvtColor(image, bgr, image.channels() == 1 ? cv::COLOR_GRAY2BGR : cv::COLOR_BGRA2BGR);
  return bgr;
}

cv::Mat readSingleChannel(const std::filesystem::path& file, int type, cv::Size colour_size,
                          std::string_view what) {
  cv::Mat image = decodeImage(file);
  requireType(image, type, file, what);
  requireSize(image, colour_size, file, what, "the colour image");
  return image;
}

}  // namespace

std::optional<std::string> imageTruncation(const std::filesystem::path& file) {
  const HeadAndTail bytes = headAndTail(file);
  if (bytes.head.starts_with(kJpegStart) && !bytes.tail.ends_with(kJpegEnd)) {
    return "the JPEG data stops before its end marker (FF D9): the file is truncated";
  }
  if (bytes.head.starts_with(kPngSignature) && !bytes.tail.ends_with(kPngEnd)) {
    return "the PNG data stops before its IEND chunk: the file is truncated";
  }
  return std::nullopt;
}

cv::Mat readColourImage(const std::filesystem::path& file, const core::Camera& camera) {
  cv::Mat bgr = toBgr(decodeImage(file), file);
  requireSize(bgr, {camera.width, camera.height}, file, "colour image",
              fmt::format("camera '{}'", camera.name));
  return bgr;
}

cv::Mat readDepthImage(const std::filesystem::path& file, const core::Camera& camera,
                       cv::Size colour_size) {
  const cv::Mat raw = readSingleChannel(file, CV_16UC1, colour_size, "depth image");
  cv::Mat metres;
  raw.convertTo(metres, CV_32F, 1.0 / camera.depth_factor);
  return metres;
}

cv::Size readImageSize(const std::filesystem::path& file) { return decodeImage(file).size(); }

cv::Mat readMaskImage(const std::filesystem::path& file, cv::Size colour_size) {
  const cv::Mat raw = readSingleChannel(file, CV_8UC1, colour_size, "mask");
  cv::Mat mask;
  cv::compare(raw, 0, mask, cv::CMP_NE);
  return mask;
}

cv::Mat readLabelImage(const std::filesystem::path& file, cv::Size colour_size) {
  return readSingleChannel(file, CV_8UC1, colour_size, "label image");
}

cv::Mat readInstanceImage(const std::filesystem::path& file, cv::Size colour_size) {
  return readSingleChannel(file, CV_16UC1, colour_size, "instance image");
}

}  // namespace segslam::io
