#include "segslam/system/mask_evaluation.h"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "segslam/io/image_list.h"
#include "segslam/io/io_test_support.h"
#include "segslam/testing/test_support.h"

namespace segslam::system {
namespace {

using testing::ScopedTempDir;

MaskEvaluationOptions oracleOptions() {
  MaskEvaluationOptions options;
  options.masks.source = MaskSource::kOracle;
  options.features = 50;
  return options;
}

TEST(EvaluateMasks, OracleMasksScorePerfectlyAndCanBeWrittenAsAMaskList) {
  const ScopedTempDir temp;
  io::testing::writeTinyDataset(temp.path() / "data", 3);
  const auto dataset = io::TumDataset::open(temp.path() / "data");
  MaskEvaluationOptions options = oracleOptions();
  options.write_masks = true;
  const auto summary = evaluateMasks(dataset, options, temp.path() / "out", {});
  EXPECT_EQ(summary.frames_with_dynamic, 3u);
  EXPECT_DOUBLE_EQ(summary.mean_iou, 1.0);

  const auto written = io::readImageList(temp.path() / "out" / "mask.txt");
  ASSERT_EQ(written.size(), 3u);
  for (std::size_t i = 0; i < written.size(); ++i) {
    EXPECT_NEAR(written[i].timestamp, dataset.frames()[i].timestamp, 1e-6);
    const cv::Mat mask =
        cv::imread((temp.path() / "out" / written[i].path).string(), cv::IMREAD_GRAYSCALE);
    EXPECT_EQ(cv::countNonZero(mask != dataset.loadFrame(i).mask), 0);
  }
}

TEST(EvaluateMasks, IgnoreListWithoutTheFrameFailsNamingTheList) {
  const ScopedTempDir temp;
  io::testing::writeTinyDataset(temp.path() / "data", 2);
  const auto dataset = io::TumDataset::open(temp.path() / "data");
  io::testing::writeText(temp.path() / "ignore.txt", "1000.0 mask/none.png\n");
  MaskEvaluationOptions options = oracleOptions();
  options.ignore_masks = temp.path() / "ignore.txt";
  const std::string message =
      io::testing::errorMessage([&] { evaluateMasks(dataset, options, temp.path() / "out", {}); });
  EXPECT_TRUE(io::testing::contains(message, "ignore.txt"));
  EXPECT_TRUE(io::testing::contains(message, "no ignore mask for the frame"));
}

}  // namespace
}  // namespace segslam::system
