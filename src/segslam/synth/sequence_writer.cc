#include "segslam/synth/sequence_writer.h"

#include <fmt/format.h>
#include <fmt/os.h>

#include <array>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "segslam/io/camera_config.h"
#include "segslam/io/trajectory_io.h"
#include "segslam/synth/room_layout.h"
#include "segslam/util/error.h"

namespace segslam::synth {

namespace {

constexpr int kGeneratorVersion = 1;
constexpr const char* kGenerator = "segslam synth";
constexpr const char* kDynamicDefinition =
    "an object is dynamic at frame k when its world pose at k differs from its pose at k-1 or "
    "k+1 (limb motion included); mask pixels show exactly the dynamic objects";

struct ImageKind {
  const char* name;
  const char* description;
};

constexpr std::array<ImageKind, 5> kImageKinds{{
    {"rgb", "color images (8-bit BGR)"},
    {"depth", "depth images (16-bit, metres * 5000, 0 = no depth)"},
    {"mask", "dynamic-object masks (8-bit, 255 = dynamic)"},
    {"labels", "semantic class ids (8-bit, see meta.json)"},
    {"instances", "instance ids (16-bit, 0 = none, see meta.json)"},
}};

void writeImage(const std::filesystem::path& file, const cv::Mat& image) {
  bool written = false;
  try {
    written = cv::imwrite(file.string(), image);
  } catch (const cv::Exception& e) {
    util::failAt(file, fmt::format("cannot write image: {}", e.what()));
  }
  if (!written) util::failAt(file, "cannot write image");
}

// Opens a text file for writing; util::Error naming it when that fails.
fmt::ostream openText(const std::filesystem::path& file) {
  try {
    return fmt::output_file(file.string());
  } catch (const std::system_error& e) {
    util::failAt(file, fmt::format("cannot write: {}", e.what()));
  }
}

nlohmann::json optionsJson(const SynthOptions& options) {
  return {{"frames", options.frames},
          {"width", options.width},
          {"height", options.height},
          {"path", options.path},
          {"laps", options.laps},
          {"people", options.people},
          {"person_speed", options.person_speed},
          {"person_size", options.person_size},
          {"moved_furniture", options.moved_furniture},
          {"depth_noise", options.depth_noise},
          {"seed", options.seed}};
}

nlohmann::json cameraJson(const core::Camera& camera) {
  return {{"width", camera.width},
          {"height", camera.height},
          {"fx", camera.fx},
          {"fy", camera.fy},
          {"cx", camera.cx},
          {"cy", camera.cy},
          {"depth_factor", camera.depth_factor},
          {"fps", camera.fps}};
}

nlohmann::json objectsJson(const SyntheticSequence& sequence) {
  nlohmann::json objects = nlohmann::json::array();
  for (const SceneObject& object : sequence.scene().objects()) {
    int dynamic_frames = 0;
    for (int k = 0; k < sequence.frameCount(); ++k) {
      if (sequence.scene().isDynamic(object.instance, k)) ++dynamic_frames;
    }
    objects.push_back({{"instance_id", object.instance},
                       {"class", std::string(core::semanticClassName(object.semantic_class))},
                       {"class_id", static_cast<int>(object.semantic_class)},
                       {"name", object.name},
                       {"dynamic", dynamic_frames > 0},
                       {"dynamic_frames", dynamic_frames}});
  }
  return objects;
}

nlohmann::json classesJson() {
  nlohmann::json classes = nlohmann::json::array();
  for (std::size_t id = 0; id < core::kSemanticClassNames.size(); ++id) {
    classes.push_back({{"id", id}, {"name", std::string(core::kSemanticClassNames[id])}});
  }
  return classes;
}

}  // namespace

std::string frameImagePath(const std::string& kind, double timestamp) {
  return fmt::format("{}/{:.6f}.png", kind, timestamp);
}

SequenceWriter::SequenceWriter(std::filesystem::path folder) : folder_(std::move(folder)) {
  for (const ImageKind& kind : kImageKinds) {
    std::error_code error;
    std::filesystem::create_directories(folder_ / kind.name, error);
    if (error) util::failAt(folder_ / kind.name, "cannot create folder: " + error.message());
  }
}

void SequenceWriter::writeFrame(const SyntheticSequence& sequence, int frame,
                                const FrameImages& images) const {
  const double timestamp = sequence.timestamp(frame);
  writeImage(folder_ / frameImagePath("rgb", timestamp), images.rgb);
  writeImage(folder_ / frameImagePath("depth", timestamp), images.depth);
  writeImage(folder_ / frameImagePath("mask", timestamp), images.mask);
  writeImage(folder_ / frameImagePath("labels", timestamp), images.labels);
  writeImage(folder_ / frameImagePath("instances", timestamp), images.instances);
}

void SequenceWriter::writeMetadata(const SyntheticSequence& sequence) const {
  for (const ImageKind& kind : kImageKinds) writeImageList(sequence, kind.name, kind.description);
  writeGroundTruth(sequence);
  io::writeCameraYaml(folder_ / "camera.yaml", sequence.camera());
  writeDynamicObjects(sequence);
  writeMeta(sequence);
}

void SequenceWriter::writeImageList(const SyntheticSequence& sequence, const std::string& kind,
                                    const std::string& description) const {
  const auto file = folder_ / (kind + ".txt");
  auto out = openText(file);
  out.print("# {}\n# generated by {} (seed {})\n# timestamp filename\n", description, kGenerator,
            sequence.options().seed);
  for (int k = 0; k < sequence.frameCount(); ++k) {
    const double timestamp = sequence.timestamp(k);
    out.print("{:.6f} {}\n", timestamp, frameImagePath(kind, timestamp));
  }
}

void SequenceWriter::writeGroundTruth(const SyntheticSequence& sequence) const {
  core::Trajectory trajectory;
  for (int k = 0; k < sequence.frameCount(); ++k) {
    trajectory.append(sequence.timestamp(k), sequence.cameraPose(k));
  }
  io::writeTumTrajectory(folder_ / "groundtruth.txt", trajectory,
                         fmt::format("ground truth trajectory of {} (exact)", kGenerator));
}

void SequenceWriter::writeDynamicObjects(const SyntheticSequence& sequence) const {
  auto out = openText(folder_ / "dynamic_objects_gt.txt");
  out.print("# objects dynamic at each frame ({})\n", kDynamicDefinition);
  out.print("# x y z: world position of the object's reference point (base centre on the floor)\n");
  out.print("# timestamp instance_id class_name x y z\n");
  for (int k = 0; k < sequence.frameCount(); ++k) {
    for (const ObjectPosition& object : sequence.scene().dynamicObjectsAt(k)) {
      out.print("{:.6f} {} {} {:.6f} {:.6f} {:.6f}\n", sequence.timestamp(k), object.instance,
                core::semanticClassName(object.semantic_class), object.position.x(),
                object.position.y(), object.position.z());
    }
  }
}

void SequenceWriter::writeMeta(const SyntheticSequence& sequence) const {
  const Eigen::AlignedBox3d room = roomBox();
  const nlohmann::json meta = {
      {"generator", kGenerator},
      {"generator_version", kGeneratorVersion},
      {"segslam_version", SEGSLAM_VERSION},
      {"options", optionsJson(sequence.options())},
      {"camera", cameraJson(sequence.camera())},
      {"frame_count", sequence.frameCount()},
      {"start_timestamp", kSynthStartTimestamp},
      {"world_frame",
       "z up, floor at z = 0; poses are camera-to-world (camera x right, y down, "
       "z forward)"},
      {"room",
       {{"min", {room.min().x(), room.min().y(), room.min().z()}},
        {"max", {room.max().x(), room.max().y(), room.max().z()}}}},
      {"dynamic_definition", kDynamicDefinition},
      {"objects", objectsJson(sequence)},
      {"classes", classesJson()},
  };
  auto out = openText(folder_ / "meta.json");
  out.print("{}\n", meta.dump(2));
}

}  // namespace segslam::synth
