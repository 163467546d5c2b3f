#include "segslam/segmentation/fast_dnn_layers.h"

#include <gtest/gtest.h>

#include <opencv2/dnn.hpp>
#include <opencv2/imgcodecs.hpp>
#include <optional>
#include <string>
#include <typeinfo>
#include <vector>

#include "segslam/testing/test_support.h"

namespace segslam::segmentation {
namespace {

cv::Mat randomBlob(const std::vector<int>& shape) {
  cv::Mat blob(static_cast<int>(shape.size()), shape.data(), CV_32F);
  cv::RNG rng(7);
  rng.fill(blob, cv::RNG::UNIFORM, -1.0, 1.0);
  return blob;
}

// A net of one layer: its output for `input`, and the class that ran it.
struct OneLayerRun {
  cv::Mat output;
  std::string layer_class;
};

OneLayerRun runOneLayer(cv::dnn::LayerParams params, const cv::Mat& input) {
  cv::dnn::Net net;
  const int id = net.addLayerToPrev(params.name, params.type, params);
  net.setInput(input);
  const cv::Mat output = net.forward().clone();
  const cv::Ptr<cv::dnn::Layer> layer = net.getLayer(id);
  return {output, typeid(*layer).name()};
}

cv::dnn::LayerParams permuteParams(const std::vector<int>& order) {
  cv::dnn::LayerParams params;
  params.name = "permute";
  params.type = "Permute";
  params.set("order", cv::dnn::DictValue::arrayInt(order.data(), static_cast<int>(order.size())));
  return params;
}

cv::dnn::LayerParams alignedResizeParams(std::optional<cv::Size> size) {
  cv::dnn::LayerParams params;
  params.name = "resize";
  params.type = "Resize";
  params.set("interpolation", "bilinear");
  params.set("align_corners", true);
  if (size) {
    params.set("height", size->height);
    params.set("width", size->width);
  } else {
    params.set("zoom_factor_x", 2.0f);
    params.set("zoom_factor_y", 2.0f);
  }
  return params;
}

bool isOurs(const OneLayerRun& run) {
  return run.layer_class.find("PermuteByBlocks") != std::string::npos ||
         run.layer_class.find("AlignedCornersBilinearResize") != std::string::npos;
}

// Runs the layer with OpenCV's own implementation, then with ours: same output.
void expectSameAsOpenCv(const cv::dnn::LayerParams& params, const cv::Mat& input,
                        bool expect_ours) {
  const OneLayerRun opencv = runOneLayer(params, input);
  ASSERT_FALSE(isOurs(opencv)) << opencv.layer_class;
  const FastDnnLayers fast_layers;
  const OneLayerRun fast = runOneLayer(params, input);
  EXPECT_EQ(isOurs(fast), expect_ours) << fast.layer_class;
  ASSERT_EQ(fast.output.dims, opencv.output.dims);
  for (int axis = 0; axis < fast.output.dims; ++axis) {
    ASSERT_EQ(fast.output.size[axis], opencv.output.size[axis]) << "axis " << axis;
  }
  EXPECT_LE(cv::norm(fast.output, opencv.output, cv::NORM_INF), 1e-5);
}

TEST(FastDnnLayers, ChannelShuffleCopiesBlocksAsOpenCvPermutes) {
  expectSameAsOpenCv(permuteParams({0, 2, 1, 3, 4}), randomBlob({1, 5, 10, 6, 7}), true);
}

TEST(FastDnnLayers, SwappingTheInnermostAxesTransposesEachPlaneAsOpenCv) {
  expectSameAsOpenCv(permuteParams({0, 1, 3, 2}), randomBlob({1, 3, 5, 7}), true);
}

TEST(FastDnnLayers, OtherPermutationsAreLeftToOpenCv) {
  expectSameAsOpenCv(permuteParams({0, 2, 3, 1}), randomBlob({1, 3, 5, 7}), false);
}

TEST(FastDnnLayers, AlignedCornersBilinearZoomMatchesOpenCv) {
  expectSameAsOpenCv(alignedResizeParams(std::nullopt), randomBlob({1, 3, 6, 8}), true);
}

TEST(FastDnnLayers, AlignedCornersBilinearToAGivenSizeMatchesOpenCv) {
  expectSameAsOpenCv(alignedResizeParams(cv::Size(5, 11)), randomBlob({1, 4, 7, 9}), true);
}

TEST(FastDnnLayers, OtherResizesAreLeftToOpenCv) {
  cv::dnn::LayerParams params = alignedResizeParams(cv::Size(12, 10));
  params.set("align_corners", false);
  expectSameAsOpenCv(params, randomBlob({1, 2, 5, 6}), false);
}

TEST(FastDnnLayers, OpenCvsOwnLayersComeBackWhenTheLastScopeEnds) {
  {
    const FastDnnLayers outer;
    { const FastDnnLayers inner; }
    EXPECT_TRUE(isOurs(runOneLayer(permuteParams({0, 1, 3, 2}), randomBlob({1, 2, 3, 4}))));
  }
  EXPECT_FALSE(isOurs(runOneLayer(permuteParams({0, 1, 3, 2}), randomBlob({1, 2, 3, 4}))));
}

// The whole segmentation network: the same class scores as with OpenCV's layers, on a real frame.
TEST(FastDnnLayers, EspNetGivesOpenCvsScores) {
  SEGSLAM_REQUIRE_SHARED(walker, "tum_fr1_xyz_300_walker");
  const auto model = *testing::sharedDir() / "models" / "espnetv2_voc_384.onnx";
  const cv::Mat bgr = cv::imread((walker / "rgb" / "1305031102.175304.jpg").string());
  ASSERT_FALSE(bgr.empty());
  const cv::Mat input =
      cv::dnn::blobFromImage(bgr, 1.0 / 255, cv::Size(384, 384), cv::Scalar(), true);
  const auto scores = [&](cv::dnn::Net net) {
    net.setInput(input);
    return net.forward().clone();
  };
  const cv::Mat opencv = scores(cv::dnn::readNet(model.string()));
  const FastDnnLayers fast_layers;
  const cv::Mat fast = scores(cv::dnn::readNet(model.string()));
  ASSERT_EQ(fast.total(), opencv.total());
  EXPECT_LE(cv::norm(fast, opencv, cv::NORM_INF), 1e-3);
}

}  // namespace
}  // namespace segslam::segmentation
