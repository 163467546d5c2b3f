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

FrameMaskScores frameScores(bool truth_dynamic, std::int64_t tp, std::int64_t fp, std::int64_t fn) {
  FrameMaskScores frame;
  frame.truth_dynamic = truth_dynamic;
  frame.scores = {.true_positive = tp, .false_positive = fp, .false_negative = fn};
  return frame;
}

// A frame showing a large object found well, one showing a sliver missed, one showing nothing
// with a false alarm: per-frame means weigh the sliver like the large object, pooled pixels do
// not, and only the pooled scores over all frames count the false alarm.
TEST(SummariseMaskScores, MeansPerFramePooledPixelsAndPooledPixelsWhereSomethingMoves) {
  const auto summary = summariseMaskScores(
      {frameScores(true, 90, 10, 0), frameScores(true, 0, 0, 10), frameScores(false, 0, 100, 0)});
  EXPECT_EQ(summary.frames.size(), 3U);
  EXPECT_EQ(summary.frames_with_dynamic, 2U);
  EXPECT_DOUBLE_EQ(summary.mean_iou, (0.9 + 0.0) / 2.0);
  EXPECT_DOUBLE_EQ(summary.total_where_dynamic.iou(), 90.0 / 110.0);
  EXPECT_DOUBLE_EQ(summary.total.iou(), 90.0 / 210.0);
  EXPECT_DOUBLE_EQ(summary.mean_recall, 0.5);
  EXPECT_DOUBLE_EQ(summary.total_where_dynamic.recall(), 0.9);
}

TEST(SummariseMaskScores, NoFrameWithSomethingMovingLeavesTheMeansAtZero) {
  const auto summary = summariseMaskScores({frameScores(false, 0, 5, 0)});
  EXPECT_EQ(summary.frames_with_dynamic, 0U);
  EXPECT_DOUBLE_EQ(summary.mean_iou, 0.0);
  EXPECT_DOUBLE_EQ(summary.total.precision(), 0.0);
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
