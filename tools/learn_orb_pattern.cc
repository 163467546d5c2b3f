// Learns the 256 binary tests of our ORB descriptor (Rublee et al. 2011, section 4.3) from real
// frames and writes them as a C++ source table (src/segslam/feature/orb_pattern_table.cc).
// See docs/orb_pattern.md for the procedure and the data used. Not needed at build time: the
// generated table is committed.
//
//   segslam_tool_learn_orb_pattern --output <table.cc> [--per-image N] [--frame-step S]
//       [--seed S] [--min-separation PX] [--max-correlation R]
//       <image folder or TUM dataset folder>...
//
// Patches: keypoints found by our own OrbExtractor (1000 per image, 8 levels), a seeded random
// subset of --per-image of them per image, sampled in the smoothed pyramid level at the
// keypoint's orientation exactly as the descriptor samples them. Even-numbered images (after
// --frame-step) train; odd-numbered ones are held out to compare the learned pattern with random
// tests.

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "segslam/feature/orb_descriptor.h"
#include "segslam/feature/orb_extractor.h"
#include "segslam/feature/orb_pattern_learning.h"

namespace {

namespace fs = std::filesystem;
using namespace segslam::feature;

struct Arguments {
  fs::path output;
  std::vector<fs::path> folders;
  int per_image = 150;
  int frame_step = 1;
  unsigned seed = 20240601;
  PatternLearningOptions learning;
  std::string command_line;
};

Arguments parseArguments(int argc, char** argv) {
  Arguments args;
  args.command_line = "segslam_tool_learn_orb_pattern";
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    args.command_line += " " + arg;
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
      args.command_line += std::string(" ") + argv[i + 1];
      return argv[++i];
    };
    if (arg == "--output") {
      args.output = value();
    } else if (arg == "--per-image") {
      args.per_image = std::stoi(value());
    } else if (arg == "--frame-step") {
      args.frame_step = std::max(1, std::stoi(value()));
    } else if (arg == "--min-separation") {
      args.learning.min_point_separation = std::stoi(value());
    } else if (arg == "--max-correlation") {
      args.learning.max_correlation = std::stod(value());
    } else if (arg == "--seed") {
      args.seed = static_cast<unsigned>(std::stoul(value()));
    } else if (arg.starts_with("--")) {
      throw std::invalid_argument("unknown option " + arg);
    } else {
      args.folders.emplace_back(arg);
    }
  }
  if (args.output.empty() || args.folders.empty()) {
    throw std::invalid_argument("need --output and at least one image folder");
  }
  return args;
}

std::vector<fs::path> imagesIn(const fs::path& folder, int step) {
  const fs::path images = fs::is_directory(folder / "rgb") ? folder / "rgb" : folder;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(images)) {
    const std::string extension = entry.path().extension().string();
    if (extension == ".png" || extension == ".jpg") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  std::vector<fs::path> every_step;
  for (std::size_t i = 0; i < files.size(); i += step) every_step.push_back(files[i]);
  return every_step;
}

// Adds up to `per_image` randomly chosen keypoints of the image to `samples`.
void samplePatches(const cv::Mat& gray, int per_image, std::mt19937& random,
                   OrbExtractor& extractor, PatchSamples& samples) {
  std::vector<cv::KeyPoint> keypoints;
  extractor.detect(gray, cv::Mat(), keypoints);
  std::shuffle(keypoints.begin(), keypoints.end(), random);
  if (static_cast<int>(keypoints.size()) > per_image) keypoints.resize(per_image);
  std::vector<cv::Mat> smoothed(extractor.numLevels());
  for (const cv::KeyPoint& keypoint : keypoints) {
    const int level = keypoint.octave;
    if (smoothed[level].empty()) smoothForDescriptor(extractor.pyramid()[level], smoothed[level]);
    const auto inverse_scale = static_cast<float>(extractor.inverseScaleFactors()[level]);
    const cv::Point center(cvRound(keypoint.pt.x * inverse_scale),
                           cvRound(keypoint.pt.y * inverse_scale));
    samples.addPatch(smoothed[level], center, keypoint.angle);
  }
}

