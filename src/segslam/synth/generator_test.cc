#include "segslam/synth/generator.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <optional>
#include <set>
#include <sstream>

#include "segslam/io/camera_config.h"
#include "segslam/io/trajectory_io.h"
#include "segslam/synth/sequence_writer.h"
#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"
#include "segslam/util/text_file.h"

namespace segslam::synth {
namespace {

using segslam::testing::ScopedTempDir;

SynthOptions smallOptions(int frames, int width, int height) {
  SynthOptions options;
  options.frames = frames;
  options.width = width;
  options.height = height;
  return options;
}

cv::Mat readImage(const std::filesystem::path& file) {
  cv::Mat image = cv::imread(file.string(), cv::IMREAD_UNCHANGED);
  if (image.empty()) ADD_FAILURE() << "cannot read " << file;
  return image;
}

std::string fileBytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

// `timestamp path` rows of a TUM list.
std::vector<std::pair<double, std::string>> readList(const std::filesystem::path& file) {
  std::vector<std::pair<double, std::string>> entries;
  for (const auto& row : util::readTextRows(file)) {
    entries.emplace_back(util::parseDouble(row.fields.at(0), file, row.line, "timestamp"),
                         row.fields.at(1));
  }
  return entries;
}

// Instance ids dynamic at each timestamp, from dynamic_objects_gt.txt.
std::map<double, std::set<int>> readDynamicObjects(const std::filesystem::path& file) {
  std::map<double, std::set<int>> dynamic;
  for (const auto& row : util::readTextRows(file)) {
    EXPECT_EQ(row.fields.size(), 6u);
    const double timestamp = util::parseDouble(row.fields[0], file, row.line, "timestamp");
    dynamic[timestamp].insert(std::stoi(row.fields[1]));
  }
  return dynamic;
}

TEST(SynthGenerator, WritesTheTumLayoutWithMatchingListsAndGroundTruth) {
  const ScopedTempDir dir;
  const SynthOptions options = smallOptions(5, 64, 48);
  const SynthSummary summary = generateSequence(options, dir.path());
  EXPECT_EQ(summary.frames, 5);
  const core::Trajectory truth = io::readTumTrajectory(dir.path() / "groundtruth.txt");
  ASSERT_EQ(truth.size(), 5u);
  for (const std::string kind : {"rgb", "depth", "mask", "labels", "instances"}) {
    const auto list = readList(dir.path() / (kind + ".txt"));
    ASSERT_EQ(list.size(), 5u) << kind;
    for (std::size_t k = 0; k < list.size(); ++k) {
      EXPECT_EQ(list[k].first, truth[k].timestamp) << kind;
      EXPECT_EQ(list[k].second, frameImagePath(kind, frameTimestamp(static_cast<int>(k))));
      const cv::Mat image = readImage(dir.path() / list[k].second);
      EXPECT_EQ(image.size(), cv::Size(64, 48));
    }
  }
  EXPECT_EQ(readImage(dir.path() / frameImagePath("rgb", truth[0].timestamp)).type(), CV_8UC3);
  EXPECT_EQ(readImage(dir.path() / frameImagePath("depth", truth[0].timestamp)).type(), CV_16UC1);
  EXPECT_EQ(readImage(dir.path() / frameImagePath("mask", truth[0].timestamp)).type(), CV_8UC1);
  EXPECT_EQ(readImage(dir.path() / frameImagePath("labels", truth[0].timestamp)).type(), CV_8UC1);
  EXPECT_EQ(readImage(dir.path() / frameImagePath("instances", truth[0].timestamp)).type(),
            CV_16UC1);
  const core::Camera camera = io::readCameraYaml(dir.path() / "camera.yaml");
  EXPECT_DOUBLE_EQ(camera.fx, synthCamera(options).fx);
  EXPECT_DOUBLE_EQ(camera.cy, synthCamera(options).cy);
  EXPECT_DOUBLE_EQ(camera.depth_factor, 5000.0);

  const auto meta = nlohmann::json::parse(fileBytes(dir.path() / "meta.json"));
  EXPECT_EQ(meta["options"]["seed"], options.seed);
  EXPECT_EQ(meta["options"]["path"], "xyz");
  EXPECT_EQ(meta["objects"].size(), summary.objects);
  EXPECT_EQ(meta["classes"][8]["name"], "person");
  int dynamic_objects = 0;
  for (const auto& object : meta["objects"]) dynamic_objects += object["dynamic"] ? 1 : 0;
  EXPECT_EQ(dynamic_objects, 2);
  const auto dynamic = readDynamicObjects(dir.path() / "dynamic_objects_gt.txt");
  ASSERT_EQ(dynamic.size(), 5u);
  EXPECT_EQ(dynamic.begin()->second.size(), 2u);
}

std::map<std::string, std::string> allFiles(const std::filesystem::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
    if (entry.is_regular_file()) {
      files[std::filesystem::relative(entry.path(), folder).string()] = fileBytes(entry.path());
    }
  }
  return files;
}

TEST(SynthGenerator, SameSeedGivesIdenticalFilesWhateverTheThreadCount) {
  SynthOptions options = smallOptions(4, 96, 72);
  options.depth_noise = "kinect";
  options.moved_furniture = true;
  options.people = 3;
  const ScopedTempDir first;
  const ScopedTempDir second;
  const ScopedTempDir other_seed;
  generateSequence(options, first.path());
  {
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    generateSequence(options, second.path());
  }
  const auto files = allFiles(first.path());
  EXPECT_EQ(files.size(), 4u * 5u + 9u);
  EXPECT_TRUE(files == allFiles(second.path()));
  options.seed += 1;
  generateSequence(options, other_seed.path());
  const std::string rgb = frameImagePath("rgb", frameTimestamp(0));
  EXPECT_NE(files.at(rgb), fileBytes(other_seed.path() / rgb));
}

// One frame read back from disk.
struct View {
  cv::Mat depth;      // CV_16UC1
  cv::Mat mask;       // CV_8UC1
  cv::Mat instances;  // CV_16UC1
  geometry::Pose T_wc;
};

View readView(const std::filesystem::path& folder, const core::StampedPose& pose) {
  return {readImage(folder / frameImagePath("depth", pose.timestamp)),
          readImage(folder / frameImagePath("mask", pose.timestamp)),
          readImage(folder / frameImagePath("instances", pose.timestamp)), pose.T_wc};
}

// Inverse depth at (x, y) by bilinear interpolation among the four pixels around it, which must
// be valid, static, of `instance` and on one plane: the 4x4 pixels around them have no kink in
// inverse depth beyond what the depth quantisation explains. Inverse depth is affine in the
// pixel coordinates on a plane, so the interpolation is then exact up to quantisation.
std::optional<double> interpolateInverseDepth(const View& view, double x, double y,
                                              std::uint16_t instance, double depth_factor) {
  const int u0 = static_cast<int>(std::floor(x));
  const int v0 = static_cast<int>(std::floor(y));
  if (u0 < 1 || v0 < 1 || u0 + 2 >= view.depth.cols || v0 + 2 >= view.depth.rows) return {};
  double w[4][4];
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      const int u = u0 - 1 + c;
      const int v = v0 - 1 + r;
      const std::uint16_t raw = view.depth.at<std::uint16_t>(v, u);
      if (raw == 0 || view.mask.at<std::uint8_t>(v, u) != 0 ||
          view.instances.at<std::uint16_t>(v, u) != instance) {
        return {};
      }
      w[r][c] = depth_factor / raw;
    }
  }
  // Quantisation moves z by up to half a unit, inverse depth by up to w^2 / (2 depth_factor).
  const double tolerance = 2.5 * w[1][1] * w[1][1] / depth_factor;
  for (int i = 0; i < 4; ++i) {
    for (int j = 1; j < 3; ++j) {
      if (std::abs(w[i][j - 1] - 2 * w[i][j] + w[i][j + 1]) > tolerance) return {};
      if (std::abs(w[j - 1][i] - 2 * w[j][i] + w[j + 1][i]) > tolerance) return {};
    }
  }
  const double fx = x - u0;
  const double fy = y - v0;
  return (1 - fy) * ((1 - fx) * w[1][1] + fx * w[1][2]) + fy * ((1 - fx) * w[2][1] + fx * w[2][2]);
}

