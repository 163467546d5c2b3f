#include "segslam/dense/label_segments.h"

#include <gtest/gtest.h>

#include "segslam/dense/object_test_clouds.h"

namespace segslam::dense {
namespace {

using core::SemanticClass;
using test_clouds::addBox;

TEST(LabelSegments, TouchingPointsOfOneLabelAreOneSegment) {
  LabelledCloud cloud;
  addBox(cloud, {0.0f, 0.0f, 0.0f}, {0.2f, 0.2f, 0.2f}, SemanticClass::kBox, 3);
  addBox(cloud, {0.5f, 0.0f, 0.0f}, {0.7f, 0.2f, 0.2f}, SemanticClass::kBox);
  addBox(cloud, {0.21f, 0.0f, 0.0f}, {0.4f, 0.2f, 0.2f}, SemanticClass::kChair);
  const auto segments = segmentByLabel(cloud, 0.02, 50);
  ASSERT_EQ(segments.size(), 3u);
  EXPECT_EQ(segments[0].label, static_cast<std::uint8_t>(SemanticClass::kChair));
  EXPECT_EQ(segments[1].label, static_cast<std::uint8_t>(SemanticClass::kBox));
  EXPECT_EQ(segments[1].instance, 0);
  EXPECT_EQ(segments[2].instance, 3);
  EXPECT_NEAR(segments[1].centroid.x(), 0.6f, 1e-3f);
  EXPECT_NEAR(segments[2].centroid.x(), 0.1f, 1e-3f);
  EXPECT_TRUE(std::is_sorted(segments[1].cells.begin(), segments[1].cells.end()));
  EXPECT_EQ(segments[0].indices.size() + segments[1].indices.size() + segments[2].indices.size(),
            cloud.size());
}

TEST(LabelSegments, TouchingObjectsOfOneLabelWithTheirOwnInstanceIdsStayApart) {
  LabelledCloud cloud;
  addBox(cloud, {0.0f, 0.0f, 0.0f}, {0.2f, 0.2f, 0.2f}, SemanticClass::kBox, 1);
  addBox(cloud, {0.2f, 0.0f, 0.0f}, {0.4f, 0.2f, 0.2f}, SemanticClass::kBox, 2);
  EXPECT_EQ(segmentByLabel(cloud, 0.02, 50).size(), 2u);
  for (auto& instance : cloud.instances) instance = 0;
  EXPECT_EQ(segmentByLabel(cloud, 0.02, 50).size(), 1u);
}

TEST(LabelSegments, TheRoomAndStrayLabelsAreNoSegments) {
  LabelledCloud cloud;
  addBox(cloud, {0.0f, 0.0f, 0.0f}, {0.3f, 0.3f, 0.3f}, SemanticClass::kWall);
  addBox(cloud, {1.0f, 0.0f, 0.0f}, {1.3f, 0.3f, 0.3f}, SemanticClass::kNone);
  addBox(cloud, {2.0f, 0.0f, 0.0f}, {2.02f, 0.02f, 0.02f}, SemanticClass::kChair);
  EXPECT_TRUE(segmentByLabel(cloud, 0.02, 50).empty());
  EXPECT_FALSE(isObjectLabel(static_cast<std::uint8_t>(SemanticClass::kFloor)));
  EXPECT_TRUE(isObjectLabel(static_cast<std::uint8_t>(SemanticClass::kPerson)));
}

}  // namespace
}  // namespace segslam::dense
