#include "segslam/segmentation/depth_mask_refiner.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <stdexcept>

namespace segslam::segmentation {
namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;
const cv::Rect kObject(60, 40, 40, 50);

// A flat object 1.5 m away in front of a wall 3 m away.
cv::Mat sceneDepth() {
  cv::Mat depth(kHeight, kWidth, CV_32FC1, cv::Scalar(3.0f));
  depth(kObject).setTo(1.5f);
  return depth;
}

cv::Mat maskOf(const cv::Rect& rect) {
  cv::Mat mask = cv::Mat::zeros(kHeight, kWidth, CV_8UC1);
  mask(rect).setTo(255);
  return mask;
}

TEST(RefineMaskByDepth, ALaggingMaskSnapsToTheObjectWithinTheBand) {
  const cv::Mat lagging = maskOf(kObject - cv::Point(12, 0));
  const cv::Mat refined = refineMaskByDepth(lagging, sceneDepth(), 16);
  EXPECT_EQ(cv::countNonZero(refined != maskOf(kObject)), 0);
}

TEST(RefineMaskByDepth, AtHalfResolutionALaggingMaskSnapsToTheObjectAsWell) {
  DepthRefinementOptions half;
  half.downscale = 2;
  const cv::Mat lagging = maskOf(kObject - cv::Point(12, 0));
  const cv::Mat refined = refineMaskByDepth(lagging, sceneDepth(), 16, {}, half);
  EXPECT_EQ(cv::countNonZero(refined != maskOf(kObject)), 0);
  half.downscale = 0;
  EXPECT_THROW(refineMaskByDepth(lagging, sceneDepth(), 16, {}, half), std::invalid_argument);
}

TEST(RefineMaskByDepth, TheObjectIsNotFollowedBeyondTheBand) {
  const cv::Mat lagging = maskOf(kObject - cv::Point(10, 0));
  const cv::Mat refined = refineMaskByDepth(lagging, sceneDepth(), 6);
  const cv::Rect reachable(kObject.x, kObject.y, kObject.width - 10 + 6, kObject.height);
  EXPECT_EQ(cv::countNonZero(refined != maskOf(reachable)), 0);
}

TEST(RefineMaskByDepth, MaskPixelsWithoutDepthAreKeptAndNothingElseIsAdded) {
  cv::Mat depth = sceneDepth();
  const cv::Rect hole(70, 50, 10, 10);
  depth(hole).setTo(0.0f);
  const cv::Mat refined = refineMaskByDepth(maskOf(kObject), depth, 8);
  EXPECT_EQ(cv::countNonZero(refined != maskOf(kObject)), 0);
}

TEST(RefineMaskByDepth, RegionsAtAnotherDepthThanTheObjectsAreDropped) {
  // Where the mask is, the object has gone and uncovered a box 2.2 m away.
  const cv::Rect uncovered(10, 10, 30, 30);
  cv::Mat depth = sceneDepth();
  depth(uncovered).setTo(2.2f);
  const cv::Mat old_mask = maskOf(uncovered);
  EXPECT_EQ(cv::countNonZero(refineMaskByDepth(old_mask, depth, 8, {1.5f})), 0);
  EXPECT_EQ(cv::countNonZero(refineMaskByDepth(old_mask, depth, 8) != old_mask), 0);
}

// A person standing at a desk at his own depth is one depth-connected region with it, mostly
// outside his mask: the masked part stays (dropping the region dropped the person).
TEST(RefineMaskByDepth, AnObjectJoinedByDepthToALargerSurfaceKeepsItsMaskedPart) {
  const cv::Rect arm(70, 20, 14, 40);
  cv::Mat depth(kHeight, kWidth, CV_32FC1, cv::Scalar(3.0f));
  depth(arm).setTo(1.5f);
  depth(cv::Rect(0, 60, kWidth, kHeight - 60)).setTo(1.5f);  // the desk, touching the arm
  const cv::Mat mask = maskOf(arm);
  EXPECT_EQ(cv::countNonZero(refineMaskByDepth(mask, depth, 16, {1.5f}) != mask), 0);
  DepthRefinementOptions dropping;
  dropping.keep_masked_part_of_joined_objects = false;
  EXPECT_EQ(cv::countNonZero(refineMaskByDepth(mask, depth, 16, {1.5f}, dropping) & mask), 0)
      << "off, the joined region goes";
}

// Only the band around the mask is searched: a frame of more image around the scene (a whole
// number of seed steps wide, so the seeds stay on the same pixels) changes nothing.
TEST(RefineMaskByDepth, ImageBeyondTheBandDoesNotChangeTheResult) {
  cv::Mat depth = sceneDepth();
  depth(cv::Rect(120, 10, 20, 20)).setTo(1.5f);  // another object at the same depth, out of reach
  const cv::Mat lagging = maskOf(kObject - cv::Point(9, 3));
  const cv::Mat refined = refineMaskByDepth(lagging, depth, 12, {1.5f});
  constexpr int kFrame = 40;
  cv::Mat wider_depth;
  cv::Mat wider_mask;
  cv::copyMakeBorder(depth, wider_depth, kFrame, kFrame, kFrame, kFrame, cv::BORDER_CONSTANT,
                     cv::Scalar(3.0f));
  cv::copyMakeBorder(lagging, wider_mask, kFrame, kFrame, kFrame, kFrame, cv::BORDER_CONSTANT,
                     cv::Scalar(0));
  const cv::Mat wider = refineMaskByDepth(wider_mask, wider_depth, 12, {1.5f});
  EXPECT_GT(cv::countNonZero(refined), 0);
  EXPECT_EQ(cv::countNonZero(wider(cv::Rect(kFrame, kFrame, kWidth, kHeight)) != refined), 0);
  EXPECT_EQ(cv::countNonZero(wider), cv::countNonZero(refined));
}

TEST(RefineMaskByDepth, PartsTooThinForAnInteriorAreKept) {
  const cv::Mat thin = maskOf(cv::Rect(20, 10, 3, 60));
  EXPECT_EQ(cv::countNonZero(refineMaskByDepth(thin, sceneDepth(), 8) != thin), 0);
}

TEST(ObjectDepths, MedianDepthOfEachLargeEnoughPart) {
  cv::Mat depth = sceneDepth();
  const cv::Rect second(10, 10, 30, 30);
  depth(second).setTo(2.2f);
  cv::Mat mask = maskOf(kObject) | maskOf(second) | maskOf(cv::Rect(140, 100, 5, 5));
  const std::vector<float> depths = objectDepths(mask, depth);
  ASSERT_EQ(depths.size(), 2u);
  EXPECT_FLOAT_EQ(depths[0], 2.2f);
  EXPECT_FLOAT_EQ(depths[1], 1.5f);
}

// A person within arm's reach of the camera changes depth by more than a fifth within a few
// frames: near the camera an object's region may be up to min_object_depth_tolerance_m off.
TEST(RefineMaskByDepth, NearTheCameraAnObjectMayHaveMovedByTheToleranceInMetres) {
  cv::Mat depth(kHeight, kWidth, CV_32FC1, cv::Scalar(3.0f));
  depth(kObject).setTo(0.27f);
  const cv::Mat mask = maskOf(kObject);
  EXPECT_EQ(cv::countNonZero(refineMaskByDepth(mask, depth, 8, {0.36f}) != mask), 0);
  DepthRefinementOptions share_only;
  share_only.min_object_depth_tolerance_m = 0.0;
  EXPECT_EQ(cv::countNonZero(refineMaskByDepth(mask, depth, 8, {0.36f}, share_only)), 0);
  EXPECT_EQ(cv::countNonZero(refineMaskByDepth(mask, depth, 8, {0.45f})), 0) << "0.18 m off";
}

TEST(RefineMaskByDepth, WithoutDepthOrObjectTheMaskIsUnchanged) {
  const cv::Mat mask = maskOf(kObject);
  EXPECT_EQ(cv::countNonZero(refineMaskByDepth(mask, cv::Mat(), 8) != mask), 0);
  const cv::Mat empty = cv::Mat::zeros(kHeight, kWidth, CV_8UC1);
  EXPECT_EQ(cv::countNonZero(refineMaskByDepth(empty, sceneDepth(), 8)), 0);
}

}  // namespace
}  // namespace segslam::segmentation