struct Agreement {
  std::vector<double> errors;  // metres, one per compared pixel
  int occluded = 0;            // behind a nearer part of the same object in the other view
};

// Back-projects every static pixel of view a, finds it in view b and back-projects it from there.
Agreement compareViews(const View& a, const View& b, const core::Camera& camera) {
  Agreement agreement;
  const geometry::Pose b_from_a = b.T_wc.inverse() * a.T_wc;
  for (int v = 0; v < a.depth.rows; ++v) {
    for (int u = 0; u < a.depth.cols; ++u) {
      const std::uint16_t raw = a.depth.at<std::uint16_t>(v, u);
      if (raw == 0 || a.mask.at<std::uint8_t>(v, u) != 0) continue;
      const Eigen::Vector3d p_a = camera.backProject(u, v, raw / camera.depth_factor);
      const Eigen::Vector3d p_b = b_from_a * p_a;
      if (p_b.z() < 0.1) continue;
      const Eigen::Vector2d uv = camera.project(p_b);
      const auto inverse = interpolateInverseDepth(
          b, uv.x(), uv.y(), a.instances.at<std::uint16_t>(v, u), camera.depth_factor);
      if (!inverse) continue;
      const double z_b = 1.0 / *inverse;
      if (z_b < p_b.z() - 0.005) {
        ++agreement.occluded;
        continue;
      }
      const Eigen::Vector3d q_b = camera.backProject(uv.x(), uv.y(), z_b);
      agreement.errors.push_back((b.T_wc * q_b - a.T_wc * p_a).norm());
    }
  }
  return agreement;
}

