#include "segslam/loop/pose_graph.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace segslam::loop {
namespace {

// A camera walking once around a circle of radius 2 m, looking outwards, in 40 steps.
std::vector<geometry::Pose> circleTruth(int steps) {
  std::vector<geometry::Pose> T_cw;
  for (int k = 0; k < steps; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / steps;
    geometry::Pose T_wc = geometry::Pose::Identity();
    T_wc.linear() = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY()).toRotationMatrix();
    T_wc.translation() =
        Eigen::Vector3d(2.0 * std::sin(angle), 0.1 * std::sin(3 * angle), 2.0 * std::cos(angle));
    T_cw.push_back(T_wc.inverse());
  }
  return T_cw;
}

geometry::Pose relative(const geometry::Pose& T_from_w, const geometry::Pose& T_to_w) {
  return T_from_w * T_to_w.inverse();
}

double maxPositionError(const PoseGraph& graph, const std::vector<geometry::Pose>& truth) {
  double worst = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const Eigen::Vector3d estimated = graph.nodes[i].T_cw.inverse().translation();
    worst = std::max(worst, (estimated - truth[i].inverse().translation()).norm());
  }
  return worst;
}

// Odometry with a systematic bias (every step turns 0.4 degrees too far and moves 1 cm too far
// sideways), chained from the first pose, plus one exact loop edge between the last and the first.
PoseGraph driftingLoop(const std::vector<geometry::Pose>& truth) {
  geometry::Pose bias = geometry::Pose::Identity();
  bias.linear() = Eigen::AngleAxisd(0.4 * std::numbers::pi / 180.0, Eigen::Vector3d::UnitY())
                      .toRotationMatrix();
  bias.translation() = Eigen::Vector3d(0.01, 0.0, 0.0);
  PoseGraph graph;
  graph.nodes.push_back({0, truth[0], true});
  for (std::size_t i = 1; i < truth.size(); ++i) {
    // T_{i-1,i}: maps camera i into camera i-1; the biased measurement is what tracking reports.
    const geometry::Pose measured = relative(truth[i - 1], truth[i]) * bias;
    graph.nodes.push_back({i, measured.inverse() * graph.nodes[i - 1].T_cw, false});
    graph.edges.push_back({i - 1, i, measured, 1.0});
  }
  graph.edges.push_back({truth.size() - 1, 0, relative(truth.back(), truth.front()), 1.0});
  return graph;
}

TEST(PoseGraph, LoopEdgeRemovesAccumulatedDrift) {
  const auto truth = circleTruth(40);
  PoseGraph graph = driftingLoop(truth);
  const double drift_before = maxPositionError(graph, truth);
  ASSERT_GT(drift_before, 0.3);
  optimisePoseGraph(graph);
  const double error_after = maxPositionError(graph, truth);
  // A biased odometry is consistently wrong everywhere, so the least-squares optimum spreads the
  // loop's error over the lap instead of removing it (0.12 m left of 0.54 m).
  EXPECT_LT(error_after, 0.3 * drift_before);
  EXPECT_TRUE(graph.nodes[0].T_cw.isApprox(truth[0], 1e-12));
}

TEST(PoseGraph, ConsistentEdgesLeaveThePosesAlone) {
  const auto truth = circleTruth(12);
  PoseGraph graph;
  for (std::size_t i = 0; i < truth.size(); ++i) graph.nodes.push_back({i, truth[i], i == 0});
  for (std::size_t i = 1; i < truth.size(); ++i) {
    graph.edges.push_back({i - 1, i, relative(truth[i - 1], truth[i]), 1.0});
  }
  optimisePoseGraph(graph);
  EXPECT_LT(maxPositionError(graph, truth), 1e-9);
}

TEST(PoseGraph, RejectsEdgesToMissingNodes) {
  PoseGraph graph;
  graph.nodes.push_back({0, geometry::Pose::Identity(), true});
  graph.edges.push_back({0, 3, geometry::Pose::Identity(), 1.0});
  EXPECT_THROW(optimisePoseGraph(graph), std::invalid_argument);
}

}  // namespace
}  // namespace segslam::loop
