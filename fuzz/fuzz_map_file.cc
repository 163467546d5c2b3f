// map::decodeMapFile either throws util::Error or returns contents the loader can build a map
// from: consistent keyframes (as many keypoints, undistorted keypoints, depths and descriptors),
// rigid poses, finite points, observations of keypoints the file holds; and they encode to bytes
// that decode to the same contents. The checksum is recomputed over the payload before a second
// decode, so that mutations reach the sections instead of stopping at the checksum.

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>

#include "fuzz_check.h"
#include "segslam/map/map_file.h"
#include "segslam/util/byte_stream.h"
#include "segslam/util/error.h"

namespace {

using segslam::fuzz::check;
namespace map = segslam::map;

constexpr std::size_t kChecksumOffset = 52;  // magic, version, section count, 3 sections
constexpr std::size_t kHeaderBytes = kChecksumOffset + 8;

bool isRigidMotion(const segslam::geometry::Pose& pose) {
  const Eigen::Matrix3d rotation = pose.linear();
  return pose.matrix().allFinite() &&
         ((rotation.transpose() * rotation) - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <
             1e-5 &&
         std::abs(rotation.determinant() - 1.0) < 1e-5;
}

void checkContents(const map::MapFileContents& contents) {
  std::map<std::uint64_t, std::size_t> keypoints_of;
  for (const auto& k : contents.keyframes) {
    const std::size_t n = k.keypoints.size();
    check(
        k.keypoints_un.size() == n && k.depth.size() == n && k.right_u.size() == n,
        "a keyframe has as many undistorted keypoints, depths and right coordinates as keypoints");
    check(static_cast<std::size_t>(k.descriptors.rows) == n && k.descriptors.cols == 32,
          "a keyframe has one 32-byte descriptor per keypoint");
    for (const auto& kp : k.keypoints) {
      check(kp.octave >= 0 && kp.octave < contents.sensor.pyramid_levels,
            "keypoints lie on the pyramid's levels");
    }
    check(isRigidMotion(k.T_cw), "keyframe poses are rigid motions");
    check(keypoints_of.emplace(k.id, n).second, "keyframe ids are unique");
  }
  for (const auto& p : contents.points) {
    check(p.position.allFinite() && p.normal.allFinite(), "points are finite");
    for (const auto& [keyframe, index] : p.observations) {
      const auto found = keypoints_of.find(keyframe);
      check(found != keypoints_of.end() && index < found->second,
            "observations name keypoints of the file's keyframes");
    }
  }
}

void decodeAndCheck(const std::string& bytes) {
  try {
    const auto contents = map::decodeMapFile(bytes, "fuzz.map");
    checkContents(contents);
    const std::string encoded = map::encodeMapFile(contents);
    check(map::encodeMapFile(map::decodeMapFile(encoded, "fuzz.map")) == encoded,
          "what decodes encodes to bytes that decode to the same contents");
  } catch (const segslam::util::Error&) {
    // Rejected input, with a message: the expected outcome for most inputs.
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string bytes(reinterpret_cast<const char*>(data), size);
  decodeAndCheck(bytes);
  if (bytes.size() >= kHeaderBytes) {
    std::uint64_t checksum = segslam::util::fnv1a64(std::string_view(bytes).substr(kHeaderBytes));
    for (std::size_t i = 0; i < 8; ++i, checksum >>= 8) {
      bytes[kChecksumOffset + i] = static_cast<char>(checksum & 0xff);
    }
    decodeAndCheck(bytes);
  }
  return 0;
}
