// Cost and quality of carrying a slow segmenter's masks to the frames in between
// (segslam::segmentation::MaskStream: optical flow, then snapping to depth), single-threaded.
//
//   segslam_bench_mask_carry <dataset with mask.txt> [age] [results.json]
//
// The segmenter is replaced by the dataset's exact masks, delivered every `age` frames (default
// 13: how old the network's output is, on average, when it arrives on 2 cores), so what is timed
// is the per-frame work on the tracking thread, and the carried mask can be scored against the
// exact one of its own frame. Images are decoded before timing.

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "segslam/eval/mask_metrics.h"
#include "segslam/io/tum_dataset.h"
#include "segslam/segmentation/mask_propagator.h"
#include "segslam/segmentation/mask_stream.h"
#include "segslam/util/elapsed_time.h"
#include "segslam/util/error.h"

namespace {

using segslam::segmentation::MaskStream;
using segslam::segmentation::MaskStreamOptions;
using segslam::segmentation::SegmentationJob;
using segslam::segmentation::SemanticMasks;

double threadCpuMilliseconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return 1e3 * static_cast<double>(now.tv_sec) + 1e-6 * static_cast<double>(now.tv_nsec);
}

double percentile(std::vector<double> values, double share) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  return values[static_cast<std::size_t>(share * static_cast<double>(values.size() - 1))];
}

double mean(const std::vector<double>& values) {
  double sum = 0.0;
  for (double v : values) sum += v;
  return values.empty() ? 0.0 : sum / static_cast<double>(values.size());
}

int run(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: segslam_bench_mask_carry <dataset with mask.txt> [age] [results.json]\n";
    return 2;
  }
  const auto dataset = segslam::io::TumDataset::open(argv[1]);
  if (!dataset.hasMasks()) throw segslam::util::Error(std::string(argv[1]) + ": no mask.txt");
  const int age = argc > 2 ? std::stoi(argv[2]) : 13;
  std::vector<segslam::io::RgbdFrame> frames;
  for (std::size_t i = 0; i < dataset.size(); ++i) frames.push_back(dataset.loadFrame(i));

  MaskStreamOptions options;
  options.synchronous = true;
  options.interval = age;
  MaskStream stream(
      [&](const SegmentationJob& job) {
        const cv::Mat& exact = frames[job.current.id].mask;
        return SemanticMasks{exact.clone(), exact.clone()};
      },
      options);

  std::vector<double> wall_ms;
  std::vector<double> cpu_ms;
  // What the stream's two steps each add: the segmenter's last mask as it is, and its objects
  // moved by optical flow alone (before the depth snapping).
  segslam::segmentation::MaskPropagator flow_only;
  std::vector<double> iou;
  std::vector<double> stale_iou;
  std::vector<double> flow_iou;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    flow_only.addFrame(i, frames[i].rgb);
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = threadCpuMilliseconds();
    const SemanticMasks masks = stream.masksFor(i, frames[i].rgb, frames[i].depth);
    cpu_ms.push_back(threadCpuMilliseconds() - cpu_start);
    wall_ms.push_back(segslam::util::millisecondsSince(start));
    if (i % static_cast<std::size_t>(age) != 0 && cv::countNonZero(frames[i].mask) > 0) {
      const std::size_t source = i - i % static_cast<std::size_t>(age);
      iou.push_back(segslam::eval::compareMasks(masks.dynamic, frames[i].mask).iou());
      stale_iou.push_back(segslam::eval::compareMasks(frames[source].mask, frames[i].mask).iou());
      flow_iou.push_back(segslam::eval::compareMasks(
                             flow_only.moveObjects(frames[source].mask, source), frames[i].mask)
                             .iou());
    }
  }
  // The frames the segmenter itself ran on include its (here trivial) cost; the others are the
  // carrying cost alone.
  std::vector<double> carry_wall;
  std::vector<double> carry_cpu;
  for (std::size_t i = 1; i < frames.size(); ++i) {
    if (i % static_cast<std::size_t>(age) == 0) continue;
    carry_wall.push_back(wall_ms[i]);
    carry_cpu.push_back(cpu_ms[i]);
  }
  const nlohmann::json results = {{"dataset", argv[1]},
                                  {"frames", frames.size()},
                                  {"age", age},
                                  {"carry_wall_ms_median", percentile(carry_wall, 0.5)},
                                  {"carry_wall_ms_p95", percentile(carry_wall, 0.95)},
                                  {"carry_cpu_ms_median", percentile(carry_cpu, 0.5)},
                                  {"carried_mask_iou_mean", mean(iou)},
                                  {"stale_mask_iou_mean", mean(stale_iou)},
                                  {"flow_only_mask_iou_mean", mean(flow_iou)},
                                  {"scored_frames", iou.size()}};
  std::cout << results.dump(2) << "\n";
  if (argc > 3) std::ofstream(argv[3]) << results.dump(2) << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& error) {
    std::cerr << "error: " << error.what() << "\n";
    return 1;
  }
}
