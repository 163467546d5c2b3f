// CNN backbone cost per image: segslam::place::CnnFeatureExtractor run on real frames, once with
// all of the config's layers (what `segslam eval loops` extracts) and once per layer alone (the
// network then stops at that layer: what the cnn loop detector extracts).
//
//   segslam_bench_cnn_extraction <backbone config> <dataset> [frames (default 30)]
//
// Per image: median wall time, median processor time of the whole process (OpenCV's worker
// threads included) and of the calling thread. On a machine shared with other work the wall time
// also counts waiting for a core; the process time is the fairer figure there.

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "segslam/io/tum_dataset.h"
#include "segslam/place/cnn_backbone_config.h"
#include "segslam/place/cnn_feature_extractor.h"
#include "segslam/util/error.h"

namespace {

namespace fs = std::filesystem;
using segslam::place::CnnBackboneConfig;
using segslam::place::CnnFeatureExtractor;

constexpr int kWarmupImages = 3;

double cpuMilliseconds(clockid_t clock) {
  timespec now{};
  clock_gettime(clock, &now);
  return 1e3 * static_cast<double>(now.tv_sec) + 1e-6 * static_cast<double>(now.tv_nsec);
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values.empty() ? 0.0 : values[values.size() / 2];
}

void measure(const std::string& label, CnnBackboneConfig config, const fs::path& model,
             const std::vector<cv::Mat>& images) {
  CnnFeatureExtractor extractor(std::move(config), model);
  for (int i = 0; i < kWarmupImages; ++i) (void)extractor.extract(images.front());
  std::vector<double> wall;
  std::vector<double> process;
  std::vector<double> thread;
  for (const cv::Mat& image : images) {
    const auto start = std::chrono::steady_clock::now();
    const double process_start = cpuMilliseconds(CLOCK_PROCESS_CPUTIME_ID);
    const double thread_start = cpuMilliseconds(CLOCK_THREAD_CPUTIME_ID);
    (void)extractor.extract(image);
    thread.push_back(cpuMilliseconds(CLOCK_THREAD_CPUTIME_ID) - thread_start);
    process.push_back(cpuMilliseconds(CLOCK_PROCESS_CPUTIME_ID) - process_start);
    wall.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count());
  }
  std::cout << "| " << label << " | " << median(wall) << " | " << median(process) << " | "
            << median(thread) << " |\n";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: segslam_bench_cnn_extraction <backbone config> <dataset> [frames]\n";
    return 2;
  }
  try {
    const fs::path config_file = argv[1];
    const CnnBackboneConfig config = segslam::place::readCnnBackboneConfig(config_file);
    const fs::path model = segslam::place::resolveBackboneModelFile(config, config_file, {});
    const auto dataset = segslam::io::TumDataset::open(argv[2]);
    const std::size_t frames = argc > 3 ? std::stoul(argv[3]) : 30;
    std::vector<cv::Mat> images;
    for (std::size_t i = 0; i < std::min(frames, dataset.size()); ++i) {
      images.push_back(dataset.loadFrame(i).rgb);
    }
    std::cout
        << "backbone " << config.name << ", input " << config.input_size.width << "x"
        << config.input_size.height << ", " << images.size() << " images, " << cv::getNumThreads()
        << " OpenCV threads\n\n"
        << "| layers | wall ms | process CPU ms | thread CPU ms |\n| --- | ---: | ---: | ---: |\n";
    measure("all", config, model, images);
    for (const auto& layer : config.layers) {
      CnnBackboneConfig single = config;
      single.layers = {layer};
      measure("up to " + layer.name, single, model, images);
    }
  } catch (const segslam::util::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
