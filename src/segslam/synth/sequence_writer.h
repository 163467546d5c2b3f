#pragma once

#include <filesystem>
#include <string>

#include "segslam/synth/renderer.h"
#include "segslam/synth/sequence.h"

namespace segslam::synth {

// Writes a synthetic sequence in the TUM RGB-D layout into one folder:
// - rgb/<ts>.png (8-bit BGR), depth/<ts>.png (16-bit, z * 5000, 0 = no depth),
//   mask/<ts>.png (8-bit, 255 = dynamic object), labels/<ts>.png (8-bit core::SemanticClass),
//   instances/<ts>.png (16-bit instance id, 0 = none), <ts> = timestamp with 6 decimals;
// - rgb.txt, depth.txt, mask.txt, labels.txt, instances.txt: `timestamp path` lists;
// - groundtruth.txt: camera-to-world poses at exactly the rgb timestamps (TUM format);
// - camera.yaml: the camera settings;
// - dynamic_objects_gt.txt: `timestamp instance_id class_name x y z` for every object that is
//   dynamic at a frame, with the world position of its reference point (see scene.h);
// - meta.json: generator and version, all options, the camera, every object (instance id, class,
//   name, whether and in how many frames it is dynamic) and the class-name table.
// Any file that cannot be written throws util::Error naming it.
class SequenceWriter {
 public:
  // Creates the folder and its image folders.
  explicit SequenceWriter(std::filesystem::path folder);

  // Writes the five images of one frame; safe to call concurrently for different frames.
  void writeFrame(const SyntheticSequence& sequence, int frame, const FrameImages& images) const;

  // Writes every text file (lists, ground truth, camera, dynamic objects, meta.json).
  void writeMetadata(const SyntheticSequence& sequence) const;

  [[nodiscard]] const std::filesystem::path& folder() const { return folder_; }

 private:
  void writeImageList(const SyntheticSequence& sequence, const std::string& kind,
                      const std::string& description) const;
  void writeGroundTruth(const SyntheticSequence& sequence) const;
  void writeDynamicObjects(const SyntheticSequence& sequence) const;
  void writeMeta(const SyntheticSequence& sequence) const;

  std::filesystem::path folder_;
};

// Path of a frame's image relative to the sequence folder, e.g. "rgb/1700000000.033333.png".
std::string frameImagePath(const std::string& kind, double timestamp);

}  // namespace segslam::synth
