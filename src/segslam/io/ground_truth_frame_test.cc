#include "segslam/io/ground_truth_frame.h"

#include <gtest/gtest.h>

#include "segslam/geometry/angles.h"
#include "segslam/geometry/pose.h"
#include "segslam/util/error.h"

namespace segslam::io {
namespace {

TEST(GroundTruthFrame, NamesRoundTripAndUnknownOnesAreErrors) {
  for (const auto& name : groundTruthFrameNames()) {
    EXPECT_EQ(groundTruthFrameName(requireGroundTruthFrame(name)), name);
  }
  EXPECT_FALSE(parseGroundTruthFrame("auto"));
  try {
    (void)requireGroundTruthFrame("markers");
    ADD_FAILURE() << "expected a util::Error";
  } catch (const util::Error& e) {
    EXPECT_STREQ(e.what(), "unknown ground truth frame 'markers' (known: camera, bonn-markers)");
  }
}

TEST(GroundTruthFrame, BonnFoldersPublishMarkerPoses) {
  EXPECT_EQ(groundTruthFrameForDataset("/data/rgbd_bonn_crowd"), GroundTruthFrame::kBonnMarkers);
  EXPECT_EQ(groundTruthFrameForDataset("/data/rgbd_bonn_person_tracking2/"),
            GroundTruthFrame::kBonnMarkers);
  EXPECT_EQ(groundTruthFrameForDataset("/data/rgbd_dataset_freiburg3_walking_xyz"),
            GroundTruthFrame::kCamera);
}

TEST(GroundTruthFrame, CameraPosesAreKept) {
  core::Trajectory trajectory;
  trajectory.append(1.0, geometry::poseFromTranslationQuaternion({1, 2, 3}, {0.9, 0.1, 0.2, 0.3}));
  const auto kept = toCameraPoses(trajectory, GroundTruthFrame::kCamera);
  EXPECT_TRUE(kept[0].T_wc.isApprox(trajectory[0].T_wc));
}

// The dataset's transform T_ros * T_gt * T_ros * T_m: for an identity marker pose the camera pose
// is T_ros * T_ros * T_m = T_m (T_ros is its own inverse); a marker translation t moves the camera
// by T_ros t (x turned around, y and z swapped); the result is a rotation.
TEST(GroundTruthFrame, BonnMarkerPosesBecomeCameraPosesByTheDatasetTransform) {
  core::Trajectory markers;
  markers.append(1.0, geometry::Pose::Identity());
  geometry::Pose moved = geometry::Pose::Identity();
  moved.translation() << 1.0, 2.0, 3.0;
  markers.append(2.0, moved);
  const auto camera = toCameraPoses(markers, GroundTruthFrame::kBonnMarkers);
  ASSERT_EQ(camera.size(), 2u);
  EXPECT_NEAR(camera[0].timestamp, 1.0, 0.0);
  EXPECT_TRUE(camera[0].T_wc.translation().isApprox(Eigen::Vector3d(0.0113, -0.0098, 0.0111)));
  const Eigen::Matrix3d rotation = camera[0].T_wc.linear();
  EXPECT_TRUE((rotation * rotation.transpose()).isApprox(Eigen::Matrix3d::Identity(), 1e-12));
  EXPECT_NEAR(rotation.determinant(), 1.0, 1e-12);
  const Eigen::Vector3d shift = camera[1].T_wc.translation() - camera[0].T_wc.translation();
  EXPECT_TRUE(shift.isApprox(Eigen::Vector3d(-1.0, 3.0, 2.0), 1e-12));
}

}  // namespace
}  // namespace segslam::io
