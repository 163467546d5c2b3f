// ORB extraction speed, count and spread: segslam::feature::OrbExtractor against cv::ORB
// (1000 features, 8 levels, factor 1.2), single-threaded, on real frames.
//
//   segslam_bench_orb_extractor <dataset or image folder> [results.json]
//
// The folder is a TUM-style dataset (images under rgb/) or a folder of images. When it has a
// mask/ folder (e.g. tum_fr1_xyz_300_walker), each frame's mask/<stem>.png, non-zero = dynamic, is
// also used for a masked run. Images are decoded before timing; the first frames warm up caches.
// Wall time (median, p95, mean) and the median CPU time of the thread are reported per frame:
// on a shared machine the wall time also counts waiting for a core. The parallel row uses TBB
// over pyramid levels; its CPU time is the calling thread's share only.

#include "segslam/feature/orb_extractor.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using segslam::feature::OrbExtractor;
using segslam::feature::OrbExtractorOptions;

constexpr int kWarmupFrames = 5;
constexpr int kGridColumns = 8;
constexpr int kGridRows = 6;

struct Frame {
  std::string name;
  cv::Mat gray;
  cv::Mat dynamic_mask;  // empty when the folder has no masks
};

using Extract = std::function<void(const Frame&, std::vector<cv::KeyPoint>&, cv::Mat&)>;

struct Summary {
  std::string method;
  double median_ms = 0;
  double p95_ms = 0;
  double mean_ms = 0;
  // CPU time of the calling thread: on a shared machine, wall time also counts waiting for a core.
  double median_cpu_ms = 0;
  double mean_keypoints = 0;
  // Spread over an 8 x 6 grid: share of cells with at least one keypoint, and the coefficient
  // of variation (stddev / mean) of the per-cell counts; both averaged over frames.
  double nonempty_cell_share = 0;
  double cell_count_cv = 0;
};

std::vector<fs::path> imageFiles(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string extension = entry.path().extension().string();
    if (extension == ".jpg" || extension == ".png") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<Frame> loadFrames(const fs::path& root) {
  const fs::path images = fs::is_directory(root / "rgb") ? root / "rgb" : root;
  const fs::path masks = root / "mask";
  std::vector<Frame> frames;
  for (const fs::path& file : imageFiles(images)) {
    Frame frame{file.stem().string(), cv::imread(file.string(), cv::IMREAD_GRAYSCALE), {}};
    if (frame.gray.empty()) continue;
    const fs::path mask = masks / (file.stem().string() + ".png");
    if (fs::exists(mask)) frame.dynamic_mask = cv::imread(mask.string(), cv::IMREAD_GRAYSCALE);
    frames.push_back(std::move(frame));
  }
  return frames;
}

double threadCpuMs() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) * 1e3 + static_cast<double>(now.tv_nsec) * 1e-6;
}

double percentile(std::vector<double> values, double fraction) {
  const auto index = static_cast<std::size_t>(std::lround(fraction * (values.size() - 1)));
  std::nth_element(values.begin(), values.begin() + static_cast<long>(index), values.end());
  return values[index];
}

void addSpread(const std::vector<cv::KeyPoint>& keypoints, cv::Size size, Summary& summary) {
  std::vector<int> counts(kGridColumns * kGridRows, 0);
  for (const auto& keypoint : keypoints) {
    const int column = std::clamp(static_cast<int>(keypoint.pt.x * kGridColumns / size.width), 0,
                                  kGridColumns - 1);
    const int row =
        std::clamp(static_cast<int>(keypoint.pt.y * kGridRows / size.height), 0, kGridRows - 1);
    ++counts[row * kGridColumns + column];
  }
  const double mean = static_cast<double>(keypoints.size()) / counts.size();
  double variance = 0;
  int nonempty = 0;
  for (const int count : counts) {
    variance += (count - mean) * (count - mean) / counts.size();
    nonempty += count > 0;
  }
  summary.nonempty_cell_share += static_cast<double>(nonempty) / counts.size();
  summary.cell_count_cv += mean > 0 ? std::sqrt(variance) / mean : 0.0;
}

struct Method {
  std::string name;
  Extract extract;
};

// Per-frame measurements of one method.
struct Samples {
  std::vector<double> wall_ms;
  std::vector<double> cpu_ms;
  Summary summary;
};

void timeOnce(const Method& method, const Frame& frame, Samples& samples) {
  static thread_local std::vector<cv::KeyPoint> keypoints;
  static thread_local cv::Mat descriptors;
  const double cpu_start = threadCpuMs();
  const auto start = std::chrono::steady_clock::now();
  method.extract(frame, keypoints, descriptors);
  const auto stop = std::chrono::steady_clock::now();
  samples.cpu_ms.push_back(threadCpuMs() - cpu_start);
  samples.wall_ms.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
  samples.summary.mean_keypoints += static_cast<double>(keypoints.size());
  addSpread(keypoints, frame.gray.size(), samples.summary);
}