std::vector<BinaryTest> randomTests(const std::vector<PatternPoint>& points, int count,
                                    int min_separation, std::mt19937& random) {
  std::uniform_int_distribution<std::size_t> pick(0, points.size() - 1);
  std::vector<BinaryTest> tests;
  while (static_cast<int>(tests.size()) < count) {
    const PatternPoint a = points[pick(random)];
    const PatternPoint b = points[pick(random)];
    if (std::max(std::abs(a.x - b.x), std::abs(a.y - b.y)) >= min_separation) {
      tests.push_back({a, b});
    }
  }
  return tests;
}

std::string describe(const PatternStatistics& s) {
  return fmt::format("mean |bit mean - 0.5| {:.4f}, mean |correlation| {:.4f}, max {:.4f}",
                     s.mean_abs_bias, s.mean_abs_correlation, s.max_abs_correlation);
}

// "//   " comment lines holding the words of `text`, wrapped to fit the 100-column style.
std::string wrappedComment(const std::string& text) {
  std::istringstream words(text);
  std::string word;
  std::string out;
  std::string line = "//  ";
  while (words >> word) {
    if (line.size() + 1 + word.size() > 100 && line.size() > 4) {
      out += line + "\n";
      line = "//    ";
    }
    line += " " + word;
  }
  return out + line + "\n";
}

std::string tableSource(const Arguments& args, const LearnedTests& learned, int images,
                        int patches) {
  std::ostringstream out;
  out << "// Generated by tools/learn_orb_pattern.cc; do not edit. See docs/orb_pattern.md.\n"
      << wrappedComment(args.command_line)
      << fmt::format("// {} training patches from {} images, {} candidate tests,\n", patches,
                     images, learned.candidate_tests)
      << fmt::format("// greedy |correlation| threshold {:.2f}.\n", learned.max_correlation)
      << "\n#include \"segslam/feature/orb_pattern.h\"\n\n"
      << "namespace segslam::feature {\n\n"
      << "const OrbPattern& learnedOrbPattern() {\n"
      << "  // {{x1, y1}, {x2, y2}}: bit = intensity(x1, y1) < intensity(x2, y2), keypoint frame.\n"
      << "  // clang-format off\n"
      << "  static constexpr OrbPattern kPattern = {{\n";
  for (const BinaryTest& test : learned.tests) {
    out << fmt::format("      {{{{{}, {}}}, {{{}, {}}}}},\n", test.first.x, test.first.y,
                       test.second.x, test.second.y);
  }
  out << "  }};\n  // clang-format on\n  return kPattern;\n}\n\n}  // namespace segslam::feature\n";
  return out.str();
}

int run(const Arguments& args) {
  const auto start = std::chrono::steady_clock::now();
  OrbExtractor extractor;
  std::mt19937 random(args.seed);
  const std::vector<PatternPoint> points = patternCandidatePoints();
  PatchSamples training(points);
  PatchSamples held_out(points);
  int images = 0;
  for (const fs::path& folder : args.folders) {
    for (const fs::path& file : imagesIn(folder, args.frame_step)) {
      const cv::Mat gray = cv::imread(file.string(), cv::IMREAD_GRAYSCALE);
      if (gray.empty()) throw std::runtime_error("cannot read " + file.string());
      samplePatches(gray, args.per_image, random, extractor, images % 2 == 0 ? training : held_out);
      ++images;
    }
  }
  std::cerr << fmt::format("{} images: {} training patches, {} held out\n", images,
                           training.patchCount(), held_out.patchCount());
  const PatternLearningOptions& options = args.learning;
  const LearnedTests learned = learnBinaryTests(training, options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cerr << fmt::format(
      "learned {} of {} candidate tests at |correlation| <= {:.2f} in {:.1f} s\n",
      learned.tests.size(), learned.candidate_tests, learned.max_correlation, seconds);
  const auto random_tests =
      randomTests(points, options.num_tests, options.min_point_separation, random);
  std::cerr << "held out, learned: " << describe(patternStatistics(held_out, learned.tests))
            << "\nheld out, random:  " << describe(patternStatistics(held_out, random_tests))
            << "\n";
  std::ofstream out(args.output);
  out << tableSource(args, learned, images, training.patchCount());
  if (!out) throw std::runtime_error("cannot write " + args.output.string());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(parseArguments(argc, argv));
  } catch (const std::exception& e) {
    std::cerr << "learn_orb_pattern: " << e.what() << "\n";
    return 1;
  }
}
