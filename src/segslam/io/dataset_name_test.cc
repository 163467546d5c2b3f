#include "segslam/io/dataset_name.h"

#include <gtest/gtest.h>

namespace segslam::io {
namespace {

TEST(DatasetName, FolderNameIsLowerCaseAndIgnoresATrailingSlash) {
  EXPECT_EQ(datasetFolderName("/data/RGBD_Bonn_Crowd/"), "rgbd_bonn_crowd");
  EXPECT_EQ(datasetFolderName("relative/tum_fr1_xyz_300"), "tum_fr1_xyz_300");
}

TEST(DatasetName, TokensAreWordsOfTheirOwn) {
  EXPECT_TRUE(hasNameToken("rgbd_bonn_crowd", "bonn"));
  EXPECT_TRUE(hasNameToken("bonn", "bonn"));
  EXPECT_TRUE(hasNameToken("bonn2", "bonn"));
  EXPECT_FALSE(hasNameToken("bonnet", "bonn"));
  EXPECT_FALSE(hasNameToken("xbonn", "bonn"));
  EXPECT_TRUE(hasNameToken("tum_fr1_xyz", "fr1"));
  EXPECT_TRUE(hasNameToken("fr1xyz", "fr1"));
  EXPECT_FALSE(hasNameToken("fr12", "fr1"));
  EXPECT_FALSE(hasNameToken("afr1", "fr1"));
  EXPECT_TRUE(hasNameToken("afr1_fr1", "fr1"));
  EXPECT_FALSE(hasNameToken("anything", ""));
}

}  // namespace
}  // namespace segslam::io
