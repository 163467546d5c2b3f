#include "segslam/optim/bundle_adjuster.h"

#include <ceres/loss_function.h>
#include <ceres/manifold.h>
#include <ceres/ordered_groups.h>
#include <ceres/problem.h>
#include <ceres/solver.h>

#include <Eigen/Geometry>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "segslam/optim/reprojection.h"
#include "segslam/optim/reprojection_cost.h"

namespace segslam::optim {
namespace {

// Up to this many free keyframes the Schur complement (6 columns per keyframe) is small enough
// for dense Cholesky; beyond it, as in global BA, a sparse factorisation wins.
constexpr int kMaxKeyFramesForDenseSchur = 50;
// Ceres' elimination groups: points first, so that the solver works on the Schur complement.
constexpr int kPointGroup = 0;
constexpr int kPoseGroup = 1;

class CancelCallback final : public ceres::IterationCallback {
 public:
  explicit CancelCallback(const std::atomic<bool>* cancel) : cancel_(cancel) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary&) override {
    return cancel_ != nullptr && cancel_->load() ? ceres::SOLVER_ABORT : ceres::SOLVER_CONTINUE;
  }

 private:
  const std::atomic<bool>* cancel_;
};

// A keyframe pose as the solver's parameter blocks: T_cw = [R(rotation) | translation].
struct PoseParameters {
  Eigen::Quaterniond rotation;
  Eigen::Vector3d translation;
};

void checkIndices(const BundleAdjustmentProblem& problem) {
  for (const BaObservation& observation : problem.observations) {
    if (observation.keyframe >= problem.keyframes.size() ||
        observation.point >= problem.points.size()) {
      throw std::invalid_argument("bundleAdjust: observation index out of range");
    }
  }
}

std::vector<PoseParameters> toParameters(const std::vector<BaKeyFrame>& keyframes) {
  std::vector<PoseParameters> poses;
  poses.reserve(keyframes.size());
  for (const BaKeyFrame& keyframe : keyframes) {
    poses.push_back(
        {Eigen::Quaterniond(keyframe.T_cw.linear()).normalized(), keyframe.T_cw.translation()});
  }
  return poses;
}

void writeBack(const std::vector<PoseParameters>& poses, std::vector<BaKeyFrame>& keyframes) {
  for (std::size_t i = 0; i < keyframes.size(); ++i) {
    if (keyframes[i].fixed) continue;
    keyframes[i].T_cw =
        geometry::poseFromTranslationQuaternion(poses[i].translation, poses[i].rotation);
  }
}

Eigen::Vector3d cameraPoint(const PoseParameters& pose, const Eigen::Vector3d& point_w) {
  return pose.rotation * point_w + pose.translation;
}

std::vector<bool> classify(const BundleAdjustmentProblem& problem,
                           const std::vector<PoseParameters>& poses) {
  std::vector<bool> inlier(problem.observations.size());
  for (std::size_t i = 0; i < inlier.size(); ++i) {
    const BaObservation& observation = problem.observations[i];
    const Eigen::Vector3d p_c =
        cameraPoint(poses[observation.keyframe], problem.points[observation.point].position);
    inlier[i] = isInlierObservation(problem.intrinsics, observation.observation, p_c);
  }
  return inlier;
}

// One Levenberg-Marquardt run over the observations flagged `included`.
class Stage {
 public:
  Stage(BundleAdjustmentProblem& problem, std::vector<PoseParameters>& poses)
      : problem_(problem), poses_(poses), solver_problem_(problemOptions()) {}

  void addObservations(const std::vector<bool>& included, bool robust) {
    for (std::size_t i = 0; i < problem_.observations.size(); ++i) {
      if (included[i]) addObservation(problem_.observations[i], robust);
    }
  }

  ceres::Solver::Summary solve(int iterations, int num_threads, const std::atomic<bool>* cancel) {
    ceres::Solver::Options options;
    CancelCallback cancel_callback(cancel);
    if (cancel != nullptr) options.callbacks.push_back(&cancel_callback);
    options.max_num_iterations = iterations;
    options.num_threads = num_threads;
    options.linear_solver_type = num_free_keyframes_ <= kMaxKeyFramesForDenseSchur
                                     ? ceres::DENSE_SCHUR
                                     : ceres::SPARSE_SCHUR;
    options.linear_solver_ordering = ordering_;
    options.logging_type = ceres::SILENT;
    ceres::Solver::Summary summary;
    ceres::Solve(options, &solver_problem_, &summary);
    return summary;
  }