Summary summarise(Samples& samples) {
  Summary summary = samples.summary;
  const double n = static_cast<double>(samples.wall_ms.size());
  summary.median_ms = percentile(samples.wall_ms, 0.5);
  summary.p95_ms = percentile(samples.wall_ms, 0.95);
  summary.median_cpu_ms = percentile(samples.cpu_ms, 0.5);
  for (const double t : samples.wall_ms) summary.mean_ms += t / n;
  summary.mean_keypoints /= n;
  summary.nonempty_cell_share /= n;
  summary.cell_count_cv /= n;
  return summary;
}

// The methods take turns frame by frame, so that a load change on the shared machine hits all of
// them alike instead of whichever happened to run at the time.
std::vector<Summary> measure(const std::vector<Method>& methods, const std::vector<Frame>& frames) {
  std::vector<Samples> samples(methods.size());
  for (std::size_t m = 0; m < methods.size(); ++m) {
    samples[m].summary.method = methods[m].name;
    Samples warmup;
    for (int i = 0; i < kWarmupFrames && i < static_cast<int>(frames.size()); ++i) {
      timeOnce(methods[m], frames[i], warmup);
    }
  }
  for (const Frame& frame : frames) {
    for (std::size_t m = 0; m < methods.size(); ++m) timeOnce(methods[m], frame, samples[m]);
  }
  std::vector<Summary> summaries;
  for (Samples& method_samples : samples) summaries.push_back(summarise(method_samples));
  return summaries;
}

Extract ours(const OrbExtractorOptions& options, bool masked) {
  auto extractor = std::make_shared<OrbExtractor>(options);
  return [extractor, masked](const Frame& frame, std::vector<cv::KeyPoint>& keypoints,
                             cv::Mat& descriptors) {
    extractor->extract(frame.gray, masked ? frame.dynamic_mask : cv::Mat(), keypoints, descriptors);
  };
}

Extract opencvOrb() {
  cv::Ptr<cv::ORB> orb = cv::ORB::create(1000, 1.2f, 8);
  return [orb](const Frame& frame, std::vector<cv::KeyPoint>& keypoints, cv::Mat& descriptors) {
    orb->detectAndCompute(frame.gray, cv::noArray(), keypoints, descriptors);
  };
}

nlohmann::json toJson(const Summary& s) {
  return {{"method", s.method},
          {"median_ms", s.median_ms},
          {"p95_ms", s.p95_ms},
          {"mean_ms", s.mean_ms},
          {"median_thread_cpu_ms", s.median_cpu_ms},
          {"mean_keypoints", s.mean_keypoints},
          {"nonempty_cell_share_8x6", s.nonempty_cell_share},
          {"cell_count_cv_8x6", s.cell_count_cv}};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::cerr << "usage: " << argv[0] << " <dataset or image folder> [results.json]\n";
    return 2;
  }
  const std::vector<Frame> frames = loadFrames(argv[1]);
  if (frames.empty()) {
    std::cerr << "no .jpg/.png images in " << argv[1] << "\n";
    return 1;
  }
  cv::setNumThreads(1);  // cv::ORB single-threaded, like our default
  const bool has_masks = std::any_of(frames.begin(), frames.end(),
                                     [](const Frame& f) { return !f.dynamic_mask.empty(); });

  OrbExtractorOptions parallel;
  parallel.parallel_levels = true;
  std::vector<Method> methods = {{"segslam", ours({}, false)},
                                 {"opencv_orb", opencvOrb()},
                                 {"segslam_parallel_levels", ours(parallel, false)}};
  if (has_masks) methods.push_back({"segslam_masked", ours({}, true)});
  const std::vector<Summary> summaries = measure(methods, frames);

  std::printf("%zu frames %dx%d from %s\n", frames.size(), frames[0].gray.cols, frames[0].gray.rows,
              argv[1]);
  std::printf("%-24s %9s %9s %9s %9s %10s %13s %7s\n", "method", "median_ms", "p95_ms", "mean_ms",
              "cpu_ms", "keypoints", "nonempty_8x6", "cv_8x6");
  nlohmann::json results = nlohmann::json::array();
  for (const Summary& s : summaries) {
    std::printf("%-24s %9.2f %9.2f %9.2f %9.2f %10.1f %13.3f %7.3f\n", s.method.c_str(),
                s.median_ms, s.p95_ms, s.mean_ms, s.median_cpu_ms, s.mean_keypoints,
                s.nonempty_cell_share, s.cell_count_cv);
    results.push_back(toJson(s));
  }
  if (argc == 3) {
    std::ofstream out(argv[2]);
    out << nlohmann::json{{"dataset", argv[1]}, {"frames", frames.size()}, {"results", results}}
               .dump(2)
        << "\n";
    if (!out) {
      std::cerr << "could not write " << argv[2] << "\n";
      return 1;
    }
  }
  return 0;
}
