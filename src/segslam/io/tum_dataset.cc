#include "segslam/io/tum_dataset.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <string_view>
#include <system_error>
#include <utility>

#include "segslam/io/camera_config.h"
#include "segslam/io/frame_images.h"
#include "segslam/io/image_list.h"
#include "segslam/io/timestamp_association.h"
#include "segslam/io/trajectory_io.h"
#include "segslam/util/error.h"

namespace segslam::io {

namespace {

namespace fs = std::filesystem;

// Lists that attach one more image to every frame, matched by timestamp.
struct FrameImageList {
  std::string_view file_name;
  std::string_view what;
  std::optional<fs::path> FrameRecord::*path;
};

// associate.py's output as the TUM tools' users name it, and as the ETH3D SLAM benchmark ships it.
constexpr std::string_view kAssociationFiles[] = {"associations.txt", "associated.txt"};

constexpr FrameImageList kFrameImageLists[] = {
    {"mask.txt", "mask", &FrameRecord::mask_path},
    {"labels.txt", "label image", &FrameRecord::labels_path},
    {"instances.txt", "instance image", &FrameRecord::instances_path},
};

// The error_code overloads: a failed status check (permissions) means "not there", not a throw.
bool isFile(const fs::path& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

bool pathExists(const fs::path& path) {
  std::error_code ec;
  return fs::exists(path, ec);
}

void requireFolder(const fs::path& folder) {
  std::error_code ec;
  if (!fs::exists(folder, ec)) util::failAt(folder, "dataset folder not found");
  if (!fs::is_directory(folder, ec)) util::failAt(folder, "is not a folder");
}

void requireMaxTimeDifference(double seconds) {
  if (!(seconds > 0.0) || !std::isfinite(seconds)) {
    throw util::Error(
        fmt::format("the maximum time difference must be positive seconds, not {}", seconds));
  }
}

void requireListedFileExists(const ImageListEntry& entry, const fs::path& folder,
                             const fs::path& list_file) {
  const fs::path path = folder / entry.path;
  if (!isFile(path)) {
    util::failAt(list_file, entry.line,
                 fmt::format("listed file {} does not exist (or is not a file)", path.string()));
  }
}

std::vector<ImageListEntry> readCheckedImageList(const fs::path& folder, std::string_view name) {
  const fs::path file = folder / name;
  auto entries = readImageList(file);
  for (const auto& entry : entries) requireListedFileExists(entry, folder, file);
  return entries;
}

// The colour and depth images a list names that are not there. Published sequences list the odd
// image they do not contain (Bonn RGB-D Dynamic); the TUM tools associate the lists as written,
// and the frames whose image is absent are skipped, as damaged ones are. A list whose images are
// mostly absent names the wrong folder, and is an error.
class AbsentImageCheck {
 public:
  AbsentImageCheck(fs::path folder, std::vector<AbsentImage>& absent)
      : folder_(std::move(folder)), absent_(absent) {}

  // Records the entries of `list_file` whose image is absent, with a warning naming each.
  void check(const fs::path& list_file, const std::vector<const ImageListEntry*>& entries) {
    const std::size_t first = absent_.size();
    for (const ImageListEntry* entry : entries) {
      const fs::path path = folder_ / entry->path;
      if (!isFile(path)) absent_.push_back({list_file, entry->line, path});
    }
    const std::size_t absent = absent_.size() - first;
    if (2 * absent > entries.size()) {
      util::failAt(list_file, absent_[first].line,
                   fmt::format("{} of its {} listed images do not exist, the first {}", absent,
                               entries.size(), absent_[first].path.string()));
    }
    for (std::size_t i = first; i < absent_.size(); ++i) {
      spdlog::warn("{}:{}: listed image {} does not exist: left out", absent_[i].list_file.string(),
                   absent_[i].line, absent_[i].path.string());
    }
  }

  [[nodiscard]] bool isAbsent(const fs::path& list_file, int line) const {
    return std::any_of(absent_.begin(), absent_.end(), [&](const AbsentImage& image) {
      return image.line == line && image.list_file == list_file;
    });
  }

 private:
  fs::path folder_;
  std::vector<AbsentImage>& absent_;
};

std::vector<const ImageListEntry*> pointersTo(const std::vector<ImageListEntry>& entries) {
  std::vector<const ImageListEntry*> pointers;
  pointers.reserve(entries.size());
  for (const auto& entry : entries) pointers.push_back(&entry);
  return pointers;
}

std::vector<ImageListEntry> readNonEmptyImageList(const fs::path& file) {
  auto entries = readImageList(file);
  if (entries.empty()) util::failAt(file, "lists no images");
  return entries;
}

std::vector<double> timestampsOf(const std::vector<ImageListEntry>& entries) {
  std::vector<double> stamps;
  stamps.reserve(entries.size());
  for (const auto& entry : entries) stamps.push_back(entry.timestamp);
  return stamps;
}

std::vector<double> timestampsOf(const std::vector<FrameRecord>& frames) {
  std::vector<double> stamps;
  stamps.reserve(frames.size());
  for (const auto& frame : frames) stamps.push_back(frame.timestamp);
  return stamps;
}

FrameRecord makeFrame(const fs::path& folder, const ImageListEntry& rgb,
                      const ImageListEntry& depth) {
  FrameRecord frame;
  frame.timestamp = rgb.timestamp;
  frame.rgb_path = folder / rgb.path;
  frame.depth_timestamp = depth.timestamp;
  frame.depth_path = folder / depth.path;
  return frame;
}

std::vector<FrameRecord> requireFrames(std::vector<FrameRecord> frames, const fs::path& file) {
  if (frames.empty()) util::failAt(file, "none of the frames it lists has its images");
  return frames;
}

std::vector<FrameRecord> framesFromAssociationList(const fs::path& file,
                                                   std::vector<AbsentImage>& absent) {
  const fs::path folder = file.parent_path();
  const auto entries = readAssociationList(file);
  if (entries.empty()) util::failAt(file, "lists no frames");
  std::vector<const ImageListEntry*> images;
  for (const auto& entry : entries) {
    images.push_back(&entry.rgb);
    images.push_back(&entry.depth);
  }
  AbsentImageCheck absent_images(folder, absent);
  absent_images.check(file, images);
  std::vector<FrameRecord> frames;
  frames.reserve(entries.size());
  for (const auto& entry : entries) {
    // Both images of an entry share its line: either absent skips it.
    if (absent_images.isAbsent(file, entry.rgb.line)) continue;
    frames.push_back(makeFrame(folder, entry.rgb, entry.depth));
  }
  return requireFrames(std::move(frames), file);
}

std::vector<FrameRecord> framesFromColourAndDepthLists(const fs::path& folder,
                                                       double max_difference,
                                                       std::vector<AbsentImage>& absent) {
  const fs::path rgb_file = folder / "rgb.txt";
  const fs::path depth_file = folder / "depth.txt";
  const auto rgb = readNonEmptyImageList(rgb_file);
  const auto depth = readNonEmptyImageList(depth_file);
  AbsentImageCheck absent_images(folder, absent);
  absent_images.check(rgb_file, pointersTo(rgb));
  absent_images.check(depth_file, pointersTo(depth));
  const auto pairs = associateTimestamps(timestampsOf(rgb), timestampsOf(depth), max_difference);
  if (pairs.empty()) {
    util::failAt(rgb_file, fmt::format("no colour image has a depth image in depth.txt within {} s "
                                       "(colour {:.6f} to {:.6f}, depth {:.6f} to {:.6f})",
                                       max_difference, rgb.front().timestamp, rgb.back().timestamp,
                                       depth.front().timestamp, depth.back().timestamp));
  }
  std::vector<FrameRecord> frames;
  frames.reserve(pairs.size());
  for (const auto& [i, j] : pairs) {
    if (absent_images.isAbsent(rgb_file, rgb[i].line) ||
        absent_images.isAbsent(depth_file, depth[j].line)) {
      continue;
    }
    frames.push_back(makeFrame(folder, rgb[i], depth[j]));
  }
  return requireFrames(std::move(frames), rgb_file);
}

std::vector<FrameRecord> readFrames(const fs::path& folder, double max_difference,
                                    std::vector<AbsentImage>& absent) {
  for (const std::string_view name : kAssociationFiles) {
    if (pathExists(folder / name)) return framesFromAssociationList(folder / name, absent);
  }
  return framesFromColourAndDepthLists(folder, max_difference, absent);
}

void attachFrameImages(const FrameImageList& list, const fs::path& folder, double max_difference,
                       std::vector<FrameRecord>& frames) {
  const fs::path file = folder / list.file_name;
  if (!pathExists(file)) return;
  const auto entries = readCheckedImageList(folder, list.file_name);
  const auto pairs =
      associateTimestamps(timestampsOf(frames), timestampsOf(entries), max_difference);
  for (const auto& [i, j] : pairs) frames[i].*list.path = folder / entries[j].path;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    if (!(frames[i].*list.path)) {
      util::failAt(file, fmt::format("no {} within {} s of frame {} (colour timestamp {:.6f}, {})",
                                     list.what, max_difference, i, frames[i].timestamp,
                                     frames[i].rgb_path.string()));
    }
  }
}

std::optional<core::Trajectory> readGroundTruth(const fs::path& folder, GroundTruthFrame frame) {
  const fs::path file = folder / "groundtruth.txt";
  if (!pathExists(file)) return std::nullopt;
  return toCameraPoses(readTumTrajectory(file), frame);
}

struct CameraChoice {
  core::Camera camera;
  std::string source;
};

CameraChoice chooseCamera(const fs::path& folder, const DatasetOptions& options,
                          const std::vector<FrameRecord>& frames) {
  if (options.camera_file) {
    return {readCameraYaml(*options.camera_file), "file " + options.camera_file->string()};
  }
  if (options.camera_preset) {
    return {requireCameraPreset(*options.camera_preset), "preset " + *options.camera_preset};
  }
  const fs::path in_folder = folder / "camera.yaml";
  if (pathExists(in_folder)) {
    return {readCameraYaml(in_folder), "file " + in_folder.string() + " (in the dataset folder)"};
  }
  const fs::path calibration = folder / "calibration.txt";
  if (pathExists(calibration)) {
    const cv::Size size = readImageSize(frames.front().rgb_path);
    return {readCalibrationTxt(calibration, size.width, size.height),
            "file " + calibration.string() + " (ETH3D calibration in the dataset folder)"};
  }
  if (const auto preset = presetNameForDataset(folder)) {
    return {requireCameraPreset(*preset), "preset " + *preset + " (from folder name)"};
  }
  throw util::Error(fmt::format(
      "cannot tell which camera recorded {}: pass --camera FILE or --camera-preset NAME",
      folder.string()));
}

}  // namespace

TumDataset TumDataset::open(const fs::path& folder, const DatasetOptions& options) {
  requireFolder(folder);
  requireMaxTimeDifference(options.max_time_difference);
  TumDataset dataset;
  dataset.folder_ = folder;
  dataset.frames_ = readFrames(folder, options.max_time_difference, dataset.absent_images_);
  for (const auto& list : kFrameImageLists) {
    attachFrameImages(list, folder, options.max_time_difference, dataset.frames_);
  }
  dataset.ground_truth_frame_ =
      options.ground_truth_frame.value_or(groundTruthFrameForDataset(folder));
  dataset.ground_truth_ = readGroundTruth(folder, dataset.ground_truth_frame_);
  auto [camera, source] = chooseCamera(folder, options, dataset.frames_);
  dataset.camera_ = std::move(camera);
  dataset.camera_source_ = std::move(source);
  return dataset;
}

TumDataset TumDataset::startingAt(std::size_t first) const {
  if (first >= frames_.size()) {
    throw util::Error(fmt::format("{}: cannot start at frame {}: the sequence has {} frames",
                                  folder_.string(), first, frames_.size()));
  }
  TumDataset later = *this;
  later.frames_.erase(later.frames_.begin(),
                      later.frames_.begin() + static_cast<std::ptrdiff_t>(first));
  return later;
}

bool TumDataset::hasMasks() const {
  // open() gives either every frame a mask or none.
  return !frames_.empty() && frames_.front().mask_path.has_value();
}

RgbdFrame TumDataset::loadFrame(std::size_t i, FrameLayers layers) const {
  const FrameRecord& record = frames_.at(i);
  RgbdFrame frame;
  frame.timestamp = record.timestamp;
  frame.rgb = readColourImage(record.rgb_path, camera_);
  const cv::Size size = frame.rgb.size();
  frame.depth = readDepthImage(record.depth_path, camera_, size);
  if (layers.mask && record.mask_path) frame.mask = readMaskImage(*record.mask_path, size);
  if (layers.labels && record.labels_path) {
    frame.labels = readLabelImage(*record.labels_path, size);
  }
  if (layers.instances && record.instances_path) {
    frame.instances = readInstanceImage(*record.instances_path, size);
  }
  return frame;
}

}  // namespace segslam::io
