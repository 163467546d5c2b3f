#include "segslam/system/mask_source.h"

#include <gtest/gtest.h>

#include <fstream>

#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"

namespace segslam::system {
namespace {

MaskSourceOptions withSource(MaskSource source) {
  MaskSourceOptions options;
  options.source = source;
  options.model_config =
      std::filesystem::path(SEGSLAM_SOURCE_DIR) / "config/models/espnetv2_voc_384.yaml";
  options.model_file = *testing::sharedDir() / "models" / "espnetv2_voc_384.onnx";
  return options;
}

TEST(FrameMaskSource, FusedMasksHoldTheSemanticMaskAndWhatMovesBesideIt) {
  SEGSLAM_REQUIRE_SHARED(walker, "tum_fr1_xyz_300_walker");
  const auto dataset = io::TumDataset::open(walker);
  FrameMaskSource semantic(dataset, withSource(MaskSource::kSemantic), true);
  FrameMaskSource fused(dataset, withSource(MaskSource::kFused), true);
  // Frames 68-75: the walker comes into view, the camera moves.
  for (std::size_t i = 68; i < 76; ++i) {
    const io::RgbdFrame frame = dataset.loadFrame(i);
    const cv::Mat semantic_mask = semantic.dynamicMask(frame, i - 68);
    const cv::Mat fused_mask = fused.dynamicMask(frame, i - 68);
    ASSERT_EQ(fused_mask.size(), frame.rgb.size()) << i;
    EXPECT_EQ(cv::countNonZero(semantic_mask & ~fused_mask), 0) << i;
    EXPECT_LT(cv::countNonZero(fused_mask), 0.5 * static_cast<double>(fused_mask.total())) << i;
  }
  EXPECT_EQ(semantic.networkRuns(), fused.networkRuns());
}

TEST(FrameMaskSource, NetworkLabelsBecomeObjectLabelsOfEveryFrame) {
  SEGSLAM_REQUIRE_SHARED(fr1, "tum_fr1_xyz_300");
  const auto dataset = io::TumDataset::open(fr1);
  FrameMaskSource semantic(dataset, withSource(MaskSource::kSemantic), true);
  // Frame 0 is segmented, frames 1-2 get its labels carried over by optical flow.
  for (std::size_t i = 0; i < 3; ++i) {
    const io::RgbdFrame frame = dataset.loadFrame(i);
    const FrameMasks masks = semantic.masks(frame, i);
    ASSERT_EQ(masks.labels.type(), CV_8UC1) << i;
    ASSERT_EQ(masks.labels.size(), frame.rgb.size()) << i;
    EXPECT_TRUE(masks.instances.empty()) << i;
    double max_label = 0.0;
    cv::minMaxLoc(masks.labels, nullptr, &max_label);
    EXPECT_LE(max_label, static_cast<double>(core::SemanticClass::kPlant)) << i;
    // The desk's monitors fill a good part of the view.
    const auto monitor = static_cast<int>(core::SemanticClass::kMonitor);
    EXPECT_GT(cv::countNonZero(masks.labels == monitor), 0.01 * masks.labels.total()) << i;
  }
  EXPECT_EQ(semantic.networkRuns(), 1);
}

TEST(FrameMaskSource, OracleWithoutMaskListFailsNamingIt) {
  SEGSLAM_REQUIRE_SHARED(fr1, "tum_fr1_xyz_300");
  const auto dataset = io::TumDataset::open(fr1);
  try {
    FrameMaskSource source(dataset, withSource(MaskSource::kOracle), true);
    FAIL() << "expected a util::Error";
  } catch (const util::Error& e) {
    EXPECT_NE(std::string(e.what()).find("mask.txt"), std::string::npos) << e.what();
  }
}

const std::filesystem::path kShippedModelConfig =
    std::filesystem::path(SEGSLAM_SOURCE_DIR) / "config/models/espnetv2_voc_384.yaml";

// Mask options whose model config is like the shipped one but names `model` as its network.
MaskSourceOptions withNetworkAt(const std::filesystem::path& dir,
                                const std::filesystem::path& model) {
  MaskSourceOptions options;
  options.model_config = dir / "net.yaml";
  testing::writeConfigNamingModel(kShippedModelConfig, options.model_config, model);
  return options;
}

TEST(AutomaticMaskSource, FusedWhenTheNetworkIsFound) {
  const auto shared = testing::sharedDir();
  const auto model = shared ? *shared / "models" / "espnetv2_voc_384.onnx" : "";
  if (!shared || !std::filesystem::exists(model)) GTEST_SKIP() << "../shared/models not found";
  const testing::ScopedTempDir dir;
  const auto automatic = automaticMaskSource(withNetworkAt(dir.path(), model));
  EXPECT_EQ(automatic.source, MaskSource::kFused) << automatic.reason;
  EXPECT_NE(automatic.reason.find(model.lexically_normal().string()), std::string::npos)
      << automatic.reason;
}

TEST(AutomaticMaskSource, GeometricWhenTheNetworkIsMissing) {
  const testing::ScopedTempDir dir;
  const auto automatic = automaticMaskSource(withNetworkAt(dir.path(), dir.path() / "no.onnx"));
  EXPECT_EQ(automatic.source, MaskSource::kGeometric);
  EXPECT_NE(automatic.reason.find("not found"), std::string::npos) << automatic.reason;
}

// A network the user names must load: a missing one fails when it is loaded, naming the file,
// rather than quietly giving geometric masks.
TEST(AutomaticMaskSource, ANamedNetworkCountsAsFound) {
  const testing::ScopedTempDir dir;
  MaskSourceOptions options = withNetworkAt(dir.path(), dir.path() / "no.onnx");
  options.model_file = dir.path() / "named.onnx";
  EXPECT_EQ(automaticMaskSource(options).source, MaskSource::kFused);
}

TEST(AutomaticMaskSource, ABrokenModelConfigIsAnError) {
  const testing::ScopedTempDir dir;
  MaskSourceOptions options;
  options.model_config = dir.path() / "broken.yaml";
  std::ofstream(options.model_config) << "segmentation_model: [unclosed\n";
  EXPECT_THROW(automaticMaskSource(options), util::Error);
}

}  // namespace
}  // namespace segslam::system
