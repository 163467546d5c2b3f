#include "segslam/dense/packed_cloud.h"

#include <gtest/gtest.h>

#include <limits>

namespace segslam::dense {
namespace {

TEST(PackedCloud, KeepsEveryPointToHalfAMillimetreWithItsColourLabelAndInstance) {
  LabelledCloud cloud;
  cloud.add({0.0F, 0.0F, 0.5F}, {1, 2, 3}, 7, 300);
  cloud.add({-1.23449F, 2.71828F, 4.99951F}, {255, 0, 128}, 15, 0);
  cloud.add({32.767F, -32.767F, 0.0004F}, {9, 9, 9}, 0, 65535);

  const PackedCloud packed(cloud);
  const LabelledCloud unpacked = packed.unpacked();

  ASSERT_EQ(packed.size(), cloud.size());
  ASSERT_EQ(unpacked.size(), cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    EXPECT_LE((unpacked.points[i] - cloud.points[i]).cwiseAbs().maxCoeff(), 0.0005F + 1e-6F);
    EXPECT_EQ(unpacked.colours[i], cloud.colours[i]);
    EXPECT_EQ(unpacked.labels[i], cloud.labels[i]);
    EXPECT_EQ(unpacked.instances[i], cloud.instances[i]);
  }
}

TEST(PackedCloud, PackingAnUnpackedCloudAgainChangesNothing) {
  LabelledCloud cloud;
  for (int i = 0; i < 1000; ++i) {
    const float x = -3.0F + 0.00613F * static_cast<float>(i);
    cloud.add({x, 0.5F * x, 2.0F + 0.25F * x}, {0, 0, 0});
  }
  const LabelledCloud once = PackedCloud(cloud).unpacked();
  const LabelledCloud twice = PackedCloud(once).unpacked();
  ASSERT_EQ(twice.size(), once.size());
  for (std::size_t i = 0; i < once.size(); ++i) EXPECT_EQ(twice.points[i], once.points[i]);
}

TEST(PackedCloud, DropsPointsOutOfRangeAndNotFinite) {
  LabelledCloud cloud;
  cloud.add({0.0F, 0.0F, 40.0F}, {0, 0, 0});
  cloud.add({std::numeric_limits<float>::quiet_NaN(), 0.0F, 1.0F}, {0, 0, 0});
  cloud.add({0.0F, 0.0F, 1.0F}, {4, 5, 6});
  const LabelledCloud unpacked = PackedCloud(cloud).unpacked();
  ASSERT_EQ(unpacked.size(), 1U);
  EXPECT_EQ(unpacked.colours[0], (Rgb{4, 5, 6}));
}

TEST(PackedKeyFrameCloud, KeepsTheThreeLayersApart) {
  KeyFrameCloud cloud;
  cloud.static_points.add({0.0F, 0.0F, 1.0F}, {1, 1, 1});
  cloud.dynamic_points.add({0.0F, 0.0F, 2.0F}, {2, 2, 2});
  cloud.dynamic_points.add({0.0F, 0.1F, 2.0F}, {2, 2, 2});
  cloud.folded_points.add({0.0F, 0.0F, 3.0F}, {3, 3, 3});
  const KeyFrameCloud unpacked = PackedKeyFrameCloud(cloud).unpacked();
  ASSERT_EQ(unpacked.static_points.size(), 1U);
  ASSERT_EQ(unpacked.dynamic_points.size(), 2U);
  ASSERT_EQ(unpacked.folded_points.size(), 1U);
  EXPECT_FLOAT_EQ(unpacked.static_points.points[0].z(), 1.0F);
  EXPECT_FLOAT_EQ(unpacked.dynamic_points.points[1].y(), 0.1F);
  EXPECT_FLOAT_EQ(unpacked.folded_points.points[0].z(), 3.0F);
}

}  // namespace
}  // namespace segslam::dense