 private:
  // The kernels and the manifold are shared by many blocks, so the stage owns them.
  static ceres::Problem::Options problemOptions() {
    ceres::Problem::Options options;
    options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    return options;
  }

  void addObservation(const BaObservation& observation, bool robust) {
    PoseParameters& pose = poses_[observation.keyframe];
    double* point = problem_.points[observation.point].position.data();
    if (!solver_problem_.HasParameterBlock(point)) ordering_->AddElementToGroup(point, kPointGroup);
    if (!solver_problem_.HasParameterBlock(pose.rotation.coeffs().data())) {
      addPose(pose, problem_.keyframes[observation.keyframe].fixed);
    }
    ceres::LossFunction* loss = nullptr;
    if (robust) loss = observation.observation.hasDepth() ? &stereo_huber_ : &mono_huber_;
    solver_problem_.AddResidualBlock(
        makeReprojectionCost(problem_.intrinsics, observation.observation).release(), loss,
        pose.rotation.coeffs().data(), pose.translation.data(), point);
  }

  void addPose(PoseParameters& pose, bool fixed) {
    double* rotation = pose.rotation.coeffs().data();
    double* translation = pose.translation.data();
    solver_problem_.AddParameterBlock(rotation, 4, &quaternion_manifold_);
    solver_problem_.AddParameterBlock(translation, 3);
    ordering_->AddElementToGroup(rotation, kPoseGroup);
    ordering_->AddElementToGroup(translation, kPoseGroup);
    if (fixed) {
      solver_problem_.SetParameterBlockConstant(rotation);
      solver_problem_.SetParameterBlockConstant(translation);
    } else {
      ++num_free_keyframes_;
    }
  }

  BundleAdjustmentProblem& problem_;
  std::vector<PoseParameters>& poses_;
  ceres::HuberLoss mono_huber_{std::sqrt(kChi2Mono)};
  ceres::HuberLoss stereo_huber_{std::sqrt(kChi2Stereo)};
  ceres::EigenQuaternionManifold quaternion_manifold_;
  std::shared_ptr<ceres::ParameterBlockOrdering> ordering_ =
      std::make_shared<ceres::ParameterBlockOrdering>();
  int num_free_keyframes_ = 0;
  ceres::Problem solver_problem_;  // last: it refers to the kernels and the manifold above
};

int iterationsOf(const ceres::Solver::Summary& summary) {
  return summary.num_successful_steps + summary.num_unsuccessful_steps;
}

// Builds, solves and frees one stage: a solver problem holds its residual blocks and Jacobians
// (5-7 MB in a global BA of 25-30 keyframes), so the two stages must not be alive together.
ceres::Solver::Summary solveStage(BundleAdjustmentProblem& problem,
                                  std::vector<PoseParameters>& poses,
                                  const std::vector<bool>& included, bool robust, int iterations,
                                  const BundleAdjustmentOptions& options) {
  Stage stage(problem, poses);
  stage.addObservations(included, robust);
  return stage.solve(iterations, options.num_threads, options.cancel);
}

}  // namespace

BundleAdjustmentResult bundleAdjust(BundleAdjustmentProblem& problem,
                                    const BundleAdjustmentOptions& options) {
  checkIndices(problem);
  std::vector<PoseParameters> poses = toParameters(problem.keyframes);
  BundleAdjustmentResult result;

  // A point behind its camera cannot be evaluated; such an observation is an outlier anyway.
  std::vector<bool> in_front(problem.observations.size());
  for (std::size_t i = 0; i < in_front.size(); ++i) {
    const BaObservation& observation = problem.observations[i];
    in_front[i] = isInFront(
        cameraPoint(poses[observation.keyframe], problem.points[observation.point].position));
  }
  const ceres::Solver::Summary first =
      solveStage(problem, poses, in_front, /*robust=*/true, options.iterations_first, options);
  result.iterations = iterationsOf(first);
  result.initial_cost = first.initial_cost;
  result.final_cost = first.final_cost;

  if (options.remove_outliers) {
    const ceres::Solver::Summary second =
        solveStage(problem, poses, classify(problem, poses), /*robust=*/false,
                   options.iterations_second, options);
    result.iterations += iterationsOf(second);
    result.final_cost = second.final_cost;
  }
  writeBack(poses, problem.keyframes);
  result.observation_inlier = classify(problem, poses);
  return result;
}

}  // namespace segslam::optim
