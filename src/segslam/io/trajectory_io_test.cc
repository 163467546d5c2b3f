#include "segslam/io/trajectory_io.h"

#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "segslam/geometry/pose.h"
#include "segslam/io/io_test_support.h"
#include "segslam/testing/test_support.h"
#include "segslam/util/text_file.h"

namespace segslam::io {
namespace {

using testing::errorMessage;

std::string parseError(std::string_view text) {
  return errorMessage([&] { (void)parseTumTrajectory(text, "d/gt.txt"); });
}

core::Trajectory randomTrajectory(std::size_t size) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  core::Trajectory trajectory;
  for (std::size_t i = 0; i < size; ++i) {
    const Eigen::Quaterniond q(unit(rng), unit(rng), unit(rng), unit(rng));
    const Eigen::Vector3d t(3.0 * unit(rng), 3.0 * unit(rng), 3.0 * unit(rng));
    trajectory.append(1305031102.175304 + 0.033 * static_cast<double>(i),
                      geometry::poseFromTranslationQuaternion(t, q));
  }
  return trajectory;
}

TEST(TrajectoryIo, RoundTripIsSubMicrometre) {
  segslam::testing::ScopedTempDir temp;
  const auto file = temp.path() / "sub" / "traj.txt";
  const core::Trajectory written = randomTrajectory(50);
  writeTumTrajectory(file, written, "estimated by a test");
  const core::Trajectory read = readTumTrajectory(file);
  ASSERT_EQ(read.size(), written.size());
  for (std::size_t i = 0; i < read.size(); ++i) {
    EXPECT_NEAR(read[i].timestamp, written[i].timestamp, 1e-6);
    EXPECT_LT((read[i].T_wc.translation() - written[i].T_wc.translation()).norm(), 1e-6);
    EXPECT_LT(geometry::rotationAngleAccurate(read[i].T_wc.inverse() * written[i].T_wc), 1e-6);
  }
  const auto rows = util::readTextRows(file);
  EXPECT_EQ(rows.front().line, 3);  // after the header comment and the format line
}

TEST(TrajectoryIo, ParsesTextAndNormalisesQuaternions) {
  const auto trajectory = parseTumTrajectory(
      "# timestamp tx ty tz qx qy qz qw\n1.0 1 2 3 0 0 0 2\n2.5,4,5,6,0,0,1,1\n", "t.txt");
  ASSERT_EQ(trajectory.size(), 2u);
  EXPECT_EQ(trajectory[0].T_wc.translation(), Eigen::Vector3d(1, 2, 3));
  EXPECT_TRUE(trajectory[0].T_wc.linear().isIdentity(1e-12));
  EXPECT_NEAR(geometry::rotationAngleAccurate(trajectory[1].T_wc), std::numbers::pi / 2.0, 1e-12);
}

TEST(TrajectoryIo, WrongFieldCountNamesFileAndLine) {
  EXPECT_EQ(parseError("# h\n1 0 0 0 0 0 0\n"),
            "d/gt.txt:2: expected 'timestamp tx ty tz qx qy qz qw' but found 7 field(s)");
  EXPECT_EQ(parseError("1 0 0 0 0 0 0 1\n2 0 0 0 0 0 0 1 9\n"),
            "d/gt.txt:2: expected 'timestamp tx ty tz qx qy qz qw' but found 9 field(s)");
}

TEST(TrajectoryIo, BadNumbersNameFileAndLine) {
  EXPECT_EQ(parseError("1 0 0 0 0 0 0 1\n\n2 0 0x 0 0 0 0 1\n"),
            "d/gt.txt:3: ty is not a finite number: '0x'");
  EXPECT_EQ(parseError("1 0 0 0 0 nan 0 1\n"), "d/gt.txt:1: qy is not a finite number: 'nan'");
  EXPECT_EQ(parseError("1 0 0 inf 0 0 0 1\n"), "d/gt.txt:1: tz is not a finite number: 'inf'");
}

TEST(TrajectoryIo, DegenerateQuaternionsNameFileAndLine) {
  EXPECT_EQ(parseError("1 0 0 0 0 0 0 0\n"), "d/gt.txt:1: quaternion is zero");
  EXPECT_EQ(parseError("1 0 0 0 1e200 1e200 0 1\n"),
            "d/gt.txt:1: quaternion is too large to normalise");
}

// As the TUM tools read trajectories (a dict keyed by timestamp): the benchmark's own ground truth
// of rgbd_dataset_freiburg2_desk repeats timestamps (line 10863).
TEST(TrajectoryIo, DuplicatedTimestampsKeepTheLaterLine) {
  testing::CapturedLog log;
  const auto trajectory =
      parseTumTrajectory("1.5 1 0 0 0 0 0 1\n1.5 2 0 0 0 0 0 1\n2 3 0 0 0 0 0 1\n", "d/gt.txt");
  ASSERT_EQ(trajectory.size(), 2u);
  EXPECT_EQ(trajectory[0].timestamp, 1.5);
  EXPECT_EQ(trajectory[0].T_wc.translation().x(), 2.0);
  EXPECT_EQ(trajectory[1].T_wc.translation().x(), 3.0);
  EXPECT_EQ(log.text(),
            "[warning] d/gt.txt:2: 1 duplicated timestamp (first 1.5): the later line of each is "
            "used, as the TUM benchmark tools do\n");
}

TEST(TrajectoryIo, LinesOutOfOrderAreSorted) {
  testing::CapturedLog log;
  const auto trajectory = parseTumTrajectory(
      "# h\n2 2 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n3 3 0 0 0 0 0 1\n0.5 0 0 0 0 0 0 1\n", "d/gt.txt");
  ASSERT_EQ(trajectory.size(), 4u);
  EXPECT_EQ(trajectory.timestamps(), (std::vector<double>{0.5, 1, 2, 3}));
  for (std::size_t i = 1; i < trajectory.size(); ++i) {
    EXPECT_EQ(trajectory[i].T_wc.translation().x(), trajectory[i].timestamp);
  }
  EXPECT_EQ(log.text(),
            "[warning] d/gt.txt:3: 2 timestamps out of order (first 1 after 2): the lines are "
            "sorted by time, as the TUM benchmark tools do\n");
}

TEST(TrajectoryIo, ACleanFileIsReadWithoutWarning) {
  testing::CapturedLog log;
  EXPECT_EQ(parseTumTrajectory("1 0 0 0 0 0 0 1\n2 0 0 0 0 0 0 1\n", "t.txt").size(), 2u);
  EXPECT_EQ(log.text(), "");
}

TEST(TrajectoryIo, UnwritableFolderIsNamed) {
  segslam::testing::ScopedTempDir temp;
  const auto file = temp.path() / "file.txt";
  writeTumTrajectory(file, randomTrajectory(2));
  EXPECT_EQ(errorMessage([&] { writeTumTrajectory(file / "traj.txt", randomTrajectory(2)); }),
            "cannot create output folder " + file.string() + ": a file of that name is in the way");
}

TEST(TrajectoryIo, EmptyOrMissingFileIsAnError) {
  EXPECT_EQ(parseError(""), "d/gt.txt: trajectory file has no poses");
  EXPECT_EQ(parseError("# only comments\n\n"), "d/gt.txt: trajectory file has no poses");
  EXPECT_EQ(errorMessage([] { (void)readTumTrajectory("/nonexistent/gt.txt"); }),
            "/nonexistent/gt.txt: file not found");
}

}  // namespace
}  // namespace segslam::io
