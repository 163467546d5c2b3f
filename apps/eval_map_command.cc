#include <fmt/format.h>

#include <fstream>
#include <memory>

#include "commands.h"
#include "dataset_arguments.h"
#include "segslam/system/map_evaluation.h"
#include "segslam/util/error.h"

namespace segslam::apps {

namespace {

struct EvalMapOptions : DatasetArguments {
  std::filesystem::path run_dir;
  system::MapEvaluationOptions evaluation;
};

void printOccupancyEvaluation(const system::OccupancyEvaluation& o) {
  fmt::print("  occupancy           {} occupied voxels of {:.2f} m in {}\n", o.occupied_voxels,
             o.resolution_m, o.file.string());
  if (o.on_people_share) {
    fmt::print("  occupied on people  {:.3f} % of the occupied voxels ({})\n",
               100.0 * *o.on_people_share, *o.on_people_voxels);
  }
  if (o.reference) {
    fmt::print(
        "  ghosts              {:.3f} % of the occupied voxels ({}) are free in {}; {:.3f} % "
        "({}) have no occupied voxel of it within one voxel\n",
        100.0 * *o.ghost_share, *o.ghost_voxels, o.reference->string(),
        100.0 * *o.ghost_beyond_a_voxel_share, *o.ghost_beyond_a_voxel_voxels);
    fmt::print("  kept                {:.1f} % of its {} occupied voxels occupied within a voxel\n",
               100.0 * *o.kept_share, *o.reference_occupied_voxels);
  }
}

void printEvaluation(const system::MapEvaluation& e, const system::MapEvaluationOptions& o) {
  fmt::print("segslam eval map: {} ({} points, trajectory ATE {:.4f} m)\n", e.map_file.string(),
             e.static_points, e.trajectory_ate_rmse);
  if (e.on_dynamic_share) {
    fmt::print("  on moving objects   {:.3f} % of the points ({} within {} m of them)\n",
               100.0 * *e.on_dynamic_share, *e.on_dynamic_points, o.on_dynamic_distance);
    fmt::print("  completeness        {:.1f} % of the true static surface within {} m\n",
               100.0 * *e.completeness, o.surface_distance);
    fmt::print("  accuracy            {:.1f} % of the points within {} m of it\n",
               100.0 * *e.accuracy, o.surface_distance);
  }
  if (e.near_person_path_share) {
    fmt::print(
        "  near person path    {:.3f} % of the points ({} within {} m horizontally, 0-{} m "
        "high)\n",
        100.0 * *e.near_person_path_share, *e.near_person_path_points, o.person_radius,
        o.person_height);
  }
  if (const auto& occupancy = e.occupancy) printOccupancyEvaluation(*occupancy);
}

void evalMapCommand(EvalMapOptions& options) {
  const auto dataset = openRunDataset(options, options.run_dir);
  const auto evaluation = system::evaluateMap(dataset, options.run_dir, options.evaluation);
  printEvaluation(evaluation, options.evaluation);
  const auto file = options.run_dir / "map_evaluation.json";
  std::ofstream out(file);
  out << system::toJson(evaluation, options.evaluation).dump(2) << "\n";
  if (!out) util::failAt(file, "cannot write");
  fmt::print("  outputs             {}\n", std::filesystem::absolute(file).string());
}

}  // namespace

void registerEvalMapCommand(CLI::App& eval) {
  auto options = std::make_shared<EvalMapOptions>();
  auto* command = eval.add_subcommand(
      "map",
      "Score a run's static map against the dataset's ground truth: points on moving objects, "
      "completeness and accuracy against the true static surface, points near persons_gt.txt's "
      "path");
  addRunFolderOptions(*command, *options, options->run_dir);
  auto& e = options->evaluation;
  command
      ->add_option("--on-dynamic-distance", e.on_dynamic_distance,
                   "A map point within this distance of a moving object is on it (m)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command
      ->add_option("--surface-distance", e.surface_distance,
                   "Completeness and accuracy distance (m)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command
      ->add_option("--frame-stride", e.frame_stride,
                   "Every n-th frame makes the true static surface")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command->add_option("--max-depth", e.max_depth, "Depth range of the true surface (m)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command
      ->add_option("--person-radius", e.person_radius,
                   "Horizontal distance to the person's path that counts as near (m)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command->add_option("--person-height", e.person_height, "Height of the person band (m)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command
      ->add_option("--occupancy-reference", e.occupancy_reference_run,
                   "Run folder of the same frames without people: the run's occupancy map is "
                   "scored against its map/occupancy.bt (ghosts: occupied where it is free; "
                   "kept: its occupied voxels occupied here)")
      ->check(CLI::ExistingDirectory);
  command->callback([options] { evalMapCommand(*options); });
}

}  // namespace segslam::apps