void expectConsistentViews(const std::filesystem::path& folder, const core::Camera& camera,
                           const std::vector<std::pair<int, int>>& pairs) {
  const core::Trajectory truth = io::readTumTrajectory(folder / "groundtruth.txt");
  for (const auto& [i, j] : pairs) {
    Agreement agreement =
        compareViews(readView(folder, truth[i]), readView(folder, truth[j]), camera);
    auto& errors = agreement.errors;
    ASSERT_FALSE(errors.empty());
    std::sort(errors.begin(), errors.end());
    const double median = errors[errors.size() / 2];
    const double p99 = errors[errors.size() * 99 / 100];
    const double max = errors.back();
    std::cout << "frames " << i << " -> " << j << ": " << errors.size()
              << " static pixels agree to median " << median * 1000 << " mm, 99 % " << p99 * 1000
              << " mm, max " << max * 1000 << " mm (" << agreement.occluded << " occluded)\n";
    EXPECT_GT(errors.size(), static_cast<std::size_t>(camera.width * camera.height / 8));
    EXPECT_LT(median, 0.0002);
    EXPECT_LT(max, 0.001);
    EXPECT_LT(agreement.occluded, static_cast<int>(errors.size() / 20));
  }
}

TEST(SynthGenerator, GroundTruthPosesAndDepthAgreeBetweenViews) {
  const ScopedTempDir dir;
  const SynthOptions options = smallOptions(61, 320, 240);
  generateSequence(options, dir.path());
  expectConsistentViews(dir.path(), synthCamera(options), {{0, 30}, {30, 60}, {60, 15}});
}

TEST(SynthGenerator, GroundTruthAgreesAcrossTheLoop) {
  const ScopedTempDir dir;
  SynthOptions options = smallOptions(kSynthMinLoopFrames, 128, 96);
  options.path = "loop";
  generateSequence(options, dir.path());
  expectConsistentViews(dir.path(), synthCamera(options),
                        {{0, 30}, {100, 60}, {200, kSynthMinLoopFrames - 1}});
}

