#include "segslam/dense/object_map.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "segslam/dense/object_test_clouds.h"

namespace segslam::dense {
namespace {

using core::SemanticClass;

MapObject objectOf(const std::string& label, std::size_t points, bool dynamic = false) {
  MapObject object;
  object.label = label;
  object.dynamic = dynamic;
  for (std::size_t i = 0; i < points; ++i) object.points.add(Eigen::Vector3f::Zero(), {0, 0, 0});
  return object;
}

TEST(ObjectMap, ObjectsAreNumberedPerLabelStaticFirstLargestFirst) {
  std::vector<MapObject> objects = {objectOf("person", 50, true), objectOf("box", 10),
                                    objectOf("person", 20), objectOf("box", 30),
                                    objectOf("chair", 5)};
  numberObjects(objects);
  std::vector<std::string> ids;
  for (const auto& object : objects) ids.push_back(object.id);
  // Label ids: chair 5, box 7, person 8.
  EXPECT_EQ(ids, (std::vector<std::string>{"chair_1", "box_1", "box_2", "person_1", "person_2"}));
  EXPECT_EQ(objects[1].points.size(), 30u);
  EXPECT_TRUE(objects[4].dynamic);
}

TEST(ObjectMap, ExtentGivesBoundsAndABoxAlongTheObjectsAxes) {
  MapObject object;
  object.points = test_clouds::box({0.0f, 0.0f, 0.0f}, {0.6f, 0.2f, 0.1f}, SemanticClass::kBox);
  const Eigen::Isometry3d turn(Eigen::AngleAxisd(M_PI / 6.0, Eigen::Vector3d::UnitZ()));
  object.points = transformed(object.points, turn);
  computeExtent(object);
  EXPECT_TRUE(
      object.centroid.isApprox((turn * Eigen::Vector3d(0.3, 0.1, 0.05)).cast<float>(), 1e-3f));
  // The axis-aligned bounds grow with the turn, the oriented box keeps the box's size.
  EXPECT_GT(object.bbox_max.y() - object.bbox_min.y(), 0.45f);
  Eigen::Vector3f extent = object.box.extent;
  std::sort(extent.data(), extent.data() + 3);
  EXPECT_TRUE(extent.isApprox(Eigen::Vector3f(0.1f, 0.2f, 0.6f), 1e-3f)) << extent.transpose();
  EXPECT_TRUE(object.box.centre.isApprox(object.centroid, 1e-2f));
  EXPECT_NEAR(object.box.axes.determinant(), 1.0f, 1e-4f);
}

}  // namespace
}  // namespace segslam::dense
