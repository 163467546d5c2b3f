#include "segslam/dense/object_map.h"

#include <gtest/gtest.h>

#include "segslam/core/semantic_class.h"

namespace segslam::dense {
namespace {

// The surface of an axis-aligned box sampled on a 1 cm grid.
void addBox(LabelledCloud& cloud, const Eigen::Vector3f& min, const Eigen::Vector3f& max,
            core::SemanticClass label, std::uint16_t instance = 0) {
  const Eigen::Vector3i cells = ((max - min) / 0.01f).array().round().cast<int>();
  for (int i = 0; i <= cells.x(); ++i) {
    for (int j = 0; j <= cells.y(); ++j) {
      for (int k = 0; k <= cells.z(); ++k) {
        const bool on_surface =
            i == 0 || j == 0 || k == 0 || i == cells.x() || j == cells.y() || k == cells.z();
        if (!on_surface) continue;
        const Eigen::Vector3f offset = 0.01f * Eigen::Vector3f(i, j, k);
        cloud.add(i == cells.x() && j == cells.y() && k == cells.z() ? max : min + offset,
                  {1, 2, 3}, static_cast<std::uint8_t>(label), instance);
      }
    }
  }
}

TEST(ObjectMap, TwoSeparatedBoxesAreTwoInstancesWithTheirBoxes) {
  LabelledCloud cloud;
  addBox(cloud, {0.0f, 0.0f, 0.0f}, {0.4f, 0.3f, 0.2f}, core::SemanticClass::kBox);
  addBox(cloud, {1.0f, 0.0f, 0.0f}, {1.2f, 0.2f, 0.2f}, core::SemanticClass::kBox);
  addBox(cloud, {3.0f, 0.0f, 0.0f}, {3.2f, 0.2f, 0.2f}, core::SemanticClass::kChair);
  const auto objects = clusterObjects(cloud, {});
  ASSERT_EQ(objects.size(), 3u);
  // Labels in class-id order (chair = 5 before box = 7), the largest object of a label first.
  std::vector<std::string> ids;
  for (const auto& object : objects) ids.push_back(object.id);
  EXPECT_EQ(ids, (std::vector<std::string>{"chair_1", "box_1", "box_2"}));
  const MapObject& big = objects[1];
  EXPECT_EQ(big.label, "box");
  EXPECT_EQ(big.instance, 1);
  EXPECT_FALSE(big.dynamic);
  EXPECT_TRUE(big.bbox_min.isApprox(Eigen::Vector3f(0.0f, 0.0f, 0.0f), 1e-4f));
  EXPECT_TRUE(big.bbox_max.isApprox(Eigen::Vector3f(0.4f, 0.3f, 0.2f), 1e-4f));
  EXPECT_NEAR(big.centroid.x(), 0.2f, 1e-3f);
  const MapObject& small = objects[2];
  EXPECT_TRUE(small.bbox_min.isApprox(Eigen::Vector3f(1.0f, 0.0f, 0.0f), 1e-4f));
  EXPECT_TRUE(small.bbox_max.isApprox(Eigen::Vector3f(1.2f, 0.2f, 0.2f), 1e-4f));
  EXPECT_EQ(big.points.size() + small.points.size() + objects[0].points.size(), cloud.size());
}

TEST(ObjectMap, UnlabelledPointsAndSmallFragmentsAreNoObjects) {
  LabelledCloud cloud;
  addBox(cloud, {0.0f, 0.0f, 0.0f}, {0.3f, 0.3f, 0.3f}, core::SemanticClass::kNone);
  addBox(cloud, {1.0f, 0.0f, 0.0f}, {1.02f, 0.02f, 0.02f}, core::SemanticClass::kBox);
  EXPECT_TRUE(clusterObjects(cloud, {}).empty());
}

TEST(ObjectMap, DynamicObjectsFollowInstanceIdsAndNumberAfterStaticOnes) {
  LabelledCloud people;
  addBox(people, {0.0f, 0.0f, 0.0f}, {0.3f, 0.3f, 0.3f}, core::SemanticClass::kPerson, 4);
  addBox(people, {2.0f, 0.0f, 0.0f}, {2.3f, 0.3f, 0.3f}, core::SemanticClass::kPerson, 4);
  addBox(people, {5.0f, 0.0f, 0.0f}, {5.2f, 0.2f, 0.2f}, core::SemanticClass::kPerson, 9);
  auto dynamic = dynamicObjects(people, {});
  ASSERT_EQ(dynamic.size(), 2u);  // instance 4 walked: still one object
  EXPECT_TRUE(dynamic[0].dynamic);
  EXPECT_TRUE(dynamic[0].bbox_max.isApprox(Eigen::Vector3f(2.3f, 0.3f, 0.3f), 1e-4f));
  LabelledCloud statue;
  addBox(statue, {9.0f, 0.0f, 0.0f}, {9.2f, 0.2f, 0.2f}, core::SemanticClass::kPerson);
  const auto static_objects = clusterObjects(statue, {});
  numberAfter(static_objects, dynamic);
  EXPECT_EQ(static_objects[0].id, "person_1");
  EXPECT_EQ(dynamic[0].id, "person_2");
  EXPECT_EQ(dynamic[1].id, "person_3");
}

}  // namespace
}  // namespace segslam::dense
