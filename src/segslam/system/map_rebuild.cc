#include "segslam/system/map_rebuild.h"

#include <fmt/format.h>

#include <algorithm>

#include "segslam/io/trajectory_io.h"
#include "segslam/segmentation/semantic_class_map.h"
#include "segslam/segmentation/semantic_segmenter.h"
#include "segslam/util/error.h"

namespace segslam::system {

namespace {

std::size_t frameAt(const io::TumDataset& dataset, double timestamp,
                    const std::filesystem::path& trajectory_file) {
  const auto& frames = dataset.frames();
  const auto it =
      std::lower_bound(frames.begin(), frames.end(), timestamp - 1e-4,
                       [](const io::FrameRecord& frame, double t) { return frame.timestamp < t; });
  if (it == frames.end() || it->timestamp > timestamp + 1e-4) {
    util::failAt(trajectory_file, fmt::format("keyframe {:.6f} is no frame of {}", timestamp,
                                              dataset.folder().string()));
  }
  return static_cast<std::size_t>(it - frames.begin());
}

// A keyframe's own network segmentation, in the map's labels.
class KeyFrameSegmenter {
 public:
  KeyFrameSegmenter(const std::filesystem::path& model_config,
                    const std::optional<std::filesystem::path>& model_file)
      : config_(segmentation::readModelConfig(model_config)),
        segmenter_(config_, segmentation::resolveModelFile(config_, model_config, model_file)),
        classes_(config_.classes) {}

  void label(dense::KeyFrameImages& images) {
    const segmentation::SemanticMasks masks = segmenter_.segment(images.bgr);
    images.dynamic_mask = masks.dynamic;
    images.labels = classes_.apply(masks.labels);
    images.instances = cv::Mat();
  }

 private:
  segmentation::ModelConfig config_;
  segmentation::SemanticSegmenter segmenter_;
  segmentation::SemanticClassMap classes_;
};

}  // namespace

MapSummary rebuildMap(const io::TumDataset& dataset, const std::filesystem::path& run_dir,
                      const MapRebuildOptions& options) {
  if (options.oracle_masks && !dataset.hasMasks()) {
    util::failAt(dataset.folder() / "mask.txt", "oracle masks need the dataset's mask.txt");
  }
  const auto start = std::chrono::steady_clock::now();
  const auto trajectory_file = run_dir / "KeyFrameTrajectory.txt";
  const auto keyframes = io::readTumTrajectory(trajectory_file);
  std::optional<KeyFrameSegmenter> network;
  if (options.model_config) network.emplace(*options.model_config, options.model_file);
  dense::MapBuilder builder(dataset.camera(), options.map);
  std::uint64_t id = 0;
  for (const auto& keyframe : keyframes.poses()) {
    auto frame = dataset.loadFrame(frameAt(dataset, keyframe.timestamp, trajectory_file));
    dense::KeyFrameImages images{frame.rgb, frame.depth,
                                 options.oracle_masks ? frame.mask : cv::Mat(), frame.labels,
                                 frame.instances};
    if (network) network->label(images);
    builder.addKeyFrame(id++, keyframe.timestamp, std::move(images));
  }
  MapSummary summary = buildAndWriteMap(builder, keyframes, run_dir / "map", options.occupancy);
  summary.build_seconds = secondsSince(start);
  return summary;
}

}  // namespace segslam::system
