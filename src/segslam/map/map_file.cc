#include "segslam/map/map_file.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

#include "segslam/util/byte_stream.h"
#include "segslam/util/error.h"

namespace segslam::map {

namespace {

constexpr char kMagic[8] = {'S', 'E', 'G', 'S', 'L', 'M', 'A', 'P'};
constexpr std::uint32_t kSectionCount = 3;
// Section tags, in file order: the sensor and identity, keyframes, map points.
constexpr std::array<std::uint32_t, kSectionCount> kSectionTags = {0x52534E53,   // "SNSR"
                                                                   0x4D52464B,   // "KFRM"
                                                                   0x53544E50};  // "PNTS"
constexpr std::size_t kHeaderBytes = sizeof(kMagic) + 4 + 4 + kSectionCount * 12 + 8;
constexpr std::size_t kDescriptorBytes = 32;
constexpr std::size_t kKeypointBytes = 7 * 4 + 2 * 4 + 2 * 4 + kDescriptorBytes;
constexpr const char* kWhat = "map file";
// The least a keyframe (no keypoints, no neighbours, no place description) and a point (no
// observations) take.
constexpr std::size_t kMinKeyFrameBytes = 8 + 8 + 8 + 4 + 12 * 8 + 8 + 4 + 4 + 4;
constexpr std::size_t kMinPointBytes =
    8 + 8 + 4 + 6 * 8 + kDescriptorBytes + 2 * 8 + 8 + 4 + 4 + 1 + 4;

void putPose(util::ByteWriter& out, const geometry::Pose& pose) {
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) out.putF64(pose.matrix()(r, c));
  }
}

geometry::Pose getPose(util::ByteReader& in) {
  geometry::Pose pose = geometry::Pose::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) pose.matrix()(r, c) = in.getF64();
  }
  return pose;
}

// Finite, with a proper orthonormal rotation: a file edited and re-summed would otherwise put
// NaN or a shear into tracking.
bool isRigidMotion(const geometry::Pose& pose) {
  const Eigen::Matrix3d rotation = pose.linear();
  return pose.matrix().allFinite() &&
         ((rotation.transpose() * rotation) - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <
             1e-6 &&
         std::abs(rotation.determinant() - 1.0) < 1e-6;
}

void putVector(util::ByteWriter& out, const Eigen::Vector3d& v) {
  for (int i = 0; i < 3; ++i) out.putF64(v(i));
}

Eigen::Vector3d getVector(util::ByteReader& in) {
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) v(i) = in.getF64();
  return v;
}

std::string encodeSensor(const MapFileContents& contents) {
  util::ByteWriter out;
  const core::Camera& camera = contents.sensor.camera;
  out.putString(camera.name);
  out.putI32(camera.width);
  out.putI32(camera.height);
  for (double v : {camera.fx, camera.fy, camera.cx, camera.cy}) out.putF64(v);
  for (double v : camera.distortion) out.putF64(v);
  out.putF64(camera.depth_factor);
  out.putF64(camera.fps);
  out.putF64(contents.sensor.virtual_baseline_m);
  out.putF64(contents.sensor.close_depth_baselines);
  out.putI32(contents.sensor.pyramid_levels);
  out.putF64(contents.sensor.scale_factor);
  out.putString(contents.identity.vocabulary_file);
  out.putU64(contents.identity.vocabulary_hash);
  out.putString(contents.identity.place_recognition);
  out.putString(contents.identity.dense_map);
  return out.bytes();
}

void decodeSensor(util::ByteReader& in, MapFileContents& contents) {
  core::Camera& camera = contents.sensor.camera;
  camera.name = in.getString();
  camera.width = in.getI32();
  camera.height = in.getI32();
  for (double* v : {&camera.fx, &camera.fy, &camera.cx, &camera.cy}) *v = in.getF64();
  for (double& v : camera.distortion) v = in.getF64();
  camera.depth_factor = in.getF64();
  camera.fps = in.getF64();
  contents.sensor.virtual_baseline_m = in.getF64();
  contents.sensor.close_depth_baselines = in.getF64();
  contents.sensor.pyramid_levels = in.getI32();
  contents.sensor.scale_factor = in.getF64();
  contents.identity.vocabulary_file = in.getString();
  contents.identity.vocabulary_hash = in.getU64();
  contents.identity.place_recognition = in.getString();
  contents.identity.dense_map = in.getString();
  if (camera.width <= 0 || camera.height <= 0 || contents.sensor.pyramid_levels <= 0) {
    in.fail("camera size or pyramid levels not positive");
  }
}

