#include "segslam/io/tum_dataset.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "segslam/io/frame_images.h"
#include "segslam/io/io_test_support.h"
#include "segslam/io/timestamp_association.h"
#include "segslam/io/trajectory_io.h"
#include "segslam/testing/test_support.h"

namespace segslam::io {
namespace {

namespace fs = std::filesystem;
using testing::contains;
using testing::errorMessage;
using testing::TinyDataset;
using testing::writeImage;
using testing::writeText;
using testing::writeTinyDataset;

std::string openError(const fs::path& folder, const DatasetOptions& options = {}) {
  return errorMessage([&] { (void)TumDataset::open(folder, options); });
}

// "<folder>/<file>:<line>: " as error messages start.
std::string at(const fs::path& folder, std::string_view file, int line) {
  return fmt::format("{}:{}: ", (folder / file).string(), line);
}

class TumDatasetTest : public ::testing::Test {
 protected:
  segslam::testing::ScopedTempDir temp_;
  fs::path folder_ = temp_.path() / "tiny";
  TinyDataset tiny_ = writeTinyDataset(folder_);
};

TEST_F(TumDatasetTest, OpensValidDatasetAndAssociatesJitteredDepth) {
  const auto dataset = TumDataset::open(folder_);
  ASSERT_EQ(dataset.size(), 4u);
  for (std::size_t i = 0; i < dataset.size(); ++i) {
    const FrameRecord& frame = dataset.frames()[i];
    EXPECT_DOUBLE_EQ(frame.timestamp, tiny_.rgb_stamps[i]);
    EXPECT_NEAR(frame.depth_timestamp, tiny_.depth_stamps[i], 1e-6);
    EXPECT_EQ(frame.rgb_path, folder_ / fmt::format("rgb/{:.6f}.png", tiny_.rgb_stamps[i]));
    EXPECT_EQ(frame.depth_path.parent_path(), folder_ / "depth");
    ASSERT_TRUE(frame.mask_path);
    EXPECT_EQ(frame.mask_path->parent_path(), folder_ / "mask");
    EXPECT_FALSE(frame.labels_path);
    EXPECT_FALSE(frame.instances_path);
  }
  EXPECT_TRUE(dataset.hasMasks());
  ASSERT_TRUE(dataset.groundTruth());
  EXPECT_EQ(dataset.groundTruth()->size(), 4u);
  EXPECT_EQ(dataset.camera().width, TinyDataset::kWidth);
  EXPECT_EQ(dataset.cameraSource(),
            "file " + (folder_ / "camera.yaml").string() + " (in the dataset folder)");
  EXPECT_EQ(dataset.folder(), folder_);
}

TEST_F(TumDatasetTest, LoadFrameConvertsDepthToMetresAndNormalisesMask) {
  const auto dataset = TumDataset::open(folder_);
  const RgbdFrame frame = dataset.loadFrame(2);
  EXPECT_DOUBLE_EQ(frame.timestamp, tiny_.rgb_stamps[2]);
  ASSERT_EQ(frame.rgb.type(), CV_8UC3);
  EXPECT_EQ(frame.rgb.size(), cv::Size(TinyDataset::kWidth, TinyDataset::kHeight));
  EXPECT_EQ(frame.rgb.at<cv::Vec3b>(0, 0), cv::Vec3b(1, 2, 3));
  EXPECT_EQ(frame.rgb.at<cv::Vec3b>(5, 5), cv::Vec3b(20, 20, 30));
  ASSERT_EQ(frame.depth.type(), CV_32FC1);
  EXPECT_EQ(frame.depth.at<float>(0, 0), 0.0f);
  EXPECT_FLOAT_EQ(frame.depth.at<float>(5, 5), 5200.0f / 5000.0f);
  ASSERT_EQ(frame.mask.type(), CV_8UC1);
  EXPECT_EQ(frame.mask.at<std::uint8_t>(3, 3), 255);
  EXPECT_EQ(frame.mask.at<std::uint8_t>(10, 10), 255);
  EXPECT_EQ(frame.mask.at<std::uint8_t>(0, 0), 0);
  EXPECT_EQ(cv::countNonZero(frame.mask), 4 * 3 + 1);
  EXPECT_TRUE(frame.labels.empty());
  EXPECT_TRUE(frame.instances.empty());
  EXPECT_THROW((void)dataset.loadFrame(4), std::out_of_range);
}

TEST_F(TumDatasetTest, ColourWithoutDepthWithinMaxDifferenceIsDropped) {
  // Depth of frame 1 moves 25 ms away from its colour image (and 8 ms from frame 2's).
  tiny_.depth_stamps[1] = tiny_.rgb_stamps[1] + 0.025;
  writeImage(folder_ / fmt::format("depth/{:.6f}.png", tiny_.depth_stamps[1]),
             testing::tinyDepth(1));
  writeText(folder_ / "depth.txt", testing::imageList(tiny_.depth_stamps, "depth"));
  fs::remove(folder_ / "mask.txt");  // every frame would need a mask; not the point here
  const auto dataset = TumDataset::open(folder_);
  const auto expected = associateTimestamps(tiny_.rgb_stamps, tiny_.depth_stamps, 0.02);
  ASSERT_EQ(dataset.size(), expected.size());
  ASSERT_EQ(dataset.size(), 3u);
  EXPECT_DOUBLE_EQ(dataset.frames()[1].timestamp, tiny_.rgb_stamps[2]);
  EXPECT_FALSE(dataset.hasMasks());

  DatasetOptions wider;
  wider.max_time_difference = 0.03;
  EXPECT_EQ(TumDataset::open(folder_, wider).size(), 4u);
}

TEST_F(TumDatasetTest, AssociationsFileDefinesTheFramesInsteadOfTheLists) {
  fs::remove(folder_ / "rgb.txt");
  fs::remove(folder_ / "depth.txt");
  writeText(folder_ / "associations.txt",
            fmt::format("# associate.py output\n{0:.6f} rgb/{0:.6f}.png {1:.6f} depth/{1:.6f}.png\n"
                        "{2:.6f} rgb/{2:.6f}.png {3:.6f} depth/{3:.6f}.png\n",
                        tiny_.rgb_stamps[0], tiny_.depth_stamps[3], tiny_.rgb_stamps[2],
                        tiny_.depth_stamps[0]));
  const auto dataset = TumDataset::open(folder_);
  ASSERT_EQ(dataset.size(), 2u);
  EXPECT_DOUBLE_EQ(dataset.frames()[0].timestamp, tiny_.rgb_stamps[0]);
  EXPECT_NEAR(dataset.frames()[0].depth_timestamp, tiny_.depth_stamps[3], 1e-6);
  EXPECT_NEAR(dataset.frames()[1].depth_timestamp, tiny_.depth_stamps[0], 1e-6);
  EXPECT_TRUE(dataset.hasMasks());
}

// The ETH3D SLAM benchmark names associate.py's output associated.txt.
TEST_F(TumDatasetTest, AssociatedTxtIsReadAsTheAssociations) {
  writeText(folder_ / "associated.txt",
            fmt::format("{0:.6f} rgb/{0:.6f}.png {1:.6f} depth/{1:.6f}.png\n", tiny_.rgb_stamps[1],
                        tiny_.depth_stamps[1]));
  const auto dataset = TumDataset::open(folder_);
  ASSERT_EQ(dataset.size(), 1u);
  EXPECT_DOUBLE_EQ(dataset.frames()[0].timestamp, tiny_.rgb_stamps[1]);

  // associations.txt, the TUM tools' name, comes first.
  writeText(folder_ / "associations.txt",
            fmt::format("{0:.6f} rgb/{0:.6f}.png {1:.6f} depth/{1:.6f}.png\n", tiny_.rgb_stamps[2],
                        tiny_.depth_stamps[2]));
  EXPECT_DOUBLE_EQ(TumDataset::open(folder_).frames()[0].timestamp, tiny_.rgb_stamps[2]);
}

// ETH3D SLAM benchmark sequences give the camera as calibration.txt: `fx fy cx cy`.
TEST_F(TumDatasetTest, Eth3dCalibrationIsTheCameraWhenTheFolderHasNoCameraYaml) {
  fs::remove(folder_ / "camera.yaml");
  writeText(folder_ / "calibration.txt", "726.21081542969 726.5 359.2048034668 202.47247314453\n");
  const auto dataset = TumDataset::open(folder_);
  EXPECT_EQ(dataset.camera().fx, 726.21081542969);
  EXPECT_EQ(dataset.camera().fy, 726.5);
  EXPECT_EQ(dataset.camera().cx, 359.2048034668);
  EXPECT_EQ(dataset.camera().cy, 202.47247314453);
  EXPECT_EQ(dataset.camera().width, TinyDataset::kWidth);
  EXPECT_EQ(dataset.camera().height, TinyDataset::kHeight);
  EXPECT_EQ(dataset.camera().depth_factor, 5000.0);
  EXPECT_FALSE(dataset.camera().hasDistortion());
  EXPECT_EQ(dataset.cameraSource(), "file " + (folder_ / "calibration.txt").string() +
                                        " (ETH3D calibration in the dataset folder)");
  EXPECT_EQ(dataset.loadFrame(0).rgb.cols, TinyDataset::kWidth);

  writeCameraYaml(folder_ / "camera.yaml", TinyDataset::camera());
  EXPECT_EQ(TumDataset::open(folder_).camera().name, "tiny");

  fs::remove(folder_ / "camera.yaml");
  writeText(folder_ / "calibration.txt", "726.2 726.5 359.2\n");
  EXPECT_EQ(openError(folder_),
            at(folder_, "calibration.txt", 1) + "expected 'fx fy cx cy' but found 3 field(s)");
  writeText(folder_ / "calibration.txt", "726.2 726.5 359.2 202.4\n1 2 3 4\n");
  EXPECT_EQ(openError(folder_), (folder_ / "calibration.txt").string() +
                                    ": expected one line 'fx fy cx cy' but found 2 line(s)");
}

TEST_F(TumDatasetTest, LabelsAndInstancesAreAttachedAndLoaded) {
  cv::Mat labels(TinyDataset::kHeight, TinyDataset::kWidth, CV_8UC1, cv::Scalar(8));
  cv::Mat instances(TinyDataset::kHeight, TinyDataset::kWidth, CV_16UC1, cv::Scalar(1000));
  for (double stamp : tiny_.rgb_stamps) {
    writeImage(folder_ / fmt::format("labels/{:.6f}.png", stamp), labels);
    writeImage(folder_ / fmt::format("instances/{:.6f}.png", stamp), instances);
  }
  writeText(folder_ / "labels.txt", testing::imageList(tiny_.rgb_stamps, "labels"));
  writeText(folder_ / "instances.txt", testing::imageList(tiny_.rgb_stamps, "instances"));
  const RgbdFrame frame = TumDataset::open(folder_).loadFrame(0);
  ASSERT_EQ(frame.labels.type(), CV_8UC1);
  EXPECT_EQ(frame.labels.at<std::uint8_t>(1, 1), 8);
  ASSERT_EQ(frame.instances.type(), CV_16UC1);
  EXPECT_EQ(frame.instances.at<std::uint16_t>(1, 1), 1000);

  const RgbdFrame bare = TumDataset::open(folder_).loadFrame(0, FrameLayers{false, false, false});
  EXPECT_FALSE(bare.rgb.empty());
  EXPECT_FALSE(bare.depth.empty());
  EXPECT_TRUE(bare.mask.empty());
  EXPECT_TRUE(bare.labels.empty());
  EXPECT_TRUE(bare.instances.empty());
}

TEST_F(TumDatasetTest, CameraPrecedenceFileThenPresetThenFolderYamlThenFolderName) {
  const fs::path named = temp_.path() / "rgbd_dataset_freiburg2_tiny";
  fs::copy(folder_, named, fs::copy_options::recursive);
  core::Camera explicit_camera = TinyDataset::camera();
  explicit_camera.fx = 400.0;
  const fs::path camera_file = temp_.path() / "explicit.yaml";
  writeCameraYaml(camera_file, explicit_camera);

  DatasetOptions options;
  options.camera_file = camera_file;
  options.camera_preset = "freiburg3";
  auto dataset = TumDataset::open(named, options);
  EXPECT_EQ(dataset.camera().fx, 400.0);
  EXPECT_EQ(dataset.cameraSource(), "file " + camera_file.string());

  options.camera_file.reset();
  dataset = TumDataset::open(named, options);
  EXPECT_EQ(dataset.camera().fx, 535.4);
  EXPECT_EQ(dataset.cameraSource(), "preset freiburg3");

  options.camera_preset.reset();
  dataset = TumDataset::open(named, options);
  EXPECT_EQ(dataset.camera().name, "tiny");
  EXPECT_TRUE(contains(dataset.cameraSource(), "(in the dataset folder)"));

  fs::remove(named / "camera.yaml");
  dataset = TumDataset::open(named, options);
  EXPECT_EQ(dataset.camera().fx, 520.908620);
  EXPECT_EQ(dataset.cameraSource(), "preset freiburg2 (from folder name)");
}

TEST_F(TumDatasetTest, UnknownPresetListsTheKnownOnes) {
  DatasetOptions options;
  options.camera_preset = "kinect";
  EXPECT_EQ(openError(folder_, options),
            "unknown camera preset 'kinect' (known: freiburg1, freiburg2, freiburg3, bonn)");
}

TEST_F(TumDatasetTest, NoCameraIsAnErrorThatSaysWhatToPass) {
  fs::remove(folder_ / "camera.yaml");
  EXPECT_EQ(openError(folder_), "cannot tell which camera recorded " + folder_.string() +
                                    ": pass --camera FILE or --camera-preset NAME");
}

TEST_F(TumDatasetTest, BadCameraYamlInFolderNamesIt) {
  writeText(folder_ / "camera.yaml", "camera:\n  preset: freiburg1\n  fx: -1\n");
  EXPECT_EQ(openError(folder_),
            (folder_ / "camera.yaml").string() + ": camera.fx and fy must be positive and finite");
}

TEST_F(TumDatasetTest, MissingOrWrongFolder) {
  EXPECT_EQ(openError(temp_.path() / "nope"),
            (temp_.path() / "nope").string() + ": dataset folder not found");
  EXPECT_EQ(openError(folder_ / "rgb.txt"), (folder_ / "rgb.txt").string() + ": is not a folder");
}

TEST_F(TumDatasetTest, MissingListsNameTheFile) {
  fs::remove(folder_ / "depth.txt");
  EXPECT_EQ(openError(folder_), (folder_ / "depth.txt").string() + ": file not found");
  fs::remove(folder_ / "rgb.txt");
  EXPECT_EQ(openError(folder_), (folder_ / "rgb.txt").string() + ": file not found");
}

TEST_F(TumDatasetTest, MalformedListLinesNameFileAndLine) {
  auto rgbListWithSecondEntry = [&](std::string_view entry) {
    return fmt::format("# images\n# timestamp filename\n{0:.6f} rgb/{0:.6f}.png\n{1}\n",
                       tiny_.rgb_stamps[0], entry);
  };
  const std::string second = at(folder_, "rgb.txt", TinyDataset::kFirstListLine + 1);
  writeText(folder_ / "rgb.txt", rgbListWithSecondEntry("1305031102.208637"));
  EXPECT_EQ(openError(folder_), second + "expected 'timestamp filename' but found 1 field(s)");
  writeText(folder_ / "rgb.txt", rgbListWithSecondEntry("1305031102.208637 rgb/a b.png"));
  EXPECT_EQ(openError(folder_), second + "expected 'timestamp filename' but found 3 field(s)");
  writeText(folder_ / "rgb.txt", rgbListWithSecondEntry("1305031102.2O8637 rgb/a.png"));
  EXPECT_EQ(openError(folder_), second + "timestamp is not a finite number: '1305031102.2O8637'");
}

// The lists are read as associate.py reads them: sorted by time, a timestamp's later line wins.
TEST_F(TumDatasetTest, UnorderedOrDuplicatedTimestampsAreReadLikeTheTumTools) {
  auto swapped = tiny_.depth_stamps;
  std::swap(swapped[1], swapped[2]);
  writeText(folder_ / "depth.txt", testing::imageList(swapped, "depth"));
  testing::CapturedLog log;
  const auto dataset = TumDataset::open(folder_);
  ASSERT_EQ(dataset.size(), 4u);
  for (std::size_t i = 0; i < dataset.size(); ++i) {
    EXPECT_NEAR(dataset.frames()[i].depth_timestamp, tiny_.depth_stamps[i], 1e-6) << i;
  }
  EXPECT_TRUE(contains(log.text(), "[warning] " +
                                       at(folder_, "depth.txt", TinyDataset::kFirstListLine + 2) +
                                       "1 timestamp out of order (first 1305031102.216637 after "));

  // Frame 1's mask line repeats frame 0's timestamp: the later line wins, and frame 1 has no mask.
  auto doubled = tiny_.rgb_stamps;
  doubled[1] = doubled[0];
  writeText(folder_ / "mask.txt", testing::imageList(doubled, "mask"));
  EXPECT_EQ(
      openError(folder_),
      (folder_ / "mask.txt").string() +
          fmt::format(": no mask within 0.02 s of frame 1 (colour timestamp {:.6f}, {})",
                      tiny_.rgb_stamps[1],
                      (folder_ / fmt::format("rgb/{:.6f}.png", tiny_.rgb_stamps[1])).string()));
  EXPECT_TRUE(contains(log.text(), "[warning] " +
                                       at(folder_, "mask.txt", TinyDataset::kFirstListLine + 1) +
                                       "1 duplicated timestamp (first 1305031102.175304)"));
}

TEST_F(TumDatasetTest, EmptySequences) {
  writeText(folder_ / "rgb.txt", "# color images\n\n");
  EXPECT_EQ(openError(folder_), (folder_ / "rgb.txt").string() + ": lists no images");

  writeText(folder_ / "rgb.txt", testing::imageList(tiny_.rgb_stamps, "rgb"));
  writeText(folder_ / "depth.txt", "");
  EXPECT_EQ(openError(folder_), (folder_ / "depth.txt").string() + ": lists no images");

  // Depth one second later than colour: nothing associates.
  std::vector<double> late;
  for (double stamp : tiny_.rgb_stamps) {
    late.push_back(stamp + 1.0);
    writeImage(folder_ / fmt::format("depth/{:.6f}.png", stamp + 1.0), testing::tinyDepth(0));
  }
  writeText(folder_ / "depth.txt", testing::imageList(late, "depth"));
  EXPECT_TRUE(contains(openError(folder_), (folder_ / "rgb.txt").string() +
                                               ": no colour image has a depth image in "
                                               "depth.txt within 0.02 s"));

  writeText(folder_ / "associations.txt", "# nothing\n");
  EXPECT_EQ(openError(folder_), (folder_ / "associations.txt").string() + ": lists no frames");
}

// Published sequences list the odd image they lack (Bonn RGB-D Dynamic): its frame is left out
// with a warning naming the image, and the rest of the sequence opens.
TEST_F(TumDatasetTest, ListedImagesThatDoNotExistLeaveTheirFramesOut) {
  const fs::path missing = folder_ / fmt::format("depth/{:.6f}.png", tiny_.depth_stamps[2]);
  fs::remove(missing);
  testing::CapturedLog log;
  const auto dataset = TumDataset::open(folder_);
  ASSERT_EQ(dataset.size(), 3u);
  EXPECT_NEAR(dataset.frames()[1].timestamp, tiny_.rgb_stamps[1], 1e-6);
  EXPECT_NEAR(dataset.frames()[2].timestamp, tiny_.rgb_stamps[3], 1e-6);
  ASSERT_EQ(dataset.absentImages().size(), 1u);
  EXPECT_EQ(dataset.absentImages()[0].path, missing);
  EXPECT_EQ(dataset.absentImages()[0].line, TinyDataset::kFirstListLine + 2);
  EXPECT_TRUE(contains(log.text(),
                       "[warning] " + at(folder_, "depth.txt", TinyDataset::kFirstListLine + 2) +
                           "listed image " + missing.string() + " does not exist: left out"));
}

// The lists are associated as written, as the TUM tools do: a colour image whose nearest depth
// image is absent is not paired with another one instead.
TEST_F(TumDatasetTest, AbsentImagesAreAssociatedAsListedThenLeftOut) {
  auto depth = tiny_.depth_stamps;
  depth.push_back(tiny_.rgb_stamps[1] + 0.019);  // a second candidate for colour frame 1
  writeImage(folder_ / fmt::format("depth/{:.6f}.png", depth.back()), testing::tinyDepth(1));
  writeText(folder_ / "depth.txt", testing::imageList(depth, "depth"));
  fs::remove(folder_ / fmt::format("depth/{:.6f}.png", tiny_.depth_stamps[1]));
  const auto dataset = TumDataset::open(folder_);
  ASSERT_EQ(dataset.size(), 3u);
  for (const auto& frame : dataset.frames()) {
    EXPECT_GT(std::abs(frame.timestamp - tiny_.rgb_stamps[1]), 1e-3);
  }
}

TEST_F(TumDatasetTest, AbsentImagesInAnAssociationListLeaveTheirFramesOut) {
  std::string associations;
  for (std::size_t i = 0; i < tiny_.rgb_stamps.size(); ++i) {
    associations += fmt::format("{0:.6f} rgb/{0:.6f}.png {1:.6f} depth/{1:.6f}.png\n",
                                tiny_.rgb_stamps[i], tiny_.depth_stamps[i]);
  }
  writeText(folder_ / "associations.txt", associations);
  fs::remove(folder_ / fmt::format("rgb/{:.6f}.png", tiny_.rgb_stamps[0]));
  const auto dataset = TumDataset::open(folder_);
  ASSERT_EQ(dataset.size(), 3u);
  EXPECT_NEAR(dataset.frames()[0].timestamp, tiny_.rgb_stamps[1], 1e-6);
  EXPECT_EQ(dataset.absentImages().size(), 1u);
}

// A list whose images are mostly absent names the wrong folder: an error naming the list, the
// line of its first absent image and that image.
TEST_F(TumDatasetTest, MostlyAbsentImagesAreAnErrorNamingTheListAndTheFirst) {
  for (int i : {1, 2, 3}) {
    fs::remove(folder_ / fmt::format("depth/{:.6f}.png", tiny_.depth_stamps[i]));
  }
  const fs::path first = folder_ / fmt::format("depth/{:.6f}.png", tiny_.depth_stamps[1]);
  EXPECT_EQ(openError(folder_), at(folder_, "depth.txt", TinyDataset::kFirstListLine + 1) +
                                    "3 of its 4 listed images do not exist, the first " +
                                    first.string());
}

// Ground-truth images (masks) are our own lists: an absent one is still an error.
TEST_F(TumDatasetTest, ListedMaskThatDoesNotExistNamesListAndLine) {
  const fs::path missing = folder_ / fmt::format("mask/{:.6f}.png", tiny_.rgb_stamps[3]);
  fs::remove(missing);
  EXPECT_EQ(openError(folder_), at(folder_, "mask.txt", TinyDataset::kFirstListLine + 3) +
                                    "listed file " + missing.string() +
                                    " does not exist (or is not a file)");
}

TEST_F(TumDatasetTest, StartingAtALaterFrameKeepsTheRestAndTheGroundTruth) {
  const auto dataset = TumDataset::open(folder_);
  const auto later = dataset.startingAt(2);
  ASSERT_EQ(later.size(), 2u);
  EXPECT_NEAR(later.frames()[0].timestamp, tiny_.rgb_stamps[2], 1e-6);
  EXPECT_EQ(later.groundTruth()->size(), dataset.groundTruth()->size());
  EXPECT_EQ(errorMessage([&] { (void)dataset.startingAt(4); }),
            folder_.string() + ": cannot start at frame 4: the sequence has 4 frames");
}

// A Bonn sequence's groundtruth.txt holds the markers' poses: the dataset gives the camera's.
TEST_F(TumDatasetTest, BonnFolderGroundTruthIsConvertedToCameraPoses) {
  const fs::path bonn = temp_.path() / "rgbd_bonn_tiny";
  fs::rename(folder_, bonn);
  const auto dataset = TumDataset::open(bonn);
  EXPECT_EQ(dataset.groundTruthFrame(), GroundTruthFrame::kBonnMarkers);
  const auto markers = readTumTrajectory(bonn / "groundtruth.txt");
  const auto expected = toCameraPoses(markers, GroundTruthFrame::kBonnMarkers);
  ASSERT_TRUE(dataset.groundTruth());
  ASSERT_EQ(dataset.groundTruth()->size(), expected.size());
  EXPECT_TRUE((*dataset.groundTruth())[2].T_wc.isApprox(expected[2].T_wc, 1e-12));
  EXPECT_FALSE((*dataset.groundTruth())[2].T_wc.isApprox(markers[2].T_wc, 1e-3));

  DatasetOptions as_camera;
  as_camera.ground_truth_frame = GroundTruthFrame::kCamera;
  EXPECT_TRUE((*TumDataset::open(bonn, as_camera).groundTruth())[2].T_wc.isApprox(markers[2].T_wc));
  EXPECT_EQ(TumDataset::open(folder_.parent_path() / "rgbd_bonn_tiny").cameraSource(),
            "file " + (bonn / "camera.yaml").string() + " (in the dataset folder)");
}

// The shared Bonn sequence opens as published: its two absent depth images left out, the Bonn
// camera from its name, and the camera poses that the dataset's transform gives.
TEST(TumDatasetRealData, BonnCrowdOpensAsPublished) {
  SEGSLAM_REQUIRE_SHARED(folder, "rgbd_bonn_crowd_300");
  const auto dataset = TumDataset::open(folder);
  EXPECT_EQ(dataset.size(), 300u);
  EXPECT_EQ(dataset.absentImages().size(), 2u);
  EXPECT_EQ(dataset.camera().name, "bonn");
  EXPECT_EQ(dataset.cameraSource(), "preset bonn (from folder name)");
  EXPECT_EQ(dataset.groundTruthFrame(), GroundTruthFrame::kBonnMarkers);
  const auto reference = readTumTrajectory(folder / "groundtruth_camera.txt");
  const auto& truth = *dataset.groundTruth();
  ASSERT_EQ(truth.size(), reference.size());
  for (std::size_t i = 0; i < truth.size(); ++i) {
    EXPECT_LT((truth[i].T_wc.translation() - reference[i].T_wc.translation()).norm(), 2e-6) << i;
    EXPECT_LT(geometry::rotationAngleAccurate(truth[i].T_wc.inverse() * reference[i].T_wc), 1e-5)
        << i;
  }
}

TEST_F(TumDatasetTest, FrameWithoutMaskNamesMaskList) {
  auto fewer = tiny_.rgb_stamps;
  fewer.erase(fewer.begin() + 2);
  writeText(folder_ / "mask.txt", testing::imageList(fewer, "mask"));
  EXPECT_EQ(
      openError(folder_),
      (folder_ / "mask.txt").string() +
          fmt::format(": no mask within 0.02 s of frame 2 (colour timestamp {:.6f}, {})",
                      tiny_.rgb_stamps[2],
                      (folder_ / fmt::format("rgb/{:.6f}.png", tiny_.rgb_stamps[2])).string()));
}

TEST_F(TumDatasetTest, MalformedGroundTruthNamesFileAndLine) {
  writeText(folder_ / "groundtruth.txt", "# gt\n1.0 0 0 0 0 0 0 1\n2.0 0 0 0 0 0 0\n");
  EXPECT_EQ(openError(folder_),
            at(folder_, "groundtruth.txt", 3) +
                "expected 'timestamp tx ty tz qx qy qz qw' but found 7 field(s)");
}

TEST_F(TumDatasetTest, MalformedAssociationsNameFileAndLine) {
  writeText(folder_ / "associations.txt", "1.0 rgb/a.png 1.01\n");
  EXPECT_TRUE(contains(openError(folder_), at(folder_, "associations.txt", 1) + "expected"));
}

TEST_F(TumDatasetTest, NonPositiveMaxTimeDifferenceIsRejected) {
  DatasetOptions options;
  options.max_time_difference = 0.0;
  EXPECT_TRUE(contains(openError(folder_, options), "maximum time difference must be positive"));
}

TEST_F(TumDatasetTest, LoadFrameErrorsNameTheImageFile) {
  const auto dataset = TumDataset::open(folder_);
  const fs::path depth = dataset.frames()[1].depth_path;
  writeImage(depth, cv::Mat(TinyDataset::kHeight, TinyDataset::kWidth, CV_8UC3, cv::Scalar(1)));
  EXPECT_EQ(errorMessage([&] { (void)dataset.loadFrame(1); }),
            depth.string() + ": depth image must be 16-bit 1-channel but is 8-bit 3-channel");

  const fs::path mask = *dataset.frames()[0].mask_path;
  writeImage(mask, cv::Mat::zeros(TinyDataset::kHeight + 1, TinyDataset::kWidth, CV_8UC1));
  EXPECT_EQ(errorMessage([&] { (void)dataset.loadFrame(0); }),
            mask.string() + ": mask is 16x13 but the colour image is 16x12");

  const fs::path rgb = dataset.frames()[2].rgb_path;
  writeText(rgb, "not a png");
  EXPECT_TRUE(contains(errorMessage([&] { (void)dataset.loadFrame(2); }),
                       rgb.string() + ": cannot decode the image"));
}

TEST_F(TumDatasetTest, DamagedImagesThrowDamagedImageErrorNamingTheFile) {
  const auto dataset = TumDataset::open(folder_);
  const fs::path depth = dataset.frames()[1].depth_path;
  fs::resize_file(depth, fs::file_size(depth) / 2);
  try {
    (void)dataset.loadFrame(1);
    FAIL() << "expected a DamagedImageError";
  } catch (const DamagedImageError& e) {
    EXPECT_EQ(std::string(e.what()), depth.string() +
                                         ": damaged image: the PNG data stops before its IEND "
                                         "chunk: the file is truncated");
  }
  EXPECT_NO_THROW((void)dataset.loadFrame(0));
}

TEST(TumDatasetRealData, Fr1Xyz300OpensWithFreiburg1CameraAndGroundTruth) {
  SEGSLAM_REQUIRE_SHARED(dir, "tum_fr1_xyz_300");
  const auto start = std::chrono::steady_clock::now();
  const auto dataset = TumDataset::open(dir);
  const double open_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(open_seconds, 1.0) << "open() must not decode images";
  EXPECT_EQ(dataset.camera().name, "freiburg1");
  EXPECT_DOUBLE_EQ(dataset.camera().fx, 517.306408);
  EXPECT_EQ(dataset.cameraSource(), "preset freiburg1 (from folder name)");
  // 300 colour and 301 depth images; the TUM association (associate.py, 0.02 s) pairs 294: the
  // colour images 2, 11, 14, 23, 31 and 105 lose their nearest depth image to a closer one.
  ASSERT_EQ(dataset.size(), 294u);
  EXPECT_DOUBLE_EQ(dataset.frames().front().timestamp, 1305031102.175304);
  EXPECT_DOUBLE_EQ(dataset.frames().front().depth_timestamp, 1305031102.160407);
  EXPECT_DOUBLE_EQ(dataset.frames()[2].timestamp, 1305031102.275326);
  EXPECT_DOUBLE_EQ(dataset.frames().back().timestamp, 1305031112.144342);
  ASSERT_TRUE(dataset.groundTruth());
  EXPECT_EQ(dataset.groundTruth()->size(), 1187u);
  EXPECT_FALSE(dataset.hasMasks());

  const RgbdFrame frame = dataset.loadFrame(0);
  EXPECT_EQ(frame.rgb.type(), CV_8UC3);
  EXPECT_EQ(frame.rgb.size(), cv::Size(640, 480));
  ASSERT_EQ(frame.depth.type(), CV_32FC1);
  EXPECT_EQ(frame.depth.size(), cv::Size(640, 480));
  const cv::Mat valid = frame.depth > 0.0f;
  EXPECT_GT(cv::countNonZero(valid), 640 * 480 / 2);
  double min_m = 0.0;
  double max_m = 0.0;
  cv::minMaxLoc(frame.depth, &min_m, &max_m, nullptr, nullptr, valid);
  EXPECT_GT(min_m, 0.4);
  EXPECT_LT(max_m, 5.0);
  EXPECT_NEAR(cv::mean(frame.depth, valid)[0], 1.5, 1.0);
}

TEST(TumDatasetRealData, WalkerHasBinaryMasksWithThePersonInThem) {
  SEGSLAM_REQUIRE_SHARED(dir, "tum_fr1_xyz_300_walker");
  const auto dataset = TumDataset::open(dir);
  EXPECT_EQ(dataset.camera().name, "freiburg1");
  ASSERT_EQ(dataset.size(), 294u);
  ASSERT_TRUE(dataset.hasMasks());
  ASSERT_TRUE(dataset.groundTruth());
  EXPECT_EQ(dataset.groundTruth()->size(), 3000u);
  const RgbdFrame frame = dataset.loadFrame(0);
  ASSERT_EQ(frame.mask.type(), CV_8UC1);
  EXPECT_GT(cv::countNonZero(frame.mask), 10000);
  const cv::Mat neither = (frame.mask != 0) & (frame.mask != 255);
  EXPECT_EQ(cv::countNonZero(neither), 0);
}

}  // namespace
}  // namespace segslam::io
