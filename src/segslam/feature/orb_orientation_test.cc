#include "segslam/feature/orb_orientation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "segslam/feature/feature_test_images.h"

namespace segslam::feature {
namespace {

// Signed difference a - b of two angles in degrees, in (-180, 180].
double angleDifference(double a, double b) {
  double difference = std::fmod(a - b, 360.0);
  if (difference > 180.0) difference -= 360.0;
  if (difference <= -180.0) difference += 360.0;
  return difference;
}

// Dark image with a bright blob `offset` away from the centre (50, 50).
cv::Mat blobImage(cv::Point offset) {
  cv::Mat image(101, 101, CV_8UC1, cv::Scalar(20));
  cv::circle(image, cv::Point(50, 50) + offset, 4, cv::Scalar(230), cv::FILLED);
  cv::GaussianBlur(image, image, cv::Size(5, 5), 1.5);
  return image;
}

TEST(OrbOrientation, PointsTowardsTheBrightSide) {
  EXPECT_NEAR(intensityCentroidAngle(blobImage({8, 0}), {50, 50}), 0.0, 1.0);
  EXPECT_NEAR(intensityCentroidAngle(blobImage({0, 8}), {50, 50}), 90.0, 1.0);  // y points down
  EXPECT_NEAR(intensityCentroidAngle(blobImage({-8, 0}), {50, 50}), 180.0, 1.0);
  EXPECT_NEAR(intensityCentroidAngle(blobImage({6, -6}), {50, 50}), 315.0, 1.0);
  // A flat patch has no direction; the angle is still a valid one.
  const float flat = intensityCentroidAngle(cv::Mat(31, 31, CV_8UC1, cv::Scalar(9)), {15, 15});
  EXPECT_GE(flat, 0.0f);
  EXPECT_LT(flat, 360.0f);
}

TEST(OrbOrientation, RotatesWithTheImage) {
  const cv::Mat image = testing::texturedImage({201, 201}, 3);
  const cv::Point centre(100, 100);
  const float original = intensityCentroidAngle(image, centre);
  for (const double degrees : {30.0, 90.0, 150.0, 245.0}) {
    // warpAffine turns the image counter-clockwise on screen by `degrees`, which in image
    // coordinates (y down) is an angle change of -degrees.
    const cv::Mat rotation = cv::getRotationMatrix2D(cv::Point2f(centre), degrees, 1.0);
    cv::Mat rotated;
    cv::warpAffine(image, rotated, rotation, image.size(), cv::INTER_LINEAR);
    const float angle = intensityCentroidAngle(rotated, centre);
    EXPECT_NEAR(angleDifference(angle, original - degrees), 0.0, 3.0) << "rotation " << degrees;
  }
}

}  // namespace
}  // namespace segslam::feature