void putKeyPoint(util::ByteWriter& out, const cv::KeyPoint& kp) {
  out.putF32(kp.pt.x);
  out.putF32(kp.pt.y);
  out.putF32(kp.size);
  out.putF32(kp.angle);
  out.putF32(kp.response);
  out.putI32(kp.octave);
  out.putI32(kp.class_id);
}

cv::KeyPoint getKeyPoint(util::ByteReader& in) {
  cv::KeyPoint kp;
  kp.pt.x = in.getF32();
  kp.pt.y = in.getF32();
  kp.size = in.getF32();
  kp.angle = in.getF32();
  kp.response = in.getF32();
  kp.octave = in.getI32();
  kp.class_id = in.getI32();
  return kp;
}

void encodeKeyFrame(util::ByteWriter& out, const SavedKeyFrame& k) {
  out.putU64(k.id);
  out.putU64(k.frame_id);
  out.putF64(k.timestamp);
  out.putU32(k.session);
  putPose(out, k.T_cw);
  out.putU64(k.parent);
  out.putU32(static_cast<std::uint32_t>(k.keypoints.size()));
  for (std::size_t i = 0; i < k.keypoints.size(); ++i) {
    putKeyPoint(out, k.keypoints[i]);
    out.putF32(k.keypoints_un[i].pt.x);
    out.putF32(k.keypoints_un[i].pt.y);
    out.putF32(k.depth[i]);
    out.putF32(k.right_u[i]);
    out.putBytes(k.descriptors.ptr(static_cast<int>(i)), kDescriptorBytes);
  }
  out.putU32(static_cast<std::uint32_t>(k.connections.size()));
  for (const auto& [other, weight] : k.connections) {
    out.putU64(other);
    out.putI32(weight);
  }
  out.putString(k.place_description);
}

SavedKeyFrame decodeKeyFrame(util::ByteReader& in, int pyramid_levels) {
  SavedKeyFrame k;
  k.id = in.getU64();
  k.frame_id = in.getU64();
  k.timestamp = in.getF64();
  k.session = in.getU32();
  k.T_cw = getPose(in);
  if (!isRigidMotion(k.T_cw))
    in.fail("keyframe " + std::to_string(k.id) + " has a pose that is not a rigid motion");
  k.parent = in.getU64();
  const std::size_t n = in.getCount(kKeypointBytes);
  k.keypoints.resize(n);
  k.keypoints_un.resize(n);
  k.depth.resize(n);
  k.right_u.resize(n);
  k.descriptors = cv::Mat(static_cast<int>(n), static_cast<int>(kDescriptorBytes), CV_8U);
  for (std::size_t i = 0; i < n; ++i) {
    k.keypoints[i] = getKeyPoint(in);
    if (k.keypoints[i].octave < 0 || k.keypoints[i].octave >= pyramid_levels) {
      in.fail("keyframe " + std::to_string(k.id) + " has a keypoint on pyramid level " +
              std::to_string(k.keypoints[i].octave));
    }
    k.keypoints_un[i] = k.keypoints[i];
    k.keypoints_un[i].pt.x = in.getF32();
    k.keypoints_un[i].pt.y = in.getF32();
    k.depth[i] = in.getF32();
    k.right_u[i] = in.getF32();
    in.getBytes(k.descriptors.ptr(static_cast<int>(i)), kDescriptorBytes);
  }
  const std::size_t connections = in.getCount(12);
  for (std::size_t c = 0; c < connections; ++c) {
    const std::uint64_t other = in.getU64();
    k.connections.emplace_back(other, in.getI32());
  }
  k.place_description = in.getString();
  return k;
}

