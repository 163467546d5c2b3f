#include "segslam/system/map_session_layers.h"

#include <gtest/gtest.h>

#include "segslam/dense/ply_io.h"
#include "segslam/testing/test_support.h"

namespace segslam::system {
namespace {

TEST(MapSessionLayers, EachSessionGetsItsPointsAndKeyFrameCentres) {
  map::MapFileContents contents;
  for (std::uint32_t session : {0U, 0U, 1U}) {
    map::SavedKeyFrame keyframe;
    keyframe.id = contents.keyframes.size();
    keyframe.session = session;
    keyframe.T_cw.translation() = Eigen::Vector3d(-1.0, 0.0, static_cast<double>(session));
    contents.keyframes.push_back(keyframe);
  }
  for (std::uint32_t session : {0U, 1U, 1U, 1U}) {
    map::SavedMapPoint point;
    point.id = contents.points.size();
    point.session = session;
    point.position = Eigen::Vector3d(0.5, 0.25, 2.0);
    contents.points.push_back(point);
  }
  const testing::ScopedTempDir dir;
  const auto files = writeSessionLayers(contents, dir.path() / "map_sessions");
  ASSERT_EQ(files.size(), 4U);
  EXPECT_EQ(files[0].filename(), "session_0_points.ply");
  EXPECT_EQ(files[3].filename(), "session_1_keyframes.ply");
  EXPECT_EQ(dense::readPly(files[0]).size(), 1U);
  EXPECT_EQ(dense::readPly(files[2]).size(), 3U);
  const auto keyframes = dense::readPly(files[1]);
  ASSERT_EQ(keyframes.size(), 2U);
  EXPECT_FLOAT_EQ(keyframes.points[0].x(), 1.0f);  // the camera centre, -R^T t
  EXPECT_NE(keyframes.colours[0], dense::readPly(files[3]).colours[0]);
}

}  // namespace
}  // namespace segslam::system
