#include "segslam/loop/pose_graph.h"

#include <ceres/ceres.h>

#include <Eigen/Geometry>
#include <stdexcept>

namespace segslam::loop {

namespace {

// One pose as the solver sees it: world-to-camera rotation (unit quaternion) and translation.
struct PoseParameters {
  Eigen::Quaterniond q;
  Eigen::Vector3d t;
};

class RelativePoseCost {
 public:
  RelativePoseCost(const geometry::Pose& T_from_to, double weight)
      : q_measured_inverse_(Eigen::Quaterniond(T_from_to.linear()).conjugate()),
        t_measured_(T_from_to.translation()),
        sqrt_weight_(std::sqrt(weight)) {}

  template <typename T>
  bool operator()(const T* q_from_raw, const T* t_from_raw, const T* q_to_raw, const T* t_to_raw,
                  T* residual_raw) const {
    const Eigen::Map<const Eigen::Quaternion<T>> q_from(q_from_raw);
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> t_from(t_from_raw);
    const Eigen::Map<const Eigen::Quaternion<T>> q_to(q_to_raw);
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> t_to(t_to_raw);
    // T_from * T_to^-1 = [R_f R_t^T | t_f - R_f R_t^T t_t]
    const Eigen::Quaternion<T> q_estimated = q_from * q_to.conjugate();
    const Eigen::Matrix<T, 3, 1> t_estimated = t_from - q_estimated * t_to;
    const Eigen::Quaternion<T> q_error = q_measured_inverse_.template cast<T>() * q_estimated;
    Eigen::Map<Eigen::Matrix<T, 6, 1>> residual(residual_raw);
    residual.template head<3>() = t_estimated - t_measured_.template cast<T>();
    residual.template tail<3>() = T(2.0) * q_error.vec();
    residual *= T(sqrt_weight_);
    return true;
  }

 private:
  Eigen::Quaterniond q_measured_inverse_;
  Eigen::Vector3d t_measured_;
  double sqrt_weight_;
};

void checkIndices(const PoseGraph& graph) {
  for (const PoseGraphEdge& edge : graph.edges) {
    if (edge.from >= graph.nodes.size() || edge.to >= graph.nodes.size() || edge.from == edge.to) {
      throw std::invalid_argument("pose graph edge with an invalid node index");
    }
  }
}

}  // namespace

int optimisePoseGraph(PoseGraph& graph, const PoseGraphOptions& options) {
  checkIndices(graph);
  std::vector<PoseParameters> poses;
  poses.reserve(graph.nodes.size());
  for (const PoseGraphNode& node : graph.nodes) {
    poses.push_back({Eigen::Quaterniond(node.T_cw.linear()).normalized(), node.T_cw.translation()});
  }
  ceres::EigenQuaternionManifold quaternion_manifold;
  ceres::Problem::Options problem_options;
  problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  for (const PoseGraphEdge& edge : graph.edges) {
    auto* cost = new ceres::AutoDiffCostFunction<RelativePoseCost, 6, 4, 3, 4, 3>(
        new RelativePoseCost(edge.T_from_to, edge.weight));
    PoseParameters& from = poses[edge.from];
    PoseParameters& to = poses[edge.to];
    problem.AddResidualBlock(cost, nullptr, from.q.coeffs().data(), from.t.data(),
                             to.q.coeffs().data(), to.t.data());
  }
  for (std::size_t i = 0; i < poses.size(); ++i) {
    double* q = poses[i].q.coeffs().data();
    if (!problem.HasParameterBlock(q)) continue;
    problem.SetManifold(q, &quaternion_manifold);
    if (graph.nodes[i].fixed) {
      problem.SetParameterBlockConstant(q);
      problem.SetParameterBlockConstant(poses[i].t.data());
    }
  }
  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  solver_options.max_num_iterations = options.iterations;
  solver_options.num_threads = 1;
  solver_options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &problem, &summary);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    graph.nodes[i].T_cw = geometry::poseFromTranslationQuaternion(poses[i].t, poses[i].q);
  }
  return summary.num_successful_steps + summary.num_unsuccessful_steps;
}

}  // namespace segslam::loop