void encodePoint(util::ByteWriter& out, const SavedMapPoint& p) {
  out.putU64(p.id);
  out.putU64(p.first_keyframe_id);
  out.putU32(p.session);
  putVector(out, p.position);
  putVector(out, p.normal);
  out.putBytes(p.descriptor.data(), p.descriptor.size());
  out.putF64(p.min_distance);
  out.putF64(p.max_distance);
  out.putU64(p.reference_keyframe);
  out.putI32(p.seen_through);
  out.putI32(p.moving_votes);
  out.putU8(p.provisional ? 1 : 0);
  out.putU32(static_cast<std::uint32_t>(p.observations.size()));
  for (const auto& [keyframe, index] : p.observations) {
    out.putU64(keyframe);
    out.putU32(index);
  }
}

SavedMapPoint decodePoint(util::ByteReader& in) {
  SavedMapPoint p;
  p.id = in.getU64();
  p.first_keyframe_id = in.getU64();
  p.session = in.getU32();
  p.position = getVector(in);
  p.normal = getVector(in);
  if (!p.position.allFinite() || !p.normal.allFinite()) {
    in.fail("point " + std::to_string(p.id) + " has a position or normal that is not finite");
  }
  in.getBytes(p.descriptor.data(), p.descriptor.size());
  p.min_distance = in.getF64();
  p.max_distance = in.getF64();
  if (!(p.min_distance >= 0.0 && p.min_distance <= p.max_distance &&
        std::isfinite(p.max_distance))) {
    in.fail("point " + std::to_string(p.id) + " has a viewing distance range that is not one");
  }
  p.reference_keyframe = in.getU64();
  p.seen_through = in.getI32();
  p.moving_votes = in.getI32();
  p.provisional = in.getU8() != 0;
  const std::size_t observations = in.getCount(12);
  for (std::size_t o = 0; o < observations; ++o) {
    const std::uint64_t keyframe = in.getU64();
    p.observations.emplace_back(keyframe, in.getU32());
  }
  return p;
}

std::string encodeKeyFrames(const MapFileContents& contents) {
  util::ByteWriter out;
  out.putU32(static_cast<std::uint32_t>(contents.keyframes.size()));
  for (const auto& k : contents.keyframes) encodeKeyFrame(out, k);
  return out.bytes();
}

std::string encodePoints(const MapFileContents& contents) {
  util::ByteWriter out;
  out.putU32(static_cast<std::uint32_t>(contents.points.size()));
  for (const auto& p : contents.points) encodePoint(out, p);
  return out.bytes();
}

// Every id a keyframe or point refers to must be one of the file's keyframes, and every
// keypoint index within its keyframe: the loader builds pointers from them.
void checkReferences(const MapFileContents& contents, util::ByteReader& in) {
  std::map<std::uint64_t, std::size_t> keypoints_of;
  for (const auto& k : contents.keyframes) {
    if (!keypoints_of.emplace(k.id, k.keypoints.size()).second) {
      in.fail("keyframe " + std::to_string(k.id) + " appears twice");
    }
  }
  const auto known = [&](std::uint64_t id) { return keypoints_of.count(id) > 0; };
  for (const auto& k : contents.keyframes) {
    if (k.parent != kNoKeyFrame && !known(k.parent)) {
      in.fail("keyframe " + std::to_string(k.id) + " has an unknown parent");
    }
    for (const auto& [other, weight] : k.connections) {
      if (!known(other)) in.fail("keyframe " + std::to_string(k.id) + " has an unknown neighbour");
    }
  }
  std::set<std::uint64_t> point_ids;
  for (const auto& p : contents.points) {
    if (!point_ids.insert(p.id).second) in.fail("point " + std::to_string(p.id) + " twice");
    if (p.reference_keyframe != kNoKeyFrame && !known(p.reference_keyframe)) {
      in.fail("point " + std::to_string(p.id) + " has an unknown reference keyframe");
    }
    for (const auto& [keyframe, index] : p.observations) {
      if (!known(keyframe) || index >= keypoints_of[keyframe]) {
        in.fail("point " + std::to_string(p.id) + " has an observation out of range");
      }
    }
  }
}

void requireFullyRead(const util::ByteReader& in, const char* section) {
  if (in.remaining() != 0) {
    in.fail(std::string(section) + " section has " + std::to_string(in.remaining()) +
            " bytes left over");
  }
}

