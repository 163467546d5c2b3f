#include "segslam/system/loop_detector_choice.h"

#include <gtest/gtest.h>

#include <fstream>

#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"

namespace segslam::system {
namespace {

const std::filesystem::path kShippedBackboneConfig =
    std::filesystem::path(SEGSLAM_SOURCE_DIR) / "config/models/tiny_darknet_imagenet.yaml";

// A backbone config like the shipped one that names `model` as its network, written into `dir`.
std::filesystem::path backboneConfigNaming(const std::filesystem::path& dir,
                                           const std::filesystem::path& model) {
  const auto file = dir / "backbone.yaml";
  testing::writeConfigNamingModel(kShippedBackboneConfig, file, model);
  return file;
}

TEST(AutomaticLoopDetector, CnnWhenTheBackboneIsFound) {
  const auto shared = testing::sharedDir();
  const auto model = shared ? *shared / "models" / "tiny_darknet_imagenet.onnx" : "";
  if (!shared || !std::filesystem::exists(model)) GTEST_SKIP() << "../shared/models not found";
  const testing::ScopedTempDir dir;
  const auto automatic = automaticLoopDetector(backboneConfigNaming(dir.path(), model), {});
  EXPECT_EQ(automatic.detector, "cnn") << automatic.reason;
  EXPECT_NE(automatic.reason.find(model.lexically_normal().string()), std::string::npos)
      << automatic.reason;
}

TEST(AutomaticLoopDetector, BagOfWordsWhenTheBackboneIsMissing) {
  const testing::ScopedTempDir dir;
  const auto automatic =
      automaticLoopDetector(backboneConfigNaming(dir.path(), dir.path() / "no.onnx"), {});
  EXPECT_EQ(automatic.detector, "bow");
  EXPECT_NE(automatic.reason.find("not found"), std::string::npos) << automatic.reason;
}

// A backbone the user names must load: a missing one fails when it is loaded, naming the file,
// rather than quietly giving bag-of-words candidates.
TEST(AutomaticLoopDetector, ANamedBackboneCountsAsFound) {
  const testing::ScopedTempDir dir;
  const auto config = backboneConfigNaming(dir.path(), dir.path() / "no.onnx");
  EXPECT_EQ(automaticLoopDetector(config, dir.path() / "named.onnx").detector, "cnn");
}

TEST(AutomaticLoopDetector, ABrokenBackboneConfigIsAnError) {
  const testing::ScopedTempDir dir;
  const auto config = dir.path() / "broken.yaml";
  std::ofstream(config) << "cnn_backbone: [unclosed\n";
  EXPECT_THROW(automaticLoopDetector(config, {}), util::Error);
}

}  // namespace
}  // namespace segslam::system
