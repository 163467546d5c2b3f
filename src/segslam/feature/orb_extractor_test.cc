#include "segslam/feature/orb_extractor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <vector>

#include "segslam/feature/descriptor_distance.h"
#include "segslam/feature/descriptor_matcher.h"
#include "segslam/feature/feature_test_images.h"
#include "segslam/testing/test_support.h"

namespace segslam::feature {
namespace {

const cv::Size kVga(640, 480);

struct Features {
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
};

Features extract(const cv::Mat& gray, const cv::Mat& dynamic_mask = {},
                 const OrbExtractorOptions& options = {}) {
  OrbExtractor extractor(options);
  Features features;
  extractor.extract(gray, dynamic_mask, features.keypoints, features.descriptors);
  return features;
}

// Keypoint counts in a columns x rows grid over the image.
std::vector<int> countsPerCell(const std::vector<cv::KeyPoint>& keypoints, cv::Size image,
                               int columns, int rows) {
  std::vector<int> counts(columns * rows, 0);
  for (const auto& keypoint : keypoints) {
    const int column =
        std::min(columns - 1, static_cast<int>(keypoint.pt.x * columns / image.width));
    const int row = std::min(rows - 1, static_cast<int>(keypoint.pt.y * rows / image.height));
    ++counts[row * columns + column];
  }
  return counts;
}

// The dilated dynamic area by definition (exact Euclidean distance <= radius), independent of the
// extractor's own implementation.
cv::Mat dilatedDynamicArea(const cv::Mat& dynamic_mask, int radius) {
  cv::Mat distance;
  cv::distanceTransform(dynamic_mask == 0, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  return distance <= radius;
}

int keypointsInDynamicArea(const std::vector<cv::KeyPoint>& keypoints, const cv::Mat& dilated) {
  int inside = 0;
  for (const auto& keypoint : keypoints) {
    inside += dilated.at<std::uint8_t>(cvRound(keypoint.pt.y), cvRound(keypoint.pt.x)) != 0;
  }
  return inside;
}

TEST(OrbExtractor, ReachesTheBudgetWithWellFormedKeypoints) {
  const cv::Mat image = testing::texturedImage(kVga, 1);
  OrbExtractor extractor;
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  extractor.extract(image, cv::Mat(), keypoints, descriptors);
  ASSERT_EQ(keypoints.size(), 1000u);
  EXPECT_EQ(descriptors.rows, 1000);
  EXPECT_EQ(descriptors.cols, kDescriptorBytes);
  EXPECT_EQ(descriptors.type(), CV_8UC1);
  std::array<int, 8> per_level{};
  int previous_level = 0;
  for (const auto& keypoint : keypoints) {
    ASSERT_GE(keypoint.octave, previous_level);  // ordered by level
    previous_level = keypoint.octave;
    ++per_level[keypoint.octave];
    const double scale = extractor.scaleFactors()[keypoint.octave];
    EXPECT_NEAR(keypoint.size, 31.0 * scale, 1e-3);
    EXPECT_GE(keypoint.angle, 0.0f);
    EXPECT_LT(keypoint.angle, 360.0f);
    EXPECT_GE(keypoint.response, 7.0f);
    EXPECT_GE(keypoint.pt.x, 15.0 * scale - 1e-3);
    EXPECT_LE(keypoint.pt.x, kVga.width - 15.0 * scale);
  }
  // Every level gets its area share (textured everywhere, so no level runs short).
  EXPECT_NEAR(per_level[0], 323, 2);
  EXPECT_NEAR(per_level[7], 323 / std::pow(1.44, 7), 2);
  EXPECT_EQ(extractor.numLevels(), 8);
  EXPECT_DOUBLE_EQ(extractor.levelSigma2()[2], std::pow(1.2, 4));
  EXPECT_EQ(extractor.pyramid().size(), 8u);
}

TEST(OrbExtractor, SpreadsKeypointsEvenly) {
  const cv::Mat image = testing::texturedImage(kVga, 2);
  const Features features = extract(image);
  const std::vector<int> counts = countsPerCell(features.keypoints, kVga, 4, 4);
  const double mean = 1000.0 / 16.0;
  for (std::size_t cell = 0; cell < counts.size(); ++cell) {
    EXPECT_GT(counts[cell], 0.5 * mean) << "cell " << cell;
    EXPECT_LT(counts[cell], 1.6 * mean) << "cell " << cell;
  }
}

TEST(OrbExtractor, KeepsOffTheDilatedDynamicAreaAndFillsTheBudgetElsewhere) {
  const cv::Mat image = testing::texturedImage(kVga, 3);
  const Features unmasked = extract(image);
  cv::Mat dynamic(kVga, CV_8UC1, cv::Scalar(0));
  dynamic(cv::Rect(0, 0, 320, 480)).setTo(255);                    // left half
  cv::circle(dynamic, {480, 240}, 50, cv::Scalar(1), cv::FILLED);  // and a blob
  OrbExtractorOptions options;
  options.mask_dilation_px = 12;
  const Features masked = extract(image, dynamic, options);
  EXPECT_EQ(keypointsInDynamicArea(masked.keypoints, dilatedDynamicArea(dynamic, 12)), 0);
  EXPECT_GE(masked.keypoints.size(), 900u);
  EXPECT_EQ(masked.descriptors.rows, static_cast<int>(masked.keypoints.size()));
  // The static quarter at the bottom right gets more than without the mask.
  const auto in_bottom_right = [](const Features& features) {
    return std::count_if(features.keypoints.begin(), features.keypoints.end(),
                         [](const cv::KeyPoint& k) { return k.pt.x > 340 && k.pt.y > 300; });
  };
  EXPECT_GT(in_bottom_right(masked), 1.5 * in_bottom_right(unmasked));
  // The static half is covered evenly: every cell of a 2 x 4 grid over it has keypoints.
  std::vector<cv::KeyPoint> right;
  for (const auto& keypoint : masked.keypoints) {
    right.emplace_back(keypoint.pt - cv::Point2f(320, 0), keypoint.size);
  }
  for (const int count : countsPerCell(right, {320, 480}, 2, 4)) EXPECT_GT(count, 40);
}

TEST(OrbExtractor, AllDynamicGivesNothing) {
  const cv::Mat image = testing::texturedImage(kVga, 4);
  const Features features = extract(image, cv::Mat(kVga, CV_8UC1, cv::Scalar(255)));
  EXPECT_TRUE(features.keypoints.empty());
  EXPECT_EQ(features.descriptors.rows, 0);
}

// p mapped by a 2 x 3 affine transform (CV_64F).
cv::Point2f transformed(const cv::Mat& transform, cv::Point2f p) {
  return {static_cast<float>(transform.at<double>(0, 0) * p.x + transform.at<double>(0, 1) * p.y +
                             transform.at<double>(0, 2)),
          static_cast<float>(transform.at<double>(1, 0) * p.x + transform.at<double>(1, 1) * p.y +
                             transform.at<double>(1, 2))};
}

// Keypoints of two views related by `transform` (2 x 3, from view a to view b) that are the same
// scene point: same level and within 1.5 level pixels of the transformed position.
std::vector<std::pair<int, int>> correspondences(const std::vector<cv::KeyPoint>& a,
                                                 const std::vector<cv::KeyPoint>& b,
                                                 const cv::Mat& transform, cv::Point2f centre,
                                                 float radius) {
  std::vector<std::pair<int, int>> pairs;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (cv::norm(a[i].pt - centre) > radius) continue;
    const cv::Point2f expected = transformed(transform, a[i].pt);
    const double tolerance = 1.5 * std::pow(1.2, a[i].octave);
    for (std::size_t j = 0; j < b.size(); ++j) {
      if (b[j].octave == a[i].octave && cv::norm(b[j].pt - expected) <= tolerance) {
        pairs.emplace_back(static_cast<int>(i), static_cast<int>(j));
        break;
      }
    }
  }
  return pairs;
}

TEST(OrbExtractor, DescriptorsAreRotationInvariant) {
  const cv::Size size(480, 480);
  const cv::Mat image = testing::texturedImage(size, 5, 700);
  const cv::Point2f centre(239.5f, 239.5f);
  const float radius = 170.0f;  // keypoints whose patches stay inside both views
  const Features original = extract(image);
  for (const double degrees : {30.0, 90.0, 150.0}) {
    const cv::Mat rotation = cv::getRotationMatrix2D(centre, degrees, 1.0);
    cv::Mat rotated_image;
    cv::warpAffine(image, rotated_image, rotation, size, cv::INTER_LINEAR);
    const Features rotated = extract(rotated_image);

    const auto pairs =
        correspondences(original.keypoints, rotated.keypoints, rotation, centre, radius);
    ASSERT_GT(pairs.size(), 100u) << degrees;
    std::vector<int> distances;
    for (const auto& [i, j] : pairs) {
      distances.push_back(descriptorDistance(original.descriptors.ptr<std::uint8_t>(i),
                                             rotated.descriptors.ptr<std::uint8_t>(j)));
    }
    std::nth_element(distances.begin(), distances.begin() + distances.size() / 2, distances.end());
    EXPECT_LT(distances[distances.size() / 2], 40) << "rotation " << degrees;

    // Brute-force matching of everything in the central disc: mostly geometrically right.
    const auto matches = matchDescriptors(original.descriptors, rotated.descriptors);
    int considered = 0;
    int correct = 0;
    for (const auto& match : matches) {
      const cv::KeyPoint& a = original.keypoints[match.queryIdx];
      if (cv::norm(a.pt - centre) > radius) continue;
      ++considered;
      const cv::KeyPoint& b = rotated.keypoints[match.trainIdx];
      correct += cv::norm(b.pt - transformed(rotation, a.pt)) < 3.0 * std::pow(1.2, a.octave);
    }
    ASSERT_GT(considered, 100) << degrees;
    EXPECT_GT(correct, 0.7 * considered) << "rotation " << degrees;
  }
}

TEST(OrbExtractor, UnrelatedKeypointsAreFarApart) {
  const Features a = extract(testing::texturedImage(kVga, 6));
  const Features b = extract(testing::texturedImage(kVga, 7));
  std::vector<int> distances;
  for (int i = 0; i < 500; ++i) {
    distances.push_back(
        descriptorDistance(a.descriptors.ptr<std::uint8_t>(i), b.descriptors.ptr<std::uint8_t>(i)));
  }
  std::nth_element(distances.begin(), distances.begin() + 250, distances.end());
  // Not 128: the learned tests are not all balanced (see docs/orb_pattern.md), so unrelated
  // descriptors agree on somewhat more bits than coin flips would.
  EXPECT_GT(distances[250], 85);
}

TEST(OrbExtractor, IsDeterministicSerialOrParallel) {
  const cv::Mat image = testing::texturedImage(kVga, 8);
  cv::Mat dynamic(kVga, CV_8UC1, cv::Scalar(0));
  cv::circle(dynamic, {200, 200}, 80, cv::Scalar(255), cv::FILLED);
  OrbExtractor extractor;
  Features first;
  Features second;
  extractor.extract(image, dynamic, first.keypoints, first.descriptors);
  extractor.extract(image, dynamic, second.keypoints, second.descriptors);
  OrbExtractorOptions parallel_options;
  parallel_options.parallel_levels = true;
  const Features parallel = extract(image, dynamic, parallel_options);
  for (const Features* other : std::array<const Features*, 2>{&second, &parallel}) {
    ASSERT_EQ(other->keypoints.size(), first.keypoints.size());
    for (std::size_t i = 0; i < first.keypoints.size(); ++i) {
      EXPECT_EQ(other->keypoints[i].pt, first.keypoints[i].pt);
      EXPECT_EQ(other->keypoints[i].angle, first.keypoints[i].angle);
      EXPECT_EQ(other->keypoints[i].response, first.keypoints[i].response);
      EXPECT_EQ(other->keypoints[i].octave, first.keypoints[i].octave);
    }
    EXPECT_EQ(cv::norm(other->descriptors, first.descriptors, cv::NORM_HAMMING), 0.0);
  }
  std::vector<cv::KeyPoint> detected;
  extractor.detect(image, dynamic, detected);
  ASSERT_EQ(detected.size(), first.keypoints.size());
  EXPECT_EQ(detected.back().pt, first.keypoints.back().pt);
}

TEST(OrbExtractor, LeavesThePreviousFramesDescriptorsAlone) {
  OrbExtractor extractor;
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  extractor.extract(testing::texturedImage(kVga, 9), cv::Mat(), keypoints, descriptors);
  const cv::Mat previous_frame = descriptors;  // shares the buffer, as a stored frame would
  const cv::Mat snapshot = descriptors.clone();
  extractor.extract(testing::texturedImage(kVga, 10), cv::Mat(), keypoints, descriptors);
  ASSERT_EQ(descriptors.rows, previous_frame.rows);
  EXPECT_EQ(cv::norm(previous_frame, snapshot, cv::NORM_HAMMING), 0.0);
  EXPECT_GT(cv::norm(descriptors, snapshot, cv::NORM_HAMMING), 0.0);
}

TEST(OrbExtractor, RejectsInvalidInputAndOptions) {
  OrbExtractor extractor;
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  const cv::Mat gray(100, 100, CV_8UC1, cv::Scalar(0));
  EXPECT_THROW(extractor.extract(cv::Mat(100, 100, CV_8UC3), cv::Mat(), keypoints, descriptors),
               std::invalid_argument);
  EXPECT_THROW(extractor.extract(cv::Mat(), cv::Mat(), keypoints, descriptors),
               std::invalid_argument);
  EXPECT_THROW(extractor.extract(gray, cv::Mat(50, 100, CV_8UC1), keypoints, descriptors),
               std::invalid_argument);
  EXPECT_THROW(extractor.extract(gray, cv::Mat(100, 100, CV_16UC1), keypoints, descriptors),
               std::invalid_argument);
  OrbExtractorOptions options;
  options.min_fast_threshold = 30;  // above the initial threshold
  EXPECT_THROW(OrbExtractor{options}, std::invalid_argument);
  options = {};
  options.scale_factor = 0.9;
  EXPECT_THROW(OrbExtractor{options}, std::invalid_argument);
  // Tiny images are valid and simply have no room for keypoints.
  extractor.extract(cv::Mat(20, 20, CV_8UC1, cv::Scalar(0)), cv::Mat(), keypoints, descriptors);
  EXPECT_TRUE(keypoints.empty());
}

TEST(OrbExtractor, RealFrameWithPeopleMasked) {
  SEGSLAM_REQUIRE_SHARED(frames, "tum_walking_xyz_frames");
  const cv::Mat gray =
      cv::imread((frames / "rgb" / "1341846313.592026.png").string(), cv::IMREAD_GRAYSCALE);
  const cv::Mat static01 =
      cv::imread((frames / "mask" / "1341846313.592026.png").string(), cv::IMREAD_GRAYSCALE);
  ASSERT_FALSE(gray.empty());
  ASSERT_FALSE(static01.empty());
  const cv::Mat dynamic = static01 == 0;  // this data set marks people with 0
  const Features features = extract(gray, dynamic);
  EXPECT_EQ(keypointsInDynamicArea(features.keypoints, dilatedDynamicArea(dynamic, 10)), 0);
  EXPECT_GE(features.keypoints.size(), 900u);
}

TEST(OrbExtractor, RealFrameIsCoveredEvenly) {
  SEGSLAM_REQUIRE_SHARED(frame, "tum_fr1_xyz_300/rgb/1305031102.175304.jpg");
  const cv::Mat gray = cv::imread(frame.string(), cv::IMREAD_GRAYSCALE);
  ASSERT_FALSE(gray.empty());
  const Features features = extract(gray);
  EXPECT_GE(features.keypoints.size(), 950u);
  const std::vector<int> counts = countsPerCell(features.keypoints, gray.size(), 4, 4);
  EXPECT_EQ(std::count(counts.begin(), counts.end(), 0), 0);
  EXPECT_LT(*std::max_element(counts.begin(), counts.end()), 4 * 1000 / 16);
}

}  // namespace
}  // namespace segslam::feature