// Checks the magic, version, section table, size and checksum; returns the section sizes.
std::array<std::uint64_t, kSectionCount> checkHeaderAndPayload(std::string_view bytes,
                                                               const std::filesystem::path& file) {
  util::ByteReader header(bytes, file, kWhat);
  char magic[sizeof(kMagic)];
  header.getBytes(magic, sizeof(magic));
  if (std::memcmp(magic, kMagic, sizeof(kMagic)) != 0) {
    util::failAt(file, "not a segslam map file (no SEGSLMAP magic)");
  }
  const std::uint32_t version = header.getU32();
  if (version != kMapFileVersion) {
    util::failAt(file, "map file version " + std::to_string(version) +
                           " (this build reads version " + std::to_string(kMapFileVersion) + ")");
  }
  if (header.getU32() != kSectionCount) header.fail("unexpected number of sections");
  std::array<std::uint64_t, kSectionCount> sizes{};
  std::uint64_t payload_size = 0;
  for (std::size_t s = 0; s < kSectionCount; ++s) {
    if (header.getU32() != kSectionTags[s]) header.fail("unexpected section tag");
    sizes[s] = header.getU64();
    if (sizes[s] > bytes.size()) {
      util::failAt(file, "truncated map file (" + std::to_string(bytes.size()) +
                             " bytes, a section of " + std::to_string(sizes[s]) + ")");
    }
    payload_size += sizes[s];
  }
  const std::uint64_t checksum = header.getU64();
  const std::string_view payload = bytes.substr(kHeaderBytes);
  if (payload.size() < payload_size) {
    util::failAt(file, "truncated map file (" + std::to_string(bytes.size()) + " bytes of " +
                           std::to_string(kHeaderBytes + payload_size) + ")");
  }
  if (payload.size() > payload_size) header.fail("bytes after the last section");
  if (util::fnv1a64(payload) != checksum) {
    util::failAt(file, "map file fails its checksum (corrupt or edited)");
  }
  return sizes;
}

}  // namespace

std::string encodeMapFile(const MapFileContents& contents) {
  const std::array<std::string, kSectionCount> sections = {
      encodeSensor(contents), encodeKeyFrames(contents), encodePoints(contents)};
  std::string payload;
  for (const auto& section : sections) payload += section;
  util::ByteWriter out;
  out.putBytes(kMagic, sizeof(kMagic));
  out.putU32(kMapFileVersion);
  out.putU32(kSectionCount);
  for (std::size_t s = 0; s < kSectionCount; ++s) {
    out.putU32(kSectionTags[s]);
    out.putU64(sections[s].size());
  }
  out.putU64(util::fnv1a64(payload));
  return out.bytes() + payload;
}

MapFileContents decodeMapFile(std::string_view bytes, const std::filesystem::path& file) {
  const auto sizes = checkHeaderAndPayload(bytes, file);
  const std::string_view payload = bytes.substr(kHeaderBytes);
  MapFileContents contents;
  std::size_t offset = 0;
  const auto section = [&](std::size_t s) {
    const auto view = payload.substr(offset, sizes[s]);
    offset += sizes[s];
    return util::ByteReader(view, file, kWhat);
  };
  auto sensor = section(0);
  decodeSensor(sensor, contents);
  requireFullyRead(sensor, "sensor");
  auto keyframes = section(1);
  contents.keyframes.resize(keyframes.getCount(kMinKeyFrameBytes));
  for (auto& k : contents.keyframes) k = decodeKeyFrame(keyframes, contents.sensor.pyramid_levels);
  requireFullyRead(keyframes, "keyframe");
  auto points = section(2);
  contents.points.resize(points.getCount(kMinPointBytes));
  for (auto& p : contents.points) p = decodePoint(points);
  requireFullyRead(points, "point");
  checkReferences(contents, points);
  return contents;
}

void writeMapFile(const std::filesystem::path& file, const MapFileContents& contents) {
  const std::string bytes = encodeMapFile(contents);
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) util::failAt(file, "cannot write map file");
}

MapFileContents readMapFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) util::failAt(file, "cannot open map file");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) util::failAt(file, "cannot read map file");
  return decodeMapFile(bytes, file);
}

}  // namespace segslam::map
