#include "segslam/loop/cnn_loop_detector.h"

#include <gtest/gtest.h>

#include "segslam/loop/loop_test_scenes.h"
#include "segslam/synth/sequence.h"
#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"

namespace segslam::loop {
namespace {

const std::filesystem::path kBackboneConfig =
    std::filesystem::path(SEGSLAM_SOURCE_DIR) / "config" / "models" / "tiny_darknet_imagenet.yaml";

std::optional<CnnLoopBackbone> sharedBackbone() {
  const auto shared = testing::sharedDir();
  if (!shared) return std::nullopt;
  const auto model = *shared / "models" / "tiny_darknet_imagenet.onnx";
  if (!std::filesystem::exists(model)) return std::nullopt;
  return CnnLoopBackbone{place::readCnnBackboneConfig(kBackboneConfig), kBackboneConfig, model};
}

TEST(CnnLoopDetector, LayerMissingFromTheConfigIsAnErrorNamingIt) {
  const CnnLoopBackbone backbone{place::readCnnBackboneConfig(kBackboneConfig), kBackboneConfig,
                                 "no_such_model.onnx"};
  CnnLoopOptions options;
  options.layer = "pool9";
  try {
    const CnnLoopDetector detector(backbone, options);
    FAIL() << "expected util::Error";
  } catch (const util::Error& e) {
    EXPECT_NE(std::string(e.what()).find("tiny_darknet_imagenet.yaml"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("pool9"), std::string::npos);
  }
}

TEST(CnnLoopDetector, MissingModelIsAnErrorNamingIt) {
  const CnnLoopBackbone backbone{place::readCnnBackboneConfig(kBackboneConfig), kBackboneConfig,
                                 "no_such_model.onnx"};
  try {
    const CnnLoopDetector detector(backbone);
    FAIL() << "expected util::Error";
  } catch (const util::Error& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_model.onnx"), std::string::npos);
  }
}

// Keyframes every 20 frames of a synthetic lap round a room (640 frames: 11.25 degrees apart),
// each covisible with its two predecessors, as the tracker would link them.
class CnnLoopDetectorOnALap : public ::testing::Test {
 protected:
  static constexpr int kStep = 20;

  CnnLoopDetectorOnALap() : sequence_(roomLapOptions()) {}

  void SetUp() override {
    backbone_ = sharedBackbone();
    if (!backbone_) {
      GTEST_SKIP() << "../shared/models/tiny_darknet_imagenet.onnx not found (set "
                      "SEGSLAM_SHARED_DIR): the CNN loop detector needs the backbone";
    }
  }

  map::KeyFrame& addKeyFrame(int frame) {
    map::Frame image(static_cast<std::uint64_t>(frame), sequence_.timestamp(frame), {}, cv::Mat(),
                     cv::Mat(), cv::Mat(), camera_);
    image.image = sequence_.renderFrame(frame).rgb;
    auto keyframe = std::make_unique<map::KeyFrame>(keyframes_.size(), image);
    for (std::size_t back = 1; back <= 2 && back <= keyframes_.size(); ++back) {
      map::KeyFrame& previous = *keyframes_[keyframes_.size() - back];
      keyframe->addConnection(&previous, 100);
      previous.addConnection(keyframe.get(), 100);
    }
    keyframes_.push_back(std::move(keyframe));
    return *keyframes_.back();
  }

  // The query's candidates after every keyframe before it was described and added, as the loop
  // closer does it.
  std::vector<std::uint64_t> candidatesOf(const map::KeyFrame& query) const {
    CnnLoopDetector detector(*backbone_);
    for (const auto& keyframe : keyframes_) {
      if (keyframe.get() == &query) continue;
      detector.describe(*keyframe);
      detector.add(*keyframe);
    }
    detector.describe(query);
    std::set<std::uint64_t> covisible = {query.id};
    for (const map::KeyFrame* k : query.covisiblesWithWeight(0)) covisible.insert(k->id);
    return detector.candidates(query, covisible, 3);
  }

  std::optional<CnnLoopBackbone> backbone_;
  synth::SyntheticSequence sequence_;
  std::shared_ptr<const map::FrameCamera> camera_ = std::make_shared<map::FrameCamera>(
      sequence_.camera(), map::kDefaultVirtualBaselineM, 40.0, feature::ScaleLevels(8, 1.2));
  std::vector<std::unique_ptr<map::KeyFrame>> keyframes_;
};

TEST_F(CnnLoopDetectorOnALap, RevisitedStartIsACandidate) {
  for (int frame = 0; frame <= 600; frame += kStep) addKeyFrame(frame);
  // 10 frames before the end: between the last keyframe and the first, seen 11 degrees apart.
  const map::KeyFrame& query = addKeyFrame(630);
  const auto found = candidatesOf(query);
  ASSERT_FALSE(found.empty());
  EXPECT_LE(found.front(), 1U);  // the lap's first keyframes
}

TEST_F(CnnLoopDetectorOnALap, PlaceSeenForTheFirstTimeHasNoCandidate) {
  for (int frame = 0; frame <= 300; frame += kStep) addKeyFrame(frame);
  const map::KeyFrame& query = addKeyFrame(320);  // half way round: new walls
  EXPECT_TRUE(candidatesOf(query).empty());
}

TEST_F(CnnLoopDetectorOnALap, KeyFramesRestoredWithTheirSavedDescriptionAreCandidates) {
  for (int frame = 0; frame <= 600; frame += kStep) addKeyFrame(frame);
  CnnLoopDetector saving(*backbone_);
  for (const auto& keyframe : keyframes_) {
    saving.describe(*keyframe);
    saving.add(*keyframe);
  }
  // A later session: the same keyframes come from a map file, without their images.
  CnnLoopDetector restored(*backbone_);
  for (const auto& keyframe : keyframes_) {
    restored.addRestored(*keyframe, saving.savedDescription(keyframe->id));
  }
  const map::KeyFrame& query = addKeyFrame(630);
  restored.describe(query);
  std::set<std::uint64_t> covisible = {query.id};
  for (const map::KeyFrame* k : query.covisiblesWithWeight(0)) covisible.insert(k->id);
  const auto found = restored.candidates(query, covisible, 3);
  ASSERT_FALSE(found.empty());
  EXPECT_LE(found.front(), 1U);
  EXPECT_EQ(found, candidatesOf(query)) << "as if the session had described them itself";
  EXPECT_TRUE(restored.savedDescription(9999).empty());
}

}  // namespace
}  // namespace segslam::loop
