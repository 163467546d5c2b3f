#include "segslam/dense/seen_through.h"

#include <gtest/gtest.h>

namespace segslam::dense {
namespace {

// 160 x 120 pixels, 100 px focal length: at 2 m it sees x in [-1.6, 1.6], y in [-1.2, 1.2].
core::Camera camera() {
  core::Camera c;
  c.width = 160;
  c.height = 120;
  c.fx = c.fy = 100.0;
  c.cx = 79.5;
  c.cy = 59.5;
  return c;
}

// Points every 2 cm on the rectangle [x0, x1] x [y0, y1] at depth z.
LabelledCloud patch(float x0, float x1, float y0, float y1, float z) {
  LabelledCloud cloud;
  for (float x = x0; x <= x1; x += 0.02f) {
    for (float y = y0; y <= y1; y += 0.02f) cloud.add({x, y, z}, {100, 100, 100});
  }
  return cloud;
}

KeyFrameCloud wallTwoMetresAway() {
  KeyFrameCloud view;
  view.static_points = patch(-1.6f, 1.6f, -1.2f, 1.2f, 2.0f);
  return view;
}

std::size_t countAt(const LabelledCloud& cloud, float z) {
  std::size_t n = 0;
  for (const auto& p : cloud.points) n += std::abs(p.z() - z) < 1e-4f ? 1 : 0;
  return n;
}

TEST(SeenThrough, WhatMovedAwayGoesTheSurfaceBehindItAndWhatWasNotLookedAtStay) {
  LabelledCloud earlier = patch(-0.1f, 0.1f, -0.1f, 0.1f, 1.0f);  // a box, moved away since
  earlier.append(patch(-1.0f, 1.0f, -1.0f, 1.0f, 2.0f));          // the wall behind it
  earlier.append(patch(4.0f, 4.2f, 0.0f, 0.2f, 2.0f));            // out of the view
  const KeyFrameCloud view = wallTwoMetresAway();
  const LabelledCloud kept =
      withoutSeenThrough(earlier, camera(), {{Eigen::Isometry3d::Identity(), &view}});
  EXPECT_EQ(countAt(kept, 1.0f), 0u);
  EXPECT_EQ(kept.size(), earlier.size() - countAt(earlier, 1.0f));
}

TEST(SeenThrough, APersonInFrontHidesButDoesNotClear) {
  KeyFrameCloud view = wallTwoMetresAway();
  view.dynamic_points = patch(-0.3f, 0.3f, -0.5f, 0.5f, 0.8f);
  const LabelledCloud box = patch(-0.1f, 0.1f, -0.1f, 0.1f, 1.0f);
  EXPECT_EQ(withoutSeenThrough(box, camera(), {{Eigen::Isometry3d::Identity(), &view}}).size(),
            box.size());
}

TEST(SeenThrough, TheViewIsPlacedByItsPose) {
  const KeyFrameCloud view = wallTwoMetresAway();
  Eigen::Isometry3d T_wc = Eigen::Isometry3d::Identity();
  T_wc.translation() = Eigen::Vector3d(10.0, 0.0, 0.0);  // the camera looks at another place
  const LabelledCloud box = patch(-0.1f, 0.1f, -0.1f, 0.1f, 1.0f);
  EXPECT_EQ(withoutSeenThrough(box, camera(), {{T_wc, &view}}).size(), box.size());
  LabelledCloud box_there = box;
  for (auto& p : box_there.points) p.x() += 10.0f;
  EXPECT_TRUE(withoutSeenThrough(box_there, camera(), {{T_wc, &view}}).empty());
}

TEST(SeenThrough, CellsWithTooFewMeasurementsTellNothing) {
  KeyFrameCloud sparse;
  sparse.static_points.add({0.0f, 0.0f, 2.0f}, {1, 1, 1});
  const FreeSpaceView view(camera(), sparse);
  EXPECT_FALSE(view.seesThrough({0.0f, 0.0f, 1.0f}));
  const FreeSpaceView dense_view(camera(), wallTwoMetresAway());
  EXPECT_TRUE(dense_view.seesThrough({0.0f, 0.0f, 1.0f}));
  EXPECT_FALSE(dense_view.seesThrough({0.0f, 0.0f, 1.98f})) << "the wall itself, seen again";
  EXPECT_FALSE(dense_view.seesThrough({0.0f, 0.0f, -1.0f})) << "behind the camera";
}

}  // namespace
}  // namespace segslam::dense
