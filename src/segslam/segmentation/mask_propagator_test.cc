#include "segslam/segmentation/mask_propagator.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace segslam::segmentation {
namespace {

cv::Mat texture(cv::Size size) {
  cv::Mat noise(size, CV_8UC1);
  cv::RNG rng(7);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(noise, noise, cv::Size(0, 0), 2.0);
  cv::normalize(noise, noise, 0, 255, cv::NORM_MINMAX);
  return noise;
}

cv::Mat shifted(const cv::Mat& image, double dx, double dy) {
  const cv::Mat transform = (cv::Mat_<double>(2, 3) << 1, 0, dx, 0, 1, dy);
  cv::Mat out;
  cv::warpAffine(image, out, transform, image.size(), cv::INTER_LINEAR, cv::BORDER_REFLECT);
  return out;
}

double iou(const cv::Mat& a, const cv::Mat& b) {
  return static_cast<double>(cv::countNonZero(a & b)) / cv::countNonZero(a | b);
}

TEST(MaskPropagator, LabelsFollowTheImageMotion) {
  const cv::Mat base = texture({320, 240});
  MaskPropagator propagator;
  for (int frame = 0; frame <= 4; ++frame)
    propagator.addFrame(10 + frame, shifted(base, 3.0 * frame, -2.0 * frame));
  cv::Mat labels = cv::Mat::zeros(base.size(), CV_8UC1);
  // Labelled on frame 11 (shifted by 3, -2): after three more steps it moves by (9, -6).
  labels(cv::Rect(100 + 3, 120 - 2, 60, 40)).setTo(7);
  const cv::Mat carried = propagator.propagate(labels, 11);
  ASSERT_EQ(carried.size(), base.size());
  cv::Mat expected = cv::Mat::zeros(base.size(), CV_8UC1);
  expected(cv::Rect(100 + 12, 120 - 8, 60, 40)).setTo(7);
  EXPECT_GT(iou(carried == 7, expected == 7), 0.85);
  EXPECT_EQ(cv::countNonZero((carried != 0) & (carried != 7)), 0);  // labels are not blended
}

// Two mask streams over the same frames share one propagator: the second addFrame of a frame
// must not replace the flow into it by a zero flow from the frame to itself.
TEST(MaskPropagator, AddingTheNewestFrameAgainKeepsItsFlow) {
  const cv::Mat base = texture({320, 240});
  MaskPropagator shared;
  MaskPropagator single;
  for (int frame = 0; frame <= 2; ++frame) {
    const cv::Mat image = shifted(base, 4.0 * frame, 0.0);
    shared.addFrame(frame, image);
    shared.addFrame(frame, image);
    single.addFrame(frame, image);
  }
  cv::Mat labels = cv::Mat::zeros(base.size(), CV_8UC1);
  labels(cv::Rect(100, 100, 60, 40)).setTo(5);
  const cv::Mat carried = shared.propagate(labels, 0);
  ASSERT_FALSE(carried.empty());
  EXPECT_EQ(cv::countNonZero(carried != single.propagate(labels, 0)), 0);
  EXPECT_LT(iou(carried == 5, labels == 5), 0.9);  // it moved
}

// Two textured squares over a still textured background, one moving right, one moving up: each
// object is moved whole by its own motion and keeps its size.
TEST(MaskPropagator, ObjectsMoveWholeEachByItsOwnMotion) {
  const cv::Mat background = texture({640, 480});
  const cv::Mat pattern = texture({120, 120}) / 2 + 128;
  const cv::Rect right(100, 100, 120, 120);
  const cv::Rect up(400, 300, 120, 120);
  MaskPropagator propagator;
  for (int frame = 0; frame <= 4; ++frame) {
    cv::Mat image = background.clone();
    pattern.copyTo(image(right + cv::Point(5 * frame, 0)));
    pattern.copyTo(image(up + cv::Point(0, -4 * frame)));
    propagator.addFrame(frame, image);
  }
  cv::Mat mask = cv::Mat::zeros(background.size(), CV_8UC1);
  mask(right).setTo(255);
  mask(up).setTo(255);
  const cv::Mat moved = propagator.moveObjects(mask, 0);
  ASSERT_EQ(moved.size(), mask.size());
  cv::Mat expected = cv::Mat::zeros(background.size(), CV_8UC1);
  expected(right + cv::Point(20, 0)).setTo(255);
  expected(up + cv::Point(0, -16)).setTo(255);
  EXPECT_GT(iou(moved, expected), 0.8);
  EXPECT_EQ(cv::countNonZero(moved), cv::countNonZero(mask));
  EXPECT_TRUE(propagator.moveObjects(mask, 9).empty());
}

// A mask that has slipped partly off a moving square: 45 % of it on the square (moving right),
// 25 % on a background band moving left, 30 % on a still one. The median motion of its pixels is
// the still part's, so the mask would stay where it is; it follows the square, the motion most of
// its pixels share.
TEST(MaskPropagator, AnObjectFollowsTheMotionMostOfItsPixelsShare) {
  const cv::Mat still = texture({640, 480});
  const cv::Mat band = texture({640, 140}) / 2 + 64;
  const cv::Mat pattern = texture({200, 200}) / 2 + 128;
  const cv::Rect square(100, 140, 200, 200);
  MaskPropagator propagator;
  constexpr int kFrames = 6;
  for (int frame = 0; frame <= kFrames; ++frame) {
    cv::Mat image = still.clone();
    shifted(band, -12.0 * frame, 0.0).copyTo(image(cv::Rect(0, 0, 640, 140)));
    pattern.copyTo(image(square + cv::Point(8 * frame, 0)));
    propagator.addFrame(frame, image);
  }
  cv::Mat mask = cv::Mat::zeros(still.size(), CV_8UC1);
  mask(cv::Rect(100, 29, 200, 444)).setTo(255);
  const cv::Mat moved = propagator.moveObjects(mask, 0);
  ASSERT_EQ(moved.size(), mask.size());
  const cv::Rect square_now = square + cv::Point(8 * kFrames, 0);
  EXPECT_GT(cv::countNonZero(moved(square_now)), 0.95 * square_now.area());
}

TEST(MaskPropagator, NewestFrameIsReturnedAsIsAndUnknownSourcesGiveNothing) {
  const cv::Mat base = texture({160, 120});
  MaskPropagator propagator(/*history=*/2);
  const cv::Mat labels(base.size(), CV_8UC1, cv::Scalar(3));
  EXPECT_TRUE(propagator.propagate(labels, 0).empty());  // no frame yet
  for (int frame = 0; frame < 5; ++frame) propagator.addFrame(frame, shifted(base, frame, 0));
  EXPECT_EQ(cv::countNonZero(propagator.propagate(labels, 4) != labels), 0);
  EXPECT_FALSE(propagator.propagate(labels, 2).empty());
  EXPECT_TRUE(propagator.propagate(labels, 1).empty());  // older than the history
  EXPECT_TRUE(propagator.propagate(labels, 9).empty());  // not seen yet
}

}  // namespace
}  // namespace segslam::segmentation
