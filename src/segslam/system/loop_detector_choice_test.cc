#include "segslam/system/loop_detector_choice.h"

#include <gtest/gtest.h>

#include <fstream>

#include "segslam/place/vocabulary.h"
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

LoopDetectionRequest requestFor(const std::string& detector, const std::filesystem::path& dir) {
  LoopDetectionRequest request;
  request.detector = detector;
  request.shipped_vocabulary = dir / "shipped.vocabulary";
  request.vocabulary = request.shipped_vocabulary;
  request.backbone_config = backboneConfigNaming(dir, dir / "no.onnx");
  return request;
}

// `segslam run` and the Python System both configure loops here: the shipped vocabulary may be
// missing (no relocalisation vocabulary, bow falls back to the vote), a named one must load.
TEST(LoopDetection, TheShippedVocabularyMayBeMissingANamedOneMustLoad) {
  const testing::ScopedTempDir dir;
  SlamOptions slam;
  const auto detection = configureLoopDetection(requestFor("bow", dir.path()), slam);
  EXPECT_EQ(detection.detector, "bow");
  EXPECT_TRUE(detection.vocabulary_file.empty());
  EXPECT_EQ(slam.relocalisation_vocabulary, nullptr);
  EXPECT_EQ(slam.loop_vocabulary, nullptr);
  auto named = requestFor("bow", dir.path());
  named.vocabulary = dir.path() / "named.vocabulary";
  EXPECT_THROW(configureLoopDetection(named, slam), util::Error);
}

TEST(LoopDetection, AutoIsResolvedAndNoLoopClosingIsNone) {
  const testing::ScopedTempDir dir;
  SlamOptions slam;
  EXPECT_EQ(configureLoopDetection(requestFor("auto", dir.path()), slam).detector, "bow");
  auto off = requestFor("cnn", dir.path());
  off.loop_closing = false;
  EXPECT_EQ(configureLoopDetection(off, slam).detector, "none");
  EXPECT_FALSE(slam.loop_backbone.has_value());
  EXPECT_THROW(configureLoopDetection(requestFor("psychic", dir.path()), slam), util::Error);
}

TEST(LoopDetection, TheShippedVocabularyServesRelocalisationAndBowLoops) {
  const testing::ScopedTempDir dir;
  auto request = requestFor("bow", dir.path());
  request.shipped_vocabulary =
      std::filesystem::path(SEGSLAM_SOURCE_DIR) / "config" / place::kDefaultVocabularyFile;
  request.vocabulary = request.shipped_vocabulary;
  SlamOptions slam;
  const auto detection = configureLoopDetection(request, slam);
  EXPECT_EQ(detection.vocabulary_file, request.shipped_vocabulary);
  ASSERT_NE(slam.relocalisation_vocabulary, nullptr);
  EXPECT_EQ(slam.loop_vocabulary, slam.relocalisation_vocabulary);
  request.detector = "vote";
  SlamOptions vote;
  configureLoopDetection(request, vote);
  EXPECT_NE(vote.relocalisation_vocabulary, nullptr);
  EXPECT_EQ(vote.loop_vocabulary, nullptr);
}

}  // namespace
}  // namespace segslam::system
