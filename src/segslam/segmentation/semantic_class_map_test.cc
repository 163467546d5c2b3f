#include "segslam/segmentation/semantic_class_map.h"

#include <gtest/gtest.h>

#include "segslam/segmentation/model_config.h"

namespace segslam::segmentation {
namespace {

using core::SemanticClass;

TEST(SemanticClassMap, VocIndoorClassesBecomeObjectLabels) {
  EXPECT_EQ(semanticClassOfModelClass("tvmonitor"), SemanticClass::kMonitor);
  EXPECT_EQ(semanticClassOfModelClass("chair"), SemanticClass::kChair);
  EXPECT_EQ(semanticClassOfModelClass("diningtable"), SemanticClass::kTable);
  EXPECT_EQ(semanticClassOfModelClass("person"), SemanticClass::kPerson);
  EXPECT_EQ(semanticClassOfModelClass("bottle"), SemanticClass::kBottle);
  EXPECT_EQ(semanticClassOfModelClass("sofa"), SemanticClass::kSofa);
  EXPECT_EQ(semanticClassOfModelClass("pottedplant"), SemanticClass::kPlant);
  EXPECT_EQ(semanticClassOfModelClass("Dining Table"), SemanticClass::kTable);
  EXPECT_EQ(semanticClassOfModelClass("potted_plant"), SemanticClass::kPlant);
}

TEST(SemanticClassMap, OtherClassesJoinNoObject) {
  EXPECT_EQ(semanticClassOfModelClass("background"), SemanticClass::kNone);
  EXPECT_EQ(semanticClassOfModelClass("aeroplane"), SemanticClass::kNone);
  EXPECT_EQ(semanticClassOfModelClass("cow"), SemanticClass::kNone);
  EXPECT_EQ(semanticClassOfModelClass(""), SemanticClass::kNone);
}

TEST(SemanticClassMap, StoredClassIdsStayStable) {
  // Label images on disk hold these values.
  EXPECT_EQ(static_cast<int>(SemanticClass::kPerson), 8);
  EXPECT_EQ(static_cast<int>(SemanticClass::kShelf), 10);
  EXPECT_EQ(core::semanticClassName(SemanticClass::kPlant), "plant");
  EXPECT_EQ(core::semanticClassFromName("bottle"), SemanticClass::kBottle);
}

TEST(SemanticClassMap, TranslatesTheVocConfigsLabelImages) {
  const auto config = readModelConfig(std::filesystem::path(SEGSLAM_SOURCE_DIR) /
                                      "config/models/espnetv2_voc_384.yaml");
  const SemanticClassMap map(config.classes);
  // VOC indices: 0 background, 9 chair, 11 diningtable, 15 person, 20 tvmonitor; 200 is none.
  const cv::Mat model_labels = (cv::Mat_<std::uint8_t>(1, 6) << 0, 9, 11, 15, 20, 200);
  const cv::Mat labels = map.apply(model_labels);
  ASSERT_EQ(labels.type(), CV_8UC1);
  const std::vector<SemanticClass> expected = {SemanticClass::kNone,    SemanticClass::kChair,
                                               SemanticClass::kTable,   SemanticClass::kPerson,
                                               SemanticClass::kMonitor, SemanticClass::kNone};
  for (int i = 0; i < labels.cols; ++i) {
    EXPECT_EQ(static_cast<SemanticClass>(labels.at<std::uint8_t>(0, i)), expected[i]) << i;
  }
  EXPECT_EQ(map.classOf(15), SemanticClass::kPerson);
  EXPECT_EQ(map.classOf(-1), SemanticClass::kNone);
}

}  // namespace
}  // namespace segslam::segmentation
