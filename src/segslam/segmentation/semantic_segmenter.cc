#include "segslam/segmentation/semantic_segmenter.h"

#include <fmt/format.h>

#include <opencv2/imgproc.hpp>

#include "segslam/util/error.h"

namespace segslam::segmentation {

namespace {

// A 1 x C x H x W blob as 1 x H x W x C (or back), for networks that take or give channels last.
cv::Mat permuteBlob(const cv::Mat& blob, bool to_channels_last) {
  const int channels = to_channels_last ? blob.size[1] : blob.size[3];
  const int height = to_channels_last ? blob.size[2] : blob.size[1];
  const int width = to_channels_last ? blob.size[3] : blob.size[2];
  const int out_shape[] = {1, to_channels_last ? height : channels,
                           to_channels_last ? width : height, to_channels_last ? channels : width};
  cv::Mat out(4, out_shape, CV_32F);
  const auto* in = blob.ptr<float>();
  auto* dst = out.ptr<float>();
  for (int c = 0; c < channels; ++c) {
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const std::size_t planar = (static_cast<std::size_t>(c) * height + y) * width + x;
        const std::size_t interleaved = (static_cast<std::size_t>(y) * width + x) * channels + c;
        if (to_channels_last) {
          dst[interleaved] = in[planar];
        } else {
          dst[planar] = in[interleaved];
        }
      }
    }
  }
  return out;
}

}  // namespace

SemanticSegmenter::SemanticSegmenter(ModelConfig config, const std::filesystem::path& model_file)
    : config_(std::move(config)), dynamic_indices_(config_.dynamicClassIndices()) {
  try {
    net_ = cv::dnn::readNet(model_file.string());
  } catch (const cv::Exception& e) {
    util::failAt(model_file, fmt::format("cannot load the segmentation network: {}", e.err));
  }
  if (net_.empty()) util::failAt(model_file, "cannot load the segmentation network");
  net_.setPreferableBackend(cv::dnn::DNN_BACKEND_OPENCV);
  net_.setPreferableTarget(cv::dnn::DNN_TARGET_CPU);
}

cv::Mat SemanticSegmenter::inputBlob(const cv::Mat& bgr) const {
  cv::Mat blob = cv::dnn::blobFromImage(bgr, 1.0, config_.input_size, cv::Scalar(), config_.rgb,
                                        /*crop=*/false, CV_32F);
  const int plane = config_.input_size.width * config_.input_size.height;
  for (int c = 0; c < 3; ++c) {
    cv::Mat channel(1, plane, CV_32F, blob.ptr<float>(0, c));
    channel.convertTo(channel, CV_32F, config_.scale / config_.std[c],
                      -config_.mean[c] / config_.std[c]);
  }
  return config_.layout == TensorLayout::kNhwc ? permuteBlob(blob, true) : blob;
}

cv::Mat SemanticSegmenter::labelsFromScores(const cv::Mat& output) const {
  if (output.dims != 4 || output.size[0] != 1) {
    throw util::Error(
        fmt::format("segmentation network '{}': expected a 1 x C x H x W output", config_.name));
  }
  const cv::Mat scores =
      config_.layout == TensorLayout::kNhwc ? permuteBlob(output, false) : output;
  const int classes = scores.size[1];
  const int height = scores.size[2];
  const int width = scores.size[3];
  if (classes != static_cast<int>(config_.classes.size())) {
    throw util::Error(fmt::format("segmentation network '{}' gives {} classes, its config lists {}",
                                  config_.name, classes, config_.classes.size()));
  }
  cv::Mat labels(height, width, CV_8UC1, cv::Scalar(0));
  cv::Mat best(height, width, CV_32F, const_cast<float*>(scores.ptr<float>(0, 0)));
  best = best.clone();
  for (int c = 1; c < classes; ++c) {
    const cv::Mat score(height, width, CV_32F, const_cast<float*>(scores.ptr<float>(0, c)));
    const cv::Mat higher = score > best;
    score.copyTo(best, higher);
    labels.setTo(c, higher);
  }
  return labels;
}

SemanticMasks SemanticSegmenter::segment(const cv::Mat& bgr) {
  if (bgr.empty() || bgr.type() != CV_8UC3) {
    throw util::Error("semantic segmentation needs an 8-bit BGR image");
  }
  net_.setInput(inputBlob(bgr), config_.input);
  const cv::Mat output = config_.output.empty() ? net_.forward() : net_.forward(config_.output);
  SemanticMasks masks;
  cv::resize(labelsFromScores(output), masks.labels, bgr.size(), 0.0, 0.0, cv::INTER_NEAREST);
  masks.dynamic = cv::Mat::zeros(bgr.size(), CV_8UC1);
  for (int index : dynamic_indices_) masks.dynamic.setTo(255, masks.labels == index);
  return masks;
}

void SemanticSegmenter::warmUp() { segment(cv::Mat::zeros(config_.input_size, CV_8UC3)); }

}  // namespace segslam::segmentation
