#include "segslam/map/map_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"

namespace segslam::map {
namespace {

using testing::ScopedTempDir;

MapFileContents twoKeyFrameMap() {
  MapFileContents contents;
  contents.sensor.camera.width = 320;
  contents.sensor.camera.height = 240;
  contents.sensor.virtual_baseline_m = 0.076;
  contents.sensor.close_depth_baselines = 40.0;
  contents.sensor.pyramid_levels = 8;
  contents.sensor.scale_factor = 1.2;
  contents.identity = {"config/vocabulary.bin", 0x1234, "bow", "/runs/a/map"};
  for (std::uint64_t id : {0, 3}) {
    SavedKeyFrame k;
    k.id = id;
    k.frame_id = 10 * id;
    k.timestamp = 1.5 + static_cast<double>(id);
    k.session = id == 0 ? 0 : 1;
    k.T_cw.translation() = Eigen::Vector3d(0.1 * static_cast<double>(id), 0.2, 0.3);
    k.parent = id == 0 ? kNoKeyFrame : 0;
    for (int i = 0; i < 3; ++i) {
      k.keypoints.emplace_back(10.0f * static_cast<float>(i), 5.0f, 7.0f, 45.0f, 0.5f, i);
      k.keypoints_un.push_back(k.keypoints.back());
      k.keypoints_un.back().pt.x += 0.25f;
      k.depth.push_back(1.0f + static_cast<float>(i));
      k.right_u.push_back(-1.0f);
    }
    k.descriptors = cv::Mat(3, 32, CV_8U, cv::Scalar(static_cast<double>(id + 7)));
    k.connections = {{id == 0 ? 3U : 0U, 20}};
    if (id == 0) k.place_description = std::string("cnn\0features", 12);
    contents.keyframes.push_back(k);
  }
  SavedMapPoint p;
  p.id = 5;
  p.position = Eigen::Vector3d(1.0, 2.0, 3.0);
  p.normal = Eigen::Vector3d(0.0, 0.0, 1.0);
  p.descriptor.fill(9);
  p.reference_keyframe = 0;
  p.seen_through = 1;
  p.observations = {{0, 2}, {3, 1}};
  contents.points.push_back(p);
  return contents;
}

std::string errorOf(const std::string& bytes, const std::filesystem::path& file = "maps/a.map") {
  try {
    decodeMapFile(bytes, file);
  } catch (const util::Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(MapFile, DecodesWhatItEncodedAndEncodesItAgainByteForByte) {
  const auto bytes = encodeMapFile(twoKeyFrameMap());
  const auto decoded = decodeMapFile(bytes, "a.map");
  ASSERT_EQ(decoded.keyframes.size(), 2U);
  EXPECT_EQ(decoded.keyframes[1].id, 3U);
  EXPECT_EQ(decoded.keyframes[1].parent, 0U);
  EXPECT_EQ(decoded.keyframes[1].session, 1U);
  EXPECT_FLOAT_EQ(decoded.keyframes[1].keypoints_un[0].pt.x, 0.25f);
  EXPECT_EQ(decoded.keyframes[1].keypoints[2].octave, 2);
  EXPECT_EQ(decoded.keyframes[1].descriptors.at<std::uint8_t>(2, 31), 10);
  EXPECT_EQ(decoded.keyframes[0].place_description, std::string("cnn\0features", 12));
  EXPECT_TRUE(decoded.keyframes[1].place_description.empty());
  EXPECT_EQ(decoded.identity.dense_map, "/runs/a/map");
  EXPECT_EQ(decoded.identity.vocabulary_hash, 0x1234U);
  ASSERT_EQ(decoded.points.size(), 1U);
  EXPECT_EQ(decoded.points[0].observations[1], (std::pair<std::uint64_t, std::uint32_t>{3, 1}));
  EXPECT_EQ(decoded.points[0].seen_through, 1);
  EXPECT_EQ(encodeMapFile(decoded), bytes);
}

TEST(MapFile, ATruncatedFileIsNamedAsTruncated) {
  const auto bytes = encodeMapFile(twoKeyFrameMap());
  for (std::size_t size : {std::size_t{0}, std::size_t{10}, bytes.size() / 2, bytes.size() - 1}) {
    const auto error = errorOf(bytes.substr(0, size));
    EXPECT_TRUE(error.starts_with("maps/a.map: ")) << error;
    EXPECT_NE(error.find("truncated"), std::string::npos) << size << ": " << error;
  }
}

TEST(MapFile, AFlippedBitFailsTheChecksum) {
  auto bytes = encodeMapFile(twoKeyFrameMap());
  bytes[bytes.size() - 20] ^= 0x10;
  EXPECT_EQ(errorOf(bytes), "maps/a.map: map file fails its checksum (corrupt or edited)");
}

TEST(MapFile, AnotherVersionOrAnotherKindOfFileIsRefused) {
  auto bytes = encodeMapFile(twoKeyFrameMap());
  bytes[8] = 2;
  EXPECT_EQ(errorOf(bytes), "maps/a.map: map file version 2 (this build reads version 1)");
  EXPECT_EQ(errorOf("SEGSBOWV and more bytes than the header needs, to be sure of it"),
            "maps/a.map: not a segslam map file (no SEGSLMAP magic)");
}

TEST(MapFile, AReferenceToAKeyFrameTheFileDoesNotHoldIsCorruption) {
  auto contents = twoKeyFrameMap();
  contents.points[0].observations.emplace_back(99, 0);
  const auto error = errorOf(encodeMapFile(contents));
  EXPECT_NE(error.find("corrupt map file: point 5 has an observation out of range"),
            std::string::npos)
      << error;
  contents = twoKeyFrameMap();
  contents.points[0].observations[0].second = 3;  // the keyframe has 3 keypoints
  EXPECT_NE(errorOf(encodeMapFile(contents)).find("out of range"), std::string::npos);
}

TEST(MapFile, APoseOrPointThatIsNotGeometryIsCorruption) {
  auto contents = twoKeyFrameMap();
  contents.keyframes[1].T_cw.matrix()(0, 1) = 0.5;  // a shear
  EXPECT_NE(
      errorOf(encodeMapFile(contents)).find("keyframe 3 has a pose that is not a rigid motion"),
      std::string::npos);
  contents = twoKeyFrameMap();
  contents.keyframes[0].T_cw.translation().x() = std::nan("");
  EXPECT_NE(errorOf(encodeMapFile(contents)).find("not a rigid motion"), std::string::npos);
  contents = twoKeyFrameMap();
  contents.points[0].position.z() = INFINITY;
  EXPECT_NE(errorOf(encodeMapFile(contents)).find("point 5 has a position or normal that is not"),
            std::string::npos);
  contents = twoKeyFrameMap();
  contents.points[0].min_distance = 2.0;
  contents.points[0].max_distance = 1.0;
  EXPECT_NE(errorOf(encodeMapFile(contents)).find("viewing distance"), std::string::npos);
}

TEST(MapFile, WritesAndReadsFiles) {
  const ScopedTempDir dir;
  const auto file = dir.path() / "a.map";
  writeMapFile(file, twoKeyFrameMap());
  EXPECT_EQ(encodeMapFile(readMapFile(file)), encodeMapFile(twoKeyFrameMap()));
  try {
    readMapFile(dir.path() / "missing.map");
    FAIL() << "no error";
  } catch (const util::Error& e) {
    EXPECT_EQ(std::string(e.what()),
              (dir.path() / "missing.map").string() + ": cannot open map file");
  }
}

}  // namespace
}  // namespace segslam::map
