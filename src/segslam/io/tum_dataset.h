#pragma once

#include <cstddef>
#include <filesystem>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "segslam/core/camera.h"
#include "segslam/core/trajectory.h"
#include "segslam/io/ground_truth_frame.h"

namespace segslam::io {

struct DatasetOptions {
  // Maximum |t_rgb - t_depth| (seconds) when associating colour and depth, as the TUM tools; also
  // used to find each frame's mask, label and instance images. Must be positive.
  double max_time_difference = 0.02;
  // Camera settings, in order of precedence: an explicit YAML file, an explicit preset name,
  // `camera.yaml` inside the dataset folder, an ETH3D `calibration.txt` inside it, the TUM preset
  // named by the folder ("fr1", ...).
  std::optional<std::filesystem::path> camera_file;
  std::optional<std::string> camera_preset;
  // What groundtruth.txt holds poses of; by default as the folder's name tells
  // (groundTruthFrameForDataset: a Bonn sequence's marker poses).
  std::optional<GroundTruthFrame> ground_truth_frame;
};

// An image that a list names and the sequence does not contain.
struct AbsentImage {
  std::filesystem::path list_file;
  int line = 0;
  std::filesystem::path path;
};

// One associated RGB-D frame of the sequence (paths are resolved against the dataset folder).
struct FrameRecord {
  double timestamp = 0.0;  // colour image timestamp: the frame's timestamp
  std::filesystem::path rgb_path;
  double depth_timestamp = 0.0;
  std::filesystem::path depth_path;
  std::optional<std::filesystem::path> mask_path;       // from mask.txt
  std::optional<std::filesystem::path> labels_path;     // from labels.txt (semantic class ids)
  std::optional<std::filesystem::path> instances_path;  // from instances.txt (instance ids)
};

// Images of one frame, validated against the camera settings.
struct RgbdFrame {
  double timestamp = 0.0;
  cv::Mat rgb;        // CV_8UC3, BGR (8-bit grey and BGRA files are converted)
  cv::Mat depth;      // CV_32FC1, metres, 0 = no measurement
  cv::Mat mask;       // CV_8UC1, 255 = dynamic, 0 = static; empty when the dataset has no masks
  cv::Mat labels;     // CV_8UC1 core::SemanticClass ids; empty when absent
  cv::Mat instances;  // CV_16UC1 instance ids, 0 = none; empty when absent
};

// Which of a frame's optional ground-truth images to load (colour and depth always are). Decoding
// a mask costs as much as a third of a depth image: a run that does not use them skips them.
struct FrameLayers {
  bool mask = true;
  bool labels = true;
  bool instances = true;
};

// A sequence in the TUM RGB-D layout (also that of the Bonn RGB-D Dynamic dataset and, with
// associated.txt and calibration.txt, of the ETH3D SLAM benchmark):
// - rgb.txt and depth.txt (`timestamp path` per line), associated by nearest timestamp exactly
//   as the TUM tools do; or associations.txt or else associated.txt (associate.py output,
//   `t_rgb rgb_path t_depth depth_path`), which then alone defines the frames;
// - optional groundtruth.txt (TUM trajectory), converted to camera poses where it holds others
//   (DatasetOptions::ground_truth_frame);
// - optional mask.txt, labels.txt, instances.txt (`timestamp path`), matched to the frames by
//   timestamp the same way; when such a list exists, every frame must have an entry in it;
// - optional camera.yaml (see DatasetOptions for the camera precedence).
// - optional calibration.txt (ETH3D: `fx fy cx cy`), the camera when no camera.yaml is there.
// Lists are read as the TUM tools read them (util::keyRowsByTimestamp): a duplicated timestamp's
// later line wins and lines out of order are sorted, with a warning naming the list.
// Opening parses and validates every list file and checks that every listed file exists, without
// decoding any image (but the first colour image when calibration.txt gives the camera, for its
// size); any problem throws util::Error naming the file and line. Colour and depth images that
// their lists name but the folder lacks are the exception, as published sequences have them:
// the lists are associated as written, the frames of absent images are left out with a warning
// naming each image (absentImages()), and only a list whose images are mostly absent is an error.
class TumDataset {
 public:
  static TumDataset open(const std::filesystem::path& folder, const DatasetOptions& options = {});

  [[nodiscard]] const std::filesystem::path& folder() const { return folder_; }
  [[nodiscard]] const core::Camera& camera() const { return camera_; }
  // Human-readable origin of the camera settings, e.g. "preset freiburg1 (from folder name)".
  [[nodiscard]] const std::string& cameraSource() const { return camera_source_; }
  [[nodiscard]] const std::vector<FrameRecord>& frames() const { return frames_; }
  [[nodiscard]] std::size_t size() const { return frames_.size(); }
  // Camera poses (converted from groundTruthFrame() where the file holds others).
  [[nodiscard]] const std::optional<core::Trajectory>& groundTruth() const { return ground_truth_; }
  [[nodiscard]] GroundTruthFrame groundTruthFrame() const { return ground_truth_frame_; }
  [[nodiscard]] const std::vector<AbsentImage>& absentImages() const { return absent_images_; }
  [[nodiscard]] bool hasMasks() const;

  // Loads and validates the images of frame i: wrong image types and sizes throw util::Error
  // naming the image file, and damaged images (cut short, undecodable) DamagedImageError naming
  // it, so that a player can skip the frame. i >= size() throws std::out_of_range. Of the
  // optional images, only those `layers` asks for are loaded.
  [[nodiscard]] RgbdFrame loadFrame(std::size_t i, FrameLayers layers = {}) const;

  // The same sequence from frame `first` on (a camera switched on at that moment); util::Error
  // when it has no frame `first`.
  [[nodiscard]] TumDataset startingAt(std::size_t first) const;

 private:
  std::filesystem::path folder_;
  core::Camera camera_;
  std::string camera_source_;
  std::vector<FrameRecord> frames_;
  std::optional<core::Trajectory> ground_truth_;
  GroundTruthFrame ground_truth_frame_ = GroundTruthFrame::kCamera;
  std::vector<AbsentImage> absent_images_;
};

}  // namespace segslam::io
