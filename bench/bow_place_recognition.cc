// Place recognition with a bag-of-words vocabulary on a TUM sequence with ground truth: scores of
// every pair of every N-th frame, against how far apart the cameras really were. Prints one JSON
// object (bench/bow_vocabulary.sh collects them into bench/results/bow_vocabulary.md).
//
//   segslam_bench_bow_place_recognition VOCABULARY DATASET [EVERY=10]
//
// Revisit pairs: at least 1 s apart in time, cameras within 0.10 m and 10 deg. Non-revisits:
// more than 0.20 m or 20 deg apart. Pairs in between are left out of the precision figures.

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <opencv2/imgcodecs.hpp>
#include <optional>
#include <string>
#include <vector>

#include "segslam/feature/orb_extractor.h"
#include "segslam/io/tum_dataset.h"
#include "segslam/place/bow_database.h"
#include "segslam/place/vocabulary.h"

namespace {

using segslam::place::BowVector;

struct SampledFrame {
  std::size_t index;
  double timestamp;
  segslam::geometry::Pose T_wc;
  BowVector bow;
};

struct PairScore {
  double score;
  bool revisit;
};

constexpr double kMinSeconds = 1.0;
constexpr double kRevisitMetres = 0.10;
constexpr double kRevisitDegrees = 10.0;
constexpr double kDistinctMetres = 0.20;
constexpr double kDistinctDegrees = 20.0;

double angleDegrees(const segslam::geometry::Pose& a, const segslam::geometry::Pose& b) {
  const Eigen::AngleAxisd relative(a.rotation().transpose() * b.rotation());
  return relative.angle() * 180.0 / M_PI;
}

double averagePrecision(std::vector<PairScore> pairs) {
  std::sort(pairs.begin(), pairs.end(),
            [](const PairScore& a, const PairScore& b) { return a.score > b.score; });
  double hits = 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    if (!pairs[i].revisit) continue;
    hits += 1.0;
    sum += hits / static_cast<double>(i + 1);
  }
  return hits > 0.0 ? sum / hits : 0.0;
}

double mean(const std::vector<double>& values) {
  double sum = 0.0;
  for (const double v : values) sum += v;
  return values.empty() ? 0.0 : sum / static_cast<double>(values.size());
}

int run(const std::string& vocabulary_file, const std::string& dataset_folder, int every) {
  const auto load_start = std::chrono::steady_clock::now();
  const auto vocabulary = segslam::place::Vocabulary::load(vocabulary_file);
  const double load_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - load_start).count();
  const auto dataset = segslam::io::TumDataset::open(dataset_folder);
  if (!dataset.groundTruth()) {
    fmt::print(stderr, "{}: no groundtruth.txt\n", dataset_folder);
    return 1;
  }
  segslam::feature::OrbExtractor extractor;
  std::vector<SampledFrame> frames;
  double transform_seconds = 0.0;
  for (std::size_t i = 0; i < dataset.size(); i += static_cast<std::size_t>(every)) {
    const auto& record = dataset.frames()[i];
    const auto pose = dataset.groundTruth()->poseAt(record.timestamp, 0.02);
    if (!pose) continue;
    const cv::Mat gray = cv::imread(record.rgb_path.string(), cv::IMREAD_GRAYSCALE);
    std::vector<cv::KeyPoint> keypoints;
    cv::Mat descriptors;
    extractor.extract(gray, cv::Mat(), keypoints, descriptors);
    const auto start = std::chrono::steady_clock::now();
    BowVector bow = vocabulary.transform(descriptors);
    transform_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    frames.push_back({i, record.timestamp, *pose, std::move(bow)});
  }

  std::vector<double> adjacent;
  std::vector<double> revisit_scores;
  std::vector<double> distinct_scores;
  std::vector<PairScore> pairs;
  segslam::place::BowDatabase database;
  for (const auto& frame : frames) database.add(frame.bow);
  int queries = 0;
  int top1_hits = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    if (i + 1 < frames.size())
      adjacent.push_back(segslam::place::l1Score(frames[i].bow, frames[i + 1].bow));
    bool has_revisit = false;
    for (std::size_t j = 0; j < frames.size(); ++j) {
      if (std::abs(frames[j].timestamp - frames[i].timestamp) < kMinSeconds) continue;
      const double metres = (frames[i].T_wc.translation() - frames[j].T_wc.translation()).norm();
      const double degrees = angleDegrees(frames[i].T_wc, frames[j].T_wc);
      const bool revisit = metres < kRevisitMetres && degrees < kRevisitDegrees;
      const bool distinct = metres > kDistinctMetres || degrees > kDistinctDegrees;
      has_revisit = has_revisit || revisit;
      if (j <= i || (!revisit && !distinct)) continue;
      const double score = segslam::place::l1Score(frames[i].bow, frames[j].bow);
      pairs.push_back({score, revisit});
      (revisit ? revisit_scores : distinct_scores).push_back(score);
    }
    if (!has_revisit) continue;
    ++queries;
    const auto results = database.query(frames[i].bow, 1, [&](std::uint32_t entry) {
      return std::abs(frames[entry].timestamp - frames[i].timestamp) < kMinSeconds;
    });
    if (results.empty()) continue;
    const auto& best = frames[results[0].entry];
    const double metres = (frames[i].T_wc.translation() - best.T_wc.translation()).norm();
    if (metres < kRevisitMetres && angleDegrees(frames[i].T_wc, best.T_wc) < kRevisitDegrees) {
      ++top1_hits;
    }
  }
  fmt::print(
      "{{\"vocabulary\": \"{}\", \"words\": {}, \"load_s\": {:.3f}, \"frames\": {}, "
      "\"transform_ms_per_frame\": {:.3f}, \"mean_score_adjacent\": {:.4f}, "
      "\"mean_score_revisit\": {:.4f}, \"mean_score_distinct\": {:.4f}, \"revisit_pairs\": {}, "
      "\"distinct_pairs\": {}, \"average_precision\": {:.4f}, \"top1_queries\": {}, "
      "\"top1_recall\": {:.4f}}}\n",
      vocabulary_file, vocabulary.numWords(), load_seconds, frames.size(),
      1000.0 * transform_seconds / std::max<double>(frames.size(), 1), mean(adjacent),
      mean(revisit_scores), mean(distinct_scores), revisit_scores.size(), distinct_scores.size(),
      averagePrecision(pairs), queries,
      queries > 0 ? static_cast<double>(top1_hits) / queries : 0.0);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    fmt::print(stderr, "usage: {} VOCABULARY DATASET [EVERY=10]\n", argv[0]);
    return 2;
  }
  try {
    return run(argv[1], argv[2], argc > 3 ? std::max(1, std::atoi(argv[3])) : 10);
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 1;
  }
}
