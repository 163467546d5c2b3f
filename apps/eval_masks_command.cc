#include <fmt/format.h>

#include <memory>

#include "commands.h"
#include "dataset_arguments.h"
#include "mask_arguments.h"
#include "segslam/system/mask_evaluation.h"
#include "segslam/util/output_folder.h"
#include "segslam/util/progress.h"

namespace segslam::apps {

namespace {

struct EvalMasksOptions : DatasetArguments {
  MaskArguments masks;
  system::MaskEvaluationOptions evaluation;
};

void printSummary(const EvalMasksOptions& options, const system::MaskEvaluationSummary& s) {
  fmt::print("\nsegslam eval masks: {} (masks: {})\n", options.dataset.string(),
             options.masks.source);
  fmt::print("  frames           {} ({} with dynamic pixels in mask.txt)\n", s.frames.size(),
             s.frames_with_dynamic);
  fmt::print("  per frame (mean) IoU {:.3f}, precision {:.3f}, recall {:.3f}\n", s.mean_iou,
             s.mean_precision, s.mean_recall);
  fmt::print("  all pixels       IoU {:.3f}, precision {:.3f}, recall {:.3f}\n", s.total.iou(),
             s.total.precision(), s.total.recall());
  fmt::print(
      "  pixels of frames with dynamic pixels: IoU {:.3f}, precision {:.3f}, recall {:.3f}\n",
      s.total_where_dynamic.iou(), s.total_where_dynamic.precision(),
      s.total_where_dynamic.recall());
  fmt::print("  keypoints on moving objects: {} without a mask, {} with it ({:.1f} % survive)\n",
             s.survival.on_dynamic_without_mask, s.survival.on_dynamic_with_mask,
             100.0 * s.survival.survivingShare());
  fmt::print("  outputs          {}\n", std::filesystem::absolute(options.out_dir).string());
}

}  // namespace

void registerEvalMasksCommand(CLI::App& eval) {
  auto options = std::make_shared<EvalMasksOptions>();
  auto* command = eval.add_subcommand(
      "masks",
      "Score dynamic masks against a dataset's ground truth (mask.txt): per-frame and mean IoU, "
      "precision, recall, and the share of keypoints on moving objects that survive the mask");
  addDatasetOptions(*command, *options);
  addMaskOptions(*command, options->masks);
  command
      ->add_option("--mask-dilation", options->evaluation.mask_dilation_px,
                   "Dilation of the predicted mask before keypoint extraction (pixels)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  command->add_flag("--write-masks", options->evaluation.write_masks,
                    "Also write the predicted masks (masks/<timestamp>.png and mask.txt, the "
                    "layout of a dataset's ground-truth masks)");
  command
      ->add_option("--ignore-masks", options->evaluation.ignore_masks,
                   "Mask list (timestamp path) of pixels not to score where the ground truth is "
                   "static, e.g. real people the ground truth does not mark")
      ->check(CLI::ExistingFile);
  command->add_flag(
      "--deterministic", options->evaluation.synchronous,
      "Run the network on the calling thread (every --network-interval frames): reproducible");
  command
      ->add_option("--max-frames", options->evaluation.max_frames,
                   "Evaluate at most this many frames")
      ->check(CLI::PositiveNumber);
  command->callback([options] {
    if (options->out_dir.empty()) options->out_dir = defaultOutDir(options->dataset, "masks");
    options->evaluation.masks = maskSourceOptions(options->masks);
    const auto dataset = openDataset(*options);
    util::createOutputFolder(options->out_dir);
    util::ProgressBar progress("masks", std::min(options->evaluation.max_frames, dataset.size()));
    const auto summary = system::evaluateMasks(dataset, options->evaluation, options->out_dir,
                                               [&] { progress.advance(); });
    progress.finish();
    printSummary(*options, summary);
  });
}

}  // namespace segslam::apps
