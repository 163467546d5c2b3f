#include "segslam/system/loop_evaluation.h"

#include <gtest/gtest.h>

#include "segslam/io/io_test_support.h"
#include "segslam/testing/test_support.h"

namespace segslam::system {
namespace {

// Scores places by how close the images' blue levels are: in the tiny dataset the blue level
// grows with the frame index as the camera moves along x, so this scorer ranks pairs perfectly.
class BlueLevelMethod : public place::PlaceDescriptorMethod {
 public:
  [[nodiscard]] std::string name() const override { return "blue"; }
  void add(const place::PlaceImage& image) override { levels_.push_back(cv::mean(image.bgr)[0]); }
  [[nodiscard]] std::size_t size() const override { return levels_.size(); }
  [[nodiscard]] double similarity(std::size_t i, std::size_t j, bool) const override {
    return -std::abs(levels_[i] - levels_[j]);
  }

 private:
  std::vector<double> levels_;
};

TEST(LoopEvaluation, ScoresEveryMethodWithoutAndWithEachMask) {
  testing::ScopedTempDir dir;
  // 25 frames at 30 Hz, 0.1 m apart along x.
  io::testing::writeTinyDataset(dir.path() / "tiny", 25);
  const auto dataset = io::TumDataset::open(dir.path() / "tiny");
  LoopEvaluationOptions options;
  options.every = 1;
  options.thresholds = {1.25, 20.0, 0.29};  // pairs 9 to 24 frames apart; loops up to 12 apart
  MaskSourceOptions oracle;
  oracle.source = MaskSource::kOracle;
  options.masks = {oracle};
  int images = 0;
  const LoopEvaluation evaluation = evaluateLoops(
      dataset, options,
      [] {
        std::vector<std::unique_ptr<place::PlaceDescriptorMethod>> methods;
        methods.push_back(std::make_unique<BlueLevelMethod>());
        return methods;
      },
      [&] { ++images; });
  EXPECT_EQ(images, 25);
  EXPECT_EQ(evaluation.timestamps.size(), 25u);
  // Pairs k frames apart: 25 - k of them, for k = 9..24; loops for k = 9..12.
  EXPECT_EQ(evaluation.pairs.size(), 136u);
  EXPECT_EQ(evaluation.loop_pairs, 16u + 15u + 14u + 13u);
  EXPECT_EQ(evaluation.mask_columns, (std::vector<std::string>{"none", "oracle"}));
  ASSERT_EQ(evaluation.results.size(), 2u);
  for (const auto& result : evaluation.results) {
    EXPECT_EQ(result.method, "blue");
    EXPECT_DOUBLE_EQ(result.curve.average_precision, 1.0);
  }
  writeLoopReport(dir.path() / "out", evaluation, {"a note"});
  for (const char* file : {"loops.md", "loops.json", "pr_curves.svg"}) {
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "out" / file)) << file;
  }
  const std::string table = loopTableMarkdown(evaluation, {"a note"});
  EXPECT_NE(table.find("| blue | 1.000 | 1.000 |"), std::string::npos) << table;
  EXPECT_NE(table.find("- a note"), std::string::npos);
}

TEST(LoopEvaluation, NoGroundTruthLoopIsAnError) {
  testing::ScopedTempDir dir;
  io::testing::writeTinyDataset(dir.path() / "tiny", 12);
  const auto dataset = io::TumDataset::open(dir.path() / "tiny");
  LoopEvaluationOptions options;
  options.every = 1;
  options.thresholds = {0.05, 20.0, 0.1};
  EXPECT_THROW(evaluateLoops(
                   dataset, options,
                   [] { return std::vector<std::unique_ptr<place::PlaceDescriptorMethod>>{}; }, {}),
               util::Error);
}

}  // namespace
}  // namespace segslam::system
