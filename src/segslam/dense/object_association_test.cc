#include "segslam/dense/object_association.h"

#include <gtest/gtest.h>

#include "segslam/dense/object_test_clouds.h"

namespace segslam::dense {
namespace {

using core::SemanticClass;
using test_clouds::box;

constexpr double kCell = 0.02;

std::vector<LabelSegment> segmentsOf(const LabelledCloud& cloud) {
  return segmentByLabel(cloud, kCell, 50);
}

TEST(ObjectAssociation, ViewsOfOneObjectAreOneObjectWithAVotePerKeyFrame) {
  ObjectAssociator associator(kCell, {});
  for (std::uint64_t k = 0; k < 4; ++k) {
    // Each view a little shifted, as depth noise and pose error shift them.
    const float shift = 0.004f * static_cast<float>(k);
    associator.addKeyFrame(
        k, segmentsOf(box({shift, 0.0f, 0.0f}, {0.4f + shift, 0.3f, 0.3f}, SemanticClass::kChair)));
  }
  const auto objects = associator.objects();
  ASSERT_EQ(objects.size(), 1u);
  EXPECT_EQ(objects[0].label(), static_cast<std::uint8_t>(SemanticClass::kChair));
  EXPECT_EQ(objects[0].keyframes, (std::vector<std::uint64_t>{0, 1, 2, 3}));
  EXPECT_DOUBLE_EQ(objects[0].confidence(), 1.0);
  EXPECT_NEAR(objects[0].centroid().x(), 0.206f, 0.01f);
}

TEST(ObjectAssociation, AViewSpanningTwoFragmentsMergesThem) {
  ObjectAssociator associator(kCell, {});
  // Two keyframes see either end of a long table, a third sees all of it.
  associator.addKeyFrame(
      0, segmentsOf(box({0.0f, 0.0f, 0.0f}, {0.5f, 0.05f, 0.4f}, SemanticClass::kTable)));
  associator.addKeyFrame(
      1, segmentsOf(box({1.0f, 0.0f, 0.0f}, {1.5f, 0.05f, 0.4f}, SemanticClass::kTable)));
  ASSERT_EQ(associator.objects().size(), 2u);
  associator.addKeyFrame(
      2, segmentsOf(box({0.0f, 0.0f, 0.0f}, {1.5f, 0.05f, 0.4f}, SemanticClass::kTable)));
  const auto objects = associator.objects();
  ASSERT_EQ(objects.size(), 1u);
  EXPECT_EQ(objects[0].keyframes, (std::vector<std::uint64_t>{0, 1, 2}));
  EXPECT_EQ(objects[0].label_votes.at(static_cast<std::uint8_t>(SemanticClass::kTable)), 3);
}

TEST(ObjectAssociation, AMislabelledViewVotesForAnotherLabelOfTheSameObject) {
  ObjectAssociator associator(kCell, {});
  const Eigen::Vector3f min(0.0f, 0.0f, 0.0f);
  const Eigen::Vector3f max(0.8f, 0.4f, 0.4f);
  associator.addKeyFrame(0, segmentsOf(box(min, max, SemanticClass::kSofa)));
  associator.addKeyFrame(1, segmentsOf(box(min, max, SemanticClass::kChair)));
  associator.addKeyFrame(2, segmentsOf(box(min, max, SemanticClass::kSofa)));
  const auto objects = associator.objects();
  ASSERT_EQ(objects.size(), 1u);
  EXPECT_EQ(objects[0].label(), static_cast<std::uint8_t>(SemanticClass::kSofa));
  EXPECT_NEAR(objects[0].confidence(), 2.0 / 3.0, 1e-9);
}

TEST(ObjectAssociation, InstanceIdsDecideWhereTheSegmentationTracksInstances) {
  ObjectAssociator associator(kCell, {});
  for (std::uint64_t k = 0; k < 3; ++k) {
    // A monitor's screen and its foot, never seen joined, share the id 4; a box touching the
    // screen has its own.
    LabelledCloud view = box({0.0f, 0.0f, 0.0f}, {0.5f, 0.3f, 0.05f}, SemanticClass::kMonitor, 4);
    view.append(box({0.2f, 0.5f, 0.0f}, {0.3f, 0.6f, 0.1f}, SemanticClass::kMonitor, 4));
    view.append(box({0.5f, 0.0f, 0.0f}, {0.7f, 0.3f, 0.2f}, SemanticClass::kMonitor, 5));
    associator.addKeyFrame(k, segmentsOf(view));
  }
  const auto objects = associator.objects();
  ASSERT_EQ(objects.size(), 2u);
  EXPECT_EQ(objects[0].instance, 4);
  EXPECT_EQ(objects[0].keyframes.size(), 3u);
  EXPECT_EQ(objects[1].instance, 5);
}

TEST(ObjectAssociation, NeighboursOfOtherLabelsStaySeparate) {
  ObjectAssociator associator(kCell, {});
  for (std::uint64_t k = 0; k < 3; ++k) {
    LabelledCloud view = box({0.0f, 0.0f, 0.0f}, {1.2f, 0.05f, 0.8f}, SemanticClass::kTable);
    view.append(box({0.4f, -0.4f, 0.3f}, {0.8f, 0.0f, 0.35f}, SemanticClass::kMonitor));
    associator.addKeyFrame(k, segmentsOf(view));
  }
  const auto objects = associator.objects();
  ASSERT_EQ(objects.size(), 2u);
  EXPECT_NE(objects[0].label(), objects[1].label());
  EXPECT_EQ(objects[0].keyframes.size(), 3u);
  EXPECT_EQ(objects[1].keyframes.size(), 3u);
}

}  // namespace
}  // namespace segslam::dense
