#include "segslam/io/frame_images.h"

#include <gtest/gtest.h>

#include <fstream>

#include "segslam/io/io_test_support.h"
#include "segslam/testing/test_support.h"

namespace segslam::io {
namespace {

namespace fs = std::filesystem;
using testing::contains;
using testing::errorMessage;
using testing::writeImage;
using testing::writeText;

const cv::Size kSize(8, 6);

core::Camera imageCamera() {
  core::Camera camera;
  camera.name = "small";
  camera.width = kSize.width;
  camera.height = kSize.height;
  camera.depth_factor = 1000.0;
  return camera;
}

class TumDatasetFrameImages : public ::testing::Test {
 protected:
  // Writes `image` as <temp>/<name> and returns the path.
  fs::path write(const std::string& name, const cv::Mat& image) {
    const fs::path file = temp_.path() / name;
    writeImage(file, image);
    return file;
  }

  segslam::testing::ScopedTempDir temp_;
};

TEST_F(TumDatasetFrameImages, ColourIsReadAsBgr) {
  cv::Mat bgr(kSize, CV_8UC3, cv::Scalar(1, 2, 3));
  const cv::Mat read = readColourImage(write("c.png", bgr), imageCamera());
  ASSERT_EQ(read.type(), CV_8UC3);
  EXPECT_EQ(read.at<cv::Vec3b>(2, 2), cv::Vec3b(1, 2, 3));
}

TEST_F(TumDatasetFrameImages, GreyAndBgraColourAreConverted) {
  const cv::Mat grey =
      readColourImage(write("g.png", cv::Mat(kSize, CV_8UC1, cv::Scalar(77))), imageCamera());
  ASSERT_EQ(grey.type(), CV_8UC3);
  EXPECT_EQ(grey.at<cv::Vec3b>(1, 1), cv::Vec3b(77, 77, 77));
  const cv::Mat bgra = readColourImage(
      write("a.png", cv::Mat(kSize, CV_8UC4, cv::Scalar(4, 5, 6, 7))), imageCamera());
  ASSERT_EQ(bgra.type(), CV_8UC3);
  EXPECT_EQ(bgra.at<cv::Vec3b>(1, 1), cv::Vec3b(4, 5, 6));
}

TEST_F(TumDatasetFrameImages, SixteenBitColourIsRejected) {
  const fs::path file = write("c16.png", cv::Mat(kSize, CV_16UC3, cv::Scalar(1000, 0, 0)));
  EXPECT_EQ(errorMessage([&] { (void)readColourImage(file, imageCamera()); }),
            file.string() +
                ": colour image must be 8-bit with 1, 3 or 4 channels but is 16-bit "
                "3-channel");
}

TEST_F(TumDatasetFrameImages, ColourOfAnotherSizeThanTheCameraIsRejected) {
  const fs::path file = write("big.png", cv::Mat(10, 12, CV_8UC3, cv::Scalar(0)));
  EXPECT_EQ(errorMessage([&] { (void)readColourImage(file, imageCamera()); }),
            file.string() + ": colour image is 12x10 but camera 'small' is 8x6");
}

TEST_F(TumDatasetFrameImages, MissingOrCorruptFilesAreRejected) {
  const fs::path missing = temp_.path() / "missing.png";
  EXPECT_EQ(errorMessage([&] { (void)readColourImage(missing, imageCamera()); }),
            missing.string() + ": image file not found");
  const fs::path corrupt = temp_.path() / "corrupt.png";
  writeText(corrupt, "\x89PNG\r\n\x1a\n truncated");
  EXPECT_EQ(errorMessage([&] { (void)readDepthImage(corrupt, imageCamera(), kSize); }),
            corrupt.string() +
                ": damaged image: the PNG data stops before its IEND chunk: the file is truncated");
  const fs::path garbage = temp_.path() / "garbage.png";
  writeText(garbage, "not an image at all");
  EXPECT_EQ(errorMessage([&] { (void)readDepthImage(garbage, imageCamera(), kSize); }),
            garbage.string() + ": cannot decode the image (unreadable or corrupt file)");
  EXPECT_THROW((void)readDepthImage(garbage, imageCamera(), kSize), DamagedImageError);
}

// libjpeg decodes a truncated JPEG half grey and only prints "Premature end of JPEG file".
TEST_F(TumDatasetFrameImages, TruncatedJpegIsDamaged) {
  const fs::path jpeg = write("c.jpg", cv::Mat(kSize, CV_8UC3, cv::Scalar(1, 2, 3)));
  EXPECT_FALSE(imageTruncation(jpeg));
  fs::resize_file(jpeg, fs::file_size(jpeg) - 10);
  EXPECT_EQ(imageTruncation(jpeg),
            "the JPEG data stops before its end marker (FF D9): the file is truncated");
  try {
    (void)readColourImage(jpeg, imageCamera());
    FAIL() << "expected a DamagedImageError";
  } catch (const DamagedImageError& e) {
    EXPECT_EQ(std::string(e.what()),
              jpeg.string() +
                  ": damaged image: the JPEG data stops before its end marker (FF D9): the file "
                  "is truncated");
  }
}

TEST_F(TumDatasetFrameImages, PaddingAfterTheEndMarkerIsNoDamage) {
  const fs::path jpeg = write("c.jpg", cv::Mat(kSize, CV_8UC3, cv::Scalar(1, 2, 3)));
  const fs::path png = write("d.png", cv::Mat(kSize, CV_16UC1, cv::Scalar(1000)));
  for (const fs::path& file : {jpeg, png}) {
    std::ofstream(file, std::ios::binary | std::ios::app) << std::string("\0\0\0\n \r\n", 7);
    EXPECT_FALSE(imageTruncation(file)) << file;
  }
  EXPECT_EQ(readColourImage(jpeg, imageCamera()).size(), kSize);
  EXPECT_FLOAT_EQ(readDepthImage(png, imageCamera(), kSize).at<float>(0, 0), 1.0f);
  fs::resize_file(png, fs::file_size(png) - 12);  // the padding and 5 bytes of the IEND chunk
  EXPECT_EQ(imageTruncation(png),
            "the PNG data stops before its IEND chunk: the file is truncated");
}

TEST_F(TumDatasetFrameImages, DepthIsConvertedToMetresAndZeroStaysZero) {
  cv::Mat raw(kSize, CV_16UC1, cv::Scalar(1500));
  raw.at<std::uint16_t>(0, 0) = 0;
  raw.at<std::uint16_t>(5, 7) = 65535;
  const cv::Mat depth = readDepthImage(write("d.png", raw), imageCamera(), kSize);
  ASSERT_EQ(depth.type(), CV_32FC1);
  EXPECT_EQ(depth.at<float>(0, 0), 0.0f);
  EXPECT_FLOAT_EQ(depth.at<float>(1, 1), 1.5f);
  EXPECT_FLOAT_EQ(depth.at<float>(5, 7), 65.535f);
}

TEST_F(TumDatasetFrameImages, DepthMustBeSixteenBitSingleChannelOfTheColourSize) {
  const fs::path eight = write("d8.png", cv::Mat(kSize, CV_8UC1, cv::Scalar(9)));
  EXPECT_EQ(errorMessage([&] { (void)readDepthImage(eight, imageCamera(), kSize); }),
            eight.string() + ": depth image must be 16-bit 1-channel but is 8-bit 1-channel");
  const fs::path colour = write("dc.png", cv::Mat(kSize, CV_16UC3, cv::Scalar(9)));
  EXPECT_EQ(errorMessage([&] { (void)readDepthImage(colour, imageCamera(), kSize); }),
            colour.string() + ": depth image must be 16-bit 1-channel but is 16-bit 3-channel");
  const fs::path small = write("ds.png", cv::Mat(3, 4, CV_16UC1, cv::Scalar(9)));
  EXPECT_EQ(errorMessage([&] { (void)readDepthImage(small, imageCamera(), kSize); }),
            small.string() + ": depth image is 4x3 but the colour image is 8x6");
}

TEST_F(TumDatasetFrameImages, MaskIsNormalisedTo255) {
  cv::Mat raw = cv::Mat::zeros(kSize, CV_8UC1);
  raw.at<std::uint8_t>(1, 1) = 1;
  raw.at<std::uint8_t>(2, 2) = 128;
  raw.at<std::uint8_t>(3, 3) = 255;
  const cv::Mat mask = readMaskImage(write("m.png", raw), kSize);
  ASSERT_EQ(mask.type(), CV_8UC1);
  EXPECT_EQ(mask.at<std::uint8_t>(1, 1), 255);
  EXPECT_EQ(mask.at<std::uint8_t>(2, 2), 255);
  EXPECT_EQ(mask.at<std::uint8_t>(3, 3), 255);
  EXPECT_EQ(cv::countNonZero(mask), 3);
}

TEST_F(TumDatasetFrameImages, MaskMustBeEightBitSingleChannelOfTheColourSize) {
  const fs::path colour = write("mc.png", cv::Mat(kSize, CV_8UC3, cv::Scalar(255)));
  EXPECT_EQ(errorMessage([&] { (void)readMaskImage(colour, kSize); }),
            colour.string() + ": mask must be 8-bit 1-channel but is 8-bit 3-channel");
  const fs::path small = write("ms.png", cv::Mat(5, 8, CV_8UC1, cv::Scalar(0)));
  EXPECT_EQ(errorMessage([&] { (void)readMaskImage(small, kSize); }),
            small.string() + ": mask is 8x5 but the colour image is 8x6");
}

TEST_F(TumDatasetFrameImages, LabelsAreEightBitAndInstancesSixteenBit) {
  const fs::path labels = write("l.png", cv::Mat(kSize, CV_8UC1, cv::Scalar(8)));
  EXPECT_EQ(readLabelImage(labels, kSize).at<std::uint8_t>(0, 0), 8);
  const fs::path instances = write("i.png", cv::Mat(kSize, CV_16UC1, cv::Scalar(700)));
  EXPECT_EQ(readInstanceImage(instances, kSize).at<std::uint16_t>(0, 0), 700);
  EXPECT_EQ(errorMessage([&] { (void)readLabelImage(instances, kSize); }),
            instances.string() + ": label image must be 8-bit 1-channel but is 16-bit 1-channel");
  EXPECT_EQ(errorMessage([&] { (void)readInstanceImage(labels, kSize); }),
            labels.string() + ": instance image must be 16-bit 1-channel but is 8-bit 1-channel");
}

}  // namespace
}  // namespace segslam::io
