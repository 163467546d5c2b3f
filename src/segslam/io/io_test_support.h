#pragma once

// Helpers for the io tests only (header-only, never linked into the library).

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "segslam/core/camera.h"
#include "segslam/io/camera_config.h"
#include "segslam/util/error.h"

namespace segslam::io::testing {

// The message of the util::Error that `action` throws; a test failure when it throws nothing.
// Any other exception propagates and fails the test as well.
template <typename Action>
std::string errorMessage(Action&& action) {
  try {
    action();
  } catch (const util::Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a util::Error";
  return "";
}

inline ::testing::AssertionResult contains(const std::string& text, std::string_view part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

// Collects what spdlog's default logger logs while it lives, as "[level] message" lines.
class CapturedLog {
 public:
  CapturedLog() : sink_(std::make_shared<spdlog::sinks::ostream_sink_mt>(stream_)) {
    sink_->set_pattern("[%l] %v");
    spdlog::default_logger()->sinks().push_back(sink_);
  }
  ~CapturedLog() { std::erase(spdlog::default_logger()->sinks(), sink_); }
  CapturedLog(const CapturedLog&) = delete;
  CapturedLog& operator=(const CapturedLog&) = delete;

  [[nodiscard]] std::string text() const { return stream_.str(); }

 private:
  std::ostringstream stream_;
  std::shared_ptr<spdlog::sinks::ostream_sink_mt> sink_;
};

inline void writeText(const std::filesystem::path& file, std::string_view text) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary);
  out << text;
  ASSERT_TRUE(out.good()) << file;
}

inline void writeImage(const std::filesystem::path& file, const cv::Mat& image) {
  std::filesystem::create_directories(file.parent_path());
  ASSERT_TRUE(cv::imwrite(file.string(), image)) << file;
}

// Replaces the colour image `rgb_path` of the dataset in `folder` by a JPEG of it written with
// cv::imwrite and cut short, as an interrupted copy leaves one (libjpeg decodes it half grey,
// saying only "Premature end of JPEG file"); rgb.txt then names the JPEG. Returns its path.
inline std::filesystem::path replaceByTruncatedJpeg(const std::filesystem::path& folder,
                                                    const std::filesystem::path& rgb_path) {
  const std::filesystem::path listed = rgb_path.lexically_relative(folder);
  std::filesystem::path jpeg = rgb_path;
  jpeg.replace_extension(".jpg");
  EXPECT_TRUE(cv::imwrite(jpeg.string(), cv::imread(rgb_path.string())));
  std::filesystem::resize_file(jpeg, std::filesystem::file_size(jpeg) / 2);
  std::ifstream in(folder / "rgb.txt");
  std::string list((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string listed_jpeg = std::filesystem::path(listed).replace_extension(".jpg").string();
  list.replace(list.find(listed.string()), listed.string().size(), listed_jpeg);
  writeText(folder / "rgb.txt", list);
  return jpeg;
}

// A small valid TUM dataset in `folder`: colour frames at 30 Hz, depth stamps jittered by up to
// 15 ms (so that association has work to do), ground truth, masks (raw values 0, 1 and 200) and
// a camera.yaml for the tiny image size. Colour frame i is uniform BGR (10 i, 20, 30) with pixel
// (0, 0) = (1, 2, 3); depth frame i is raw 5000 + 100 i (metres: 1 + 0.02 i) with pixel (0, 0) = 0.
struct TinyDataset {
  static constexpr int kWidth = 16;
  static constexpr int kHeight = 12;
  static constexpr double kFirstStamp = 1305031102.175304;
  static constexpr int kFirstListLine = 3;  // after two comment lines
  std::filesystem::path folder;
  std::vector<double> rgb_stamps;
  std::vector<double> depth_stamps;

  [[nodiscard]] static core::Camera camera() {
    core::Camera camera = *cameraPreset("freiburg1");
    camera.name = "tiny";
    camera.width = kWidth;
    camera.height = kHeight;
    return camera;
  }
};

// The text of an image list: two comment lines, then `<stamp> <folder>/<stamp>.png` per stamp.
inline std::string imageList(const std::vector<double>& stamps, std::string_view folder) {
  std::string text = "# images\n# timestamp filename\n";
  for (double stamp : stamps) {
    text += fmt::format("{:.6f} {}/{:.6f}.png\n", stamp, folder, stamp);
  }
  return text;
}

inline cv::Mat tinyColour(int i) {
  cv::Mat image(TinyDataset::kHeight, TinyDataset::kWidth, CV_8UC3, cv::Scalar(10 * i, 20, 30));
  image.at<cv::Vec3b>(0, 0) = {1, 2, 3};
  return image;
}

inline cv::Mat tinyDepth(int i) {
  cv::Mat image(TinyDataset::kHeight, TinyDataset::kWidth, CV_16UC1, cv::Scalar(5000 + 100 * i));
  image.at<std::uint16_t>(0, 0) = 0;
  return image;
}

inline cv::Mat tinyMask() {
  cv::Mat image = cv::Mat::zeros(TinyDataset::kHeight, TinyDataset::kWidth, CV_8UC1);
  image(cv::Rect(2, 2, 4, 3)).setTo(1);
  image.at<std::uint8_t>(10, 10) = 200;
  return image;
}

inline TinyDataset writeTinyDataset(const std::filesystem::path& folder, int frames = 4) {
  static constexpr double kJitter[] = {-0.012, 0.008, -0.003, 0.015, 0.0, -0.015};
  TinyDataset dataset{folder, {}, {}};
  std::string groundtruth = "# timestamp tx ty tz qx qy qz qw\n";
  for (int i = 0; i < frames; ++i) {
    const double rgb = TinyDataset::kFirstStamp + i / 30.0;
    const double depth = rgb + kJitter[i % 6];
    dataset.rgb_stamps.push_back(rgb);
    dataset.depth_stamps.push_back(depth);
    writeImage(folder / fmt::format("rgb/{:.6f}.png", rgb), tinyColour(i));
    writeImage(folder / fmt::format("depth/{:.6f}.png", depth), tinyDepth(i));
    writeImage(folder / fmt::format("mask/{:.6f}.png", rgb), tinyMask());
    groundtruth += fmt::format("{:.4f} {} 0 0 0 0 0 1\n", rgb, 0.1 * i);
  }
  writeText(folder / "rgb.txt", imageList(dataset.rgb_stamps, "rgb"));
  writeText(folder / "depth.txt", imageList(dataset.depth_stamps, "depth"));
  writeText(folder / "mask.txt", imageList(dataset.rgb_stamps, "mask"));
  writeText(folder / "groundtruth.txt", groundtruth);
  writeCameraYaml(folder / "camera.yaml", TinyDataset::camera());
  return dataset;
}

}  // namespace segslam::io::testing
