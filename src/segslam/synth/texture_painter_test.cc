#include "segslam/synth/texture_painter.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

namespace segslam::synth {
namespace {

constexpr Material kAllMaterials[] = {
    Material::kWallpaper, Material::kFloorPlanks, Material::kCeilingTiles, Material::kWood,
    Material::kLaminate,  Material::kCardboard,   Material::kBook,         Material::kScreen,
    Material::kFabric,    Material::kShirt,       Material::kTrousers,     Material::kSkin,
    Material::kShoes};

const cv::Size kOneMetre(223, 223);

TEST(SynthTexturePainter, SameSeedSameImageOtherSeedOtherImage) {
  for (Material material : kAllMaterials) {
    const cv::Mat a = paintTexture(material, kOneMetre, kTexelSize, 7);
    const cv::Mat b = paintTexture(material, kOneMetre, kTexelSize, 7);
    const cv::Mat c = paintTexture(material, kOneMetre, kTexelSize, 8);
    ASSERT_EQ(a.type(), CV_8UC3);
    ASSERT_EQ(a.size(), kOneMetre);
    EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0) << static_cast<int>(material);
    EXPECT_GT(cv::norm(a, c, cv::NORM_L1), 0.0) << static_cast<int>(material);
  }
}

// ORB needs corners everywhere: in nearly every 25 cm cell of a square metre of any material
// (seen at about 1 m, where a texel is about one pixel) FAST must find corners.
TEST(SynthTexturePainter, EveryMaterialHasCornersEverywhere) {
  for (Material material : kAllMaterials) {
    const cv::Mat image = paintTexture(material, kOneMetre, kTexelSize, 3);
    cv::Mat grey;
    cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
    std::vector<cv::KeyPoint> corners;
    cv::FAST(grey, corners, 20, true);
    constexpr int kCells = 4;
    int cells_with_corners[kCells][kCells] = {};
    for (const auto& corner : corners) {
      const int i = std::min(kCells - 1, static_cast<int>(corner.pt.x * kCells / grey.cols));
      const int j = std::min(kCells - 1, static_cast<int>(corner.pt.y * kCells / grey.rows));
      ++cells_with_corners[i][j];
    }
    int covered = 0;
    for (const auto& column : cells_with_corners) {
      for (int count : column) covered += count > 0 ? 1 : 0;
    }
    EXPECT_GE(covered, kCells * kCells - 2) << "material " << static_cast<int>(material);
    EXPECT_GE(corners.size(), 40u) << "material " << static_cast<int>(material);
  }
}

TEST(SynthTexturePainter, TinyAndOddSizesWork) {
  EXPECT_EQ(paintTexture(Material::kBook, cv::Size(1, 1), kTexelSize, 1).size(), cv::Size(1, 1));
  EXPECT_EQ(paintTexture(Material::kWood, cv::Size(3, 200), kTexelSize, 1).size(),
            cv::Size(3, 200));
}

}  // namespace
}  // namespace segslam::synth