TEST(SynthGenerator, MasksShowExactlyTheDynamicObjects) {
  const ScopedTempDir dir;
  SynthOptions options = smallOptions(40, 160, 120);
  options.people = 3;
  options.moved_furniture = true;
  generateSequence(options, dir.path());
  const auto dynamic = readDynamicObjects(dir.path() / "dynamic_objects_gt.txt");
  const auto meta = nlohmann::json::parse(fileBytes(dir.path() / "meta.json"));
  int chair = 0;
  for (const auto& object : meta["objects"]) {
    if (object["name"] == "chair_1") chair = object["instance_id"];
  }
  ASSERT_NE(chair, 0);
  int frames_chair_moving_in_view = 0;
  int frames_chair_resting_in_view = 0;
  for (const auto& [timestamp, path] : readList(dir.path() / "mask.txt")) {
    const cv::Mat mask = readImage(dir.path() / path);
    const cv::Mat instances = readImage(dir.path() / frameImagePath("instances", timestamp));
    const std::set<int> moving = dynamic.count(timestamp) ? dynamic.at(timestamp) : std::set<int>{};
    bool chair_seen = false;
    for (int v = 0; v < mask.rows; ++v) {
      for (int u = 0; u < mask.cols; ++u) {
        const int instance = instances.at<std::uint16_t>(v, u);
        const bool in_mask = mask.at<std::uint8_t>(v, u) == 255;
        ASSERT_TRUE(in_mask || mask.at<std::uint8_t>(v, u) == 0);
        ASSERT_EQ(in_mask, moving.count(instance) > 0)
            << "pixel " << u << "," << v << " instance " << instance << " at " << timestamp;
        chair_seen = chair_seen || instance == chair;
      }
    }
    if (chair_seen && moving.count(chair)) ++frames_chair_moving_in_view;
    if (chair_seen && !moving.count(chair)) ++frames_chair_resting_in_view;
  }
  EXPECT_GT(frames_chair_moving_in_view, 5);
  EXPECT_GT(frames_chair_resting_in_view, 5);
}

TEST(SynthGenerator, StaticSceneHasEmptyMasks) {
  const ScopedTempDir dir;
  SynthOptions options = smallOptions(6, 96, 72);
  options.people = 0;
  const SynthSummary summary = generateSequence(options, dir.path());
  EXPECT_EQ(summary.frames_with_person, 0);
  EXPECT_EQ(summary.max_dynamic_share, 0.0);
  for (const auto& [timestamp, path] : readList(dir.path() / "mask.txt")) {
    EXPECT_EQ(cv::countNonZero(readImage(dir.path() / path)), 0) << path;
  }
  EXPECT_TRUE(util::readTextRows(dir.path() / "dynamic_objects_gt.txt").empty());
}

TEST(SynthGenerator, DefaultPeopleWalkThroughTheView) {
  const ScopedTempDir dir;
  const SynthSummary summary = generateSequence(smallOptions(90, 80, 60), dir.path());
  std::cout << "person visible in " << summary.frames_with_person << " of " << summary.frames
            << " frames; dynamic pixels mean " << summary.mean_dynamic_share * 100 << " %, max "
            << summary.max_dynamic_share * 100 << " %\n";
  EXPECT_GE(summary.frames_with_person, summary.frames * 7 / 10);
  EXPECT_GT(summary.mean_dynamic_share, 0.03);
  EXPECT_LT(summary.mean_dynamic_share, 0.3);
  EXPECT_LT(summary.max_dynamic_share, 0.5);
}

TEST(SynthGenerator, ReportsBadOptionsAndUnwritableFolders) {
  const ScopedTempDir dir;
  SynthOptions options = smallOptions(0, 64, 48);
  EXPECT_THROW(generateSequence(options, dir.path() / "never"), util::Error);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "never"));
  options.frames = 1;
  std::ofstream(dir.path() / "a_file") << "x";
  EXPECT_THROW(generateSequence(options, dir.path() / "a_file"), util::Error);
}

TEST(SynthGenerator, ReportsProgressInOrder) {
  const ScopedTempDir dir;
  std::vector<int> calls;
  generateSequence(smallOptions(7, 64, 48), dir.path(), [&](int done, int total) {
    EXPECT_EQ(total, 7);
    calls.push_back(done);
  });
  EXPECT_EQ(calls, (std::vector<int>{1, 2, 3, 4, 5, 6, 7}));
}

}  // namespace
}  // namespace segslam::synth
