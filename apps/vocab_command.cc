#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include "commands.h"
#include "segslam/place/vocabulary.h"
#include "segslam/place/vocabulary_trainer.h"
#include "segslam/util/error.h"
#include "segslam/util/output_folder.h"
#include "segslam/util/progress.h"

namespace segslam::apps {

namespace {

struct VocabTrainArguments {
  std::vector<std::filesystem::path> image_folders;
  std::vector<std::filesystem::path> datasets;
  std::filesystem::path out;
  int every = 5;
  int features = 1000;
  place::VocabularyOptions vocabulary;
};

std::vector<place::TrainingSource> trainingSources(const VocabTrainArguments& args) {
  std::vector<place::TrainingSource> sources;
  for (const auto& folder : args.image_folders) {
    sources.push_back({place::TrainingSource::Kind::kImageFolder, folder});
  }
  for (const auto& folder : args.datasets) {
    sources.push_back({place::TrainingSource::Kind::kTumDataset, folder});
  }
  return sources;
}

// The folder's own name: the file records what it was trained on without this machine's paths.
std::string folderName(const std::filesystem::path& folder) {
  auto normal = folder.lexically_normal();
  if (normal.filename().empty()) normal = normal.parent_path();
  return normal.filename().string();
}

std::string describeTraining(const VocabTrainArguments& args) {
  std::string sources;
  for (const auto& folder : args.image_folders) sources += " images:" + folderName(folder);
  for (const auto& folder : args.datasets) sources += " dataset:" + folderName(folder);
  return fmt::format("every {} frames, {} ORB features, k {}, depth {}, seed {};{}", args.every,
                     args.features, args.vocabulary.k, args.vocabulary.depth, args.vocabulary.seed,
                     sources);
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void runTrain(const VocabTrainArguments& args) {
  if (args.image_folders.empty() && args.datasets.empty()) {
    throw util::Error("vocab train: give at least one --images or --dataset");
  }
  util::createFolderFor(args.out);  // before the training, which takes minutes
  const auto images = place::listTrainingImages(trainingSources(args), args.every);
  spdlog::info("vocab train: {} images; k {}, depth {}, seed {}", images.size(), args.vocabulary.k,
               args.vocabulary.depth, args.vocabulary.seed);
  feature::OrbExtractorOptions orb;
  orb.num_features = args.features;
  util::ProgressBar bar("features", images.size(), "images");
  const auto descriptor_sets =
      place::extractTrainingDescriptors(images, orb, [&] { bar.advance(); });
  bar.finish();

  place::VocabularyTrainingSummary summary;
  summary.images = images.size();
  for (const auto& set : descriptor_sets) summary.descriptors += static_cast<unsigned>(set.rows);
  summary.description = describeTraining(args);
  spdlog::info("clustering {} descriptors", summary.descriptors);
  const auto start = std::chrono::steady_clock::now();
  const auto vocabulary =
      place::Vocabulary::train(descriptor_sets, args.vocabulary, std::move(summary));
  const double seconds = secondsSince(start);
  vocabulary.save(args.out);
  spdlog::info("{} words, {} nodes in {:.1f} s; wrote {} ({} bytes)", vocabulary.numWords(),
               vocabulary.nodes().size(), seconds, args.out.string(),
               std::filesystem::file_size(args.out));
}

void printInfo(const std::filesystem::path& file) {
  const auto vocabulary = place::Vocabulary::load(file);
  const auto& summary = vocabulary.trainingSummary();
  int max_level = 0;
  for (const auto& node : vocabulary.nodes()) max_level = std::max<int>(max_level, node.level);
  fmt::print("vocabulary       {} ({} bytes)\n", file.string(), std::filesystem::file_size(file));
  fmt::print("tree             k {}, depth {} (deepest leaf at level {})\n", vocabulary.k(),
             vocabulary.depth(), max_level);
  fmt::print("words            {} ({} nodes)\n", vocabulary.numWords(), vocabulary.nodes().size());
  fmt::print("trained on       {} images, {} descriptors\n", summary.images, summary.descriptors);
  fmt::print("training         {}\n", summary.description);
}

void registerTrain(CLI::App& vocab) {
  auto args = std::make_shared<VocabTrainArguments>();
  auto* command = vocab.add_subcommand(
      "train", "Build an ORB vocabulary tree (hierarchical k-majority, TF-IDF) from images");
  command->add_option("--images", args->image_folders, "Folder of *.png/*.jpg images (repeatable)")
      ->check(CLI::ExistingDirectory);
  command
      ->add_option("--dataset", args->datasets,
                   "TUM-layout sequence (repeatable); its mask.txt keeps keypoints off moving "
                   "objects")
      ->check(CLI::ExistingDirectory);
  command->add_option("-o,--out", args->out, "Vocabulary file to write")->required();
  command->add_option("--k", args->vocabulary.k, "Branching factor")
      ->check(CLI::Range(2, 255))
      ->capture_default_str();
  command->add_option("--depth", args->vocabulary.depth, "Levels below the root")
      ->check(CLI::Range(1, 10))
      ->capture_default_str();
  command->add_option("--every", args->every, "Use every N-th image of each source")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_option("--seed", args->vocabulary.seed, "Seed of the clustering")
      ->capture_default_str();
  command->add_option("--features", args->features, "ORB features per image")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command
      ->add_option("--max-iterations", args->vocabulary.max_iterations,
                   "k-majority iterations per node")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->callback([args] { runTrain(*args); });
}

void registerInfo(CLI::App& vocab) {
  auto file = std::make_shared<std::filesystem::path>();
  auto* command = vocab.add_subcommand("info", "Print a vocabulary file's header and tree size");
  command->add_option("file", *file, "Vocabulary file")->required();
  command->callback([file] { printInfo(*file); });
}

}  // namespace

void registerVocabCommand(CLI::App& app) {
  auto* vocab = app.add_subcommand("vocab", "Bag-of-words vocabulary: train, info");
  vocab->require_subcommand(1);
  registerTrain(*vocab);
  registerInfo(*vocab);
}

}  // namespace segslam::apps
