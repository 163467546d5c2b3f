#include "segslam/place/cnn_feature_extractor.h"

#include <fmt/format.h>

#include <algorithm>

#include "segslam/util/error.h"

namespace segslam::place {

CnnFeatureExtractor::CnnFeatureExtractor(CnnBackboneConfig config,
                                         const std::filesystem::path& model_file)
    : config_(std::move(config)) {
  try {
    net_ = cv::dnn::readNet(model_file.string());
  } catch (const cv::Exception& e) {
    util::failAt(model_file, fmt::format("cannot load the CNN backbone: {}", e.err));
  }
  if (net_.empty()) util::failAt(model_file, "cannot load the CNN backbone");
  net_.setPreferableBackend(cv::dnn::DNN_BACKEND_OPENCV);
  net_.setPreferableTarget(cv::dnn::DNN_TARGET_CPU);
  const auto known = net_.getLayerNames();
  for (const auto& layer : config_.layers) {
    if (std::find(known.begin(), known.end(), layer.layer) == known.end()) {
      util::failAt(model_file, fmt::format("the CNN backbone has no layer '{}' (for {})",
                                           layer.layer, layer.name));
    }
    layer_names_.push_back(layer.layer);
  }
}

std::vector<cv::Mat> CnnFeatureExtractor::extract(const cv::Mat& bgr) {
  cv::Mat blob = cv::dnn::blobFromImage(bgr, 1.0, config_.input_size, cv::Scalar(), config_.rgb,
                                        /*crop=*/false, CV_32F);
  const int plane = config_.input_size.area();
  for (int c = 0; c < 3; ++c) {
    cv::Mat channel(1, plane, CV_32F, blob.ptr<float>(0, c));
    channel.convertTo(channel, CV_32F, config_.scale / config_.std[c],
                      -config_.mean[c] / config_.std[c]);
  }
  net_.setInput(blob);
  std::vector<cv::Mat> outputs;
  net_.forward(outputs, layer_names_);
  // forward() hands out views of the network's buffers, which the next image overwrites.
  for (auto& output : outputs) output = output.clone();
  return outputs;
}

}  // namespace segslam::place
