#include <fmt/format.h>

#include <memory>

#include "commands.h"
#include "dataset_arguments.h"
#include "segslam/place/bow_place_method.h"
#include "segslam/place/cnn_place_method.h"
#include "segslam/place/vocabulary.h"
#include "segslam/system/loop_evaluation.h"
#include "segslam/util/output_folder.h"
#include "segslam/util/progress.h"

namespace segslam::apps {

namespace {

struct EvalLoopsOptions : DatasetArguments {
  std::vector<std::string> masks;
  std::filesystem::path model_config;
  std::string model_file;
  std::filesystem::path backbone_config;
  std::string backbone_model_file;
  std::filesystem::path vocabulary;
  system::LoopEvaluationOptions evaluation;
};

void addOptions(CLI::App& command, EvalLoopsOptions& options) {
  addDatasetOptions(command, options);
  command
      .add_option("--masks", options.masks,
                  "Mask sources for the union-mask columns (several allowed): oracle (mask.txt), "
                  "semantic, geometric, fused, none; default oracle when the dataset has "
                  "mask.txt, else none")
      ->check(CLI::IsMember(system::maskSourceNames()));
  options.model_config =
      std::filesystem::path(SEGSLAM_CONFIG_DIR) / "models" / "espnetv2_voc_384.yaml";
  command
      .add_option("--model-config", options.model_config,
                  "Segmentation network description (YAML) for semantic and fused masks")
      ->capture_default_str()
      ->check(CLI::ExistingFile);
  command.add_option("--model", options.model_file,
                     "Segmentation network file (ONNX) overriding the config's");
  options.backbone_config =
      std::filesystem::path(SEGSLAM_CONFIG_DIR) / "models" / "tiny_darknet_imagenet.yaml";
  command
      .add_option("--backbone-config", options.backbone_config,
                  "CNN backbone description (YAML): network, input, layers compared")
      ->capture_default_str()
      ->check(CLI::ExistingFile);
  command.add_option("--backbone-model", options.backbone_model_file,
                     "CNN backbone file (ONNX) overriding the config's; else the config's path "
                     "or $SEGSLAM_MODEL_DIR");
  options.vocabulary = std::filesystem::path(SEGSLAM_CONFIG_DIR) / place::kDefaultVocabularyFile;
  command
      .add_option("--vocabulary", options.vocabulary,
                  "Bag-of-words vocabulary (segslam vocab train) of the bow method")
      ->capture_default_str()
      ->check(CLI::ExistingFile);
  command.add_option("--every", options.evaluation.every, "Every Nth frame is a database image")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  auto& thresholds = options.evaluation.thresholds;
  command
      .add_option("--max-translation", thresholds.max_translation_m,
                  "A loop: ground-truth poses closer than this (m)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command
      .add_option("--max-rotation", thresholds.max_rotation_deg,
                  "A loop: ground-truth rotation between the views below this (deg)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command
      .add_option("--min-gap", thresholds.min_gap_s,
                  "Pairs closer in time than this (s) are not scored")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
}

void setMaskSources(EvalLoopsOptions& options, const io::TumDataset& dataset) {
  if (options.masks.empty()) options.masks.emplace_back(dataset.hasMasks() ? "oracle" : "none");
  for (const auto& name : options.masks) {
    system::MaskSourceOptions source;
    source.source = system::maskSourceFromName(name);
    source.model_config = options.model_config;
    if (!options.model_file.empty()) source.model_file = options.model_file;
    options.evaluation.masks.push_back(source);
  }
}

std::vector<std::string> cnnNotes(const std::vector<std::shared_ptr<place::CnnFeatureBank>>& banks,
                                  const std::filesystem::path& model_file) {
  if (banks.empty() || banks.front()->size() == 0) return {};
  double wall_ms = 0.0;
  double cpu_ms = 0.0;
  std::size_t images = 0;
  for (const auto& bank : banks) {
    wall_ms += bank->meanExtractionMilliseconds() * static_cast<double>(bank->size());
    cpu_ms += bank->meanExtractionCpuMilliseconds() * static_cast<double>(bank->size());
    images += bank->size();
  }
  const auto& bank = *banks.front();
  const double count = static_cast<double>(images);
  return {fmt::format(
      "CNN backbone {} ({}), input {}x{}: extracting and storing all layers takes {:.1f} ms wall, "
      "{:.1f} ms processor time (all threads) per image (mean of {}); {} bytes stored per image "
      "(float16 maps of at most {}x{} cells and a {}x{} mask)",
      bank.config().name, model_file.filename().string(), bank.config().input_size.width,
      bank.config().input_size.height, wall_ms / count, cpu_ms / count, images,
      bank.bytesPerImage(), bank.config().stored_grid.width, bank.config().stored_grid.height,
      place::CnnFeatureBank::kMaskWidth, place::CnnFeatureBank::kMaskHeight)};
}

void run(EvalLoopsOptions& options) {
  if (options.out_dir.empty()) options.out_dir = defaultOutDir(options.dataset, "loops");
  const auto dataset = openDataset(options);
  util::createOutputFolder(options.out_dir);
  setMaskSources(options, dataset);
  const auto backbone = place::readCnnBackboneConfig(options.backbone_config);
  const auto backbone_model = place::resolveBackboneModelFile(
      backbone, options.backbone_config,
      options.backbone_model_file.empty()
          ? std::nullopt
          : std::optional<std::filesystem::path>(options.backbone_model_file));
  const auto vocabulary =
      std::make_shared<const place::Vocabulary>(place::Vocabulary::load(options.vocabulary));
  std::vector<std::shared_ptr<place::CnnFeatureBank>> banks;
  const system::PlaceMethodFactory make_methods = [&] {
    banks.push_back(std::make_shared<place::CnnFeatureBank>(
        place::CnnFeatureExtractor(backbone, backbone_model)));
    auto methods = place::makeCnnPlaceMethods(banks.back());
    methods.insert(methods.begin(), std::make_unique<place::BowPlaceMethod>(
                                        vocabulary, feature::OrbExtractorOptions{},
                                        place::BowMasking::kOwnStaticArea));
    methods.insert(methods.begin(), std::make_unique<place::BowPlaceMethod>(vocabulary));
    return methods;
  };
  const std::size_t passes = std::max<std::size_t>(1, options.masks.size());
  const std::size_t images =
      (dataset.size() + options.evaluation.every - 1) / options.evaluation.every;
  util::ProgressBar progress("loops", passes * images, "images");
  const auto evaluation =
      system::evaluateLoops(dataset, options.evaluation, make_methods, [&] { progress.advance(); });
  progress.finish();
  auto notes = cnnNotes(banks, backbone_model);
  notes.insert(notes.begin(),
               "bow: ORB on the whole image; with masks, both vectors keep only the keypoints on "
               "pixels static in both images (the union mask). bow:static: with masks, each "
               "image's ORB keypoints are extracted on its own static area and the other image's "
               "mask removes nothing (the union-mask columns are then each image's own mask)");
  system::writeLoopReport(options.out_dir, evaluation, notes);
  fmt::print("\n{}\noutputs: {}\n", system::loopTableMarkdown(evaluation, notes),
             std::filesystem::absolute(options.out_dir).string());
}

}  // namespace

void registerEvalLoopsCommand(CLI::App& eval) {
  auto options = std::make_shared<EvalLoopsOptions>();
  auto* command = eval.add_subcommand(
      "loops",
      "Loop detection: precision-recall curves and their AUC (average precision) for every "
      "place-recognition method, without masks and with the union mask of each mask source, "
      "against loops from the ground-truth poses; writes loops.md, loops.json, pr_curves.svg");
  addOptions(*command, *options);
  command->callback([options] { run(*options); });
}

}  // namespace segslam::apps
