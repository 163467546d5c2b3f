#include "segslam/segmentation/fast_dnn_layers.h"

#include <algorithm>
#include <cstring>
#include <mutex>
#include <opencv2/core.hpp>
#include <opencv2/dnn.hpp>
#include <opencv2/dnn/all_layers.hpp>
#include <opencv2/dnn/layer.hpp>
#include <utility>
#include <vector>

namespace segslam::segmentation {

namespace {

using cv::dnn::LayerParams;
using cv::dnn::MatShape;

// The permutation's axes, or empty when it has none or is not a permutation of 0..n-1.
std::vector<int> permutationOrder(const LayerParams& params) {
  if (!params.has("order")) return {};
  const cv::dnn::DictValue& value = params.get("order");
  std::vector<int> order(static_cast<std::size_t>(value.size()));
  for (int i = 0; i < value.size(); ++i) order[static_cast<std::size_t>(i)] = value.get<int>(i);
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    if (sorted[i] != static_cast<int>(i)) return {};
  }
  return order;
}

// How many innermost axes the permutation leaves in place.
int keptInnerAxes(const std::vector<int>& order) {
  int kept = 0;
  for (int axis = static_cast<int>(order.size()) - 1;
       axis >= 0 && order[static_cast<std::size_t>(axis)] == axis; --axis) {
    ++kept;
  }
  return kept;
}

bool swapsInnermostTwo(const std::vector<int>& order) {
  const int dims = static_cast<int>(order.size());
  if (dims < 2) return false;
  for (int axis = 0; axis < dims - 2; ++axis) {
    if (order[static_cast<std::size_t>(axis)] != axis) return false;
  }
  return order[static_cast<std::size_t>(dims - 2)] == dims - 1 &&
         order[static_cast<std::size_t>(dims - 1)] == dims - 2;
}

// A layer of one float blob in and one out, computed into the blob the net allocated.
class OneBlobLayer : public cv::dnn::Layer {
 public:
  using cv::dnn::Layer::Layer;

  bool getMemoryShapes(const std::vector<MatShape>& inputs, const int /*required_outputs*/,
                       std::vector<MatShape>& outputs,
                       std::vector<MatShape>& /*internals*/) const override {
    CV_Assert(inputs.size() == 1);
    outputs.assign(1, outputShape(inputs[0]));
    return false;
  }

  using cv::dnn::Layer::forward;
  void forward(cv::InputArrayOfArrays inputs, cv::OutputArrayOfArrays outputs,
               cv::OutputArrayOfArrays /*internals*/) override {
    std::vector<cv::Mat> in;
    std::vector<cv::Mat> out;
    inputs.getMatVector(in);
    outputs.getMatVector(out);
    CV_Assert(in.size() == 1 && out.size() == 1);
    CV_Assert(in[0].type() == CV_32F && in[0].isContinuous());
    CV_Assert(out[0].type() == CV_32F && out[0].isContinuous());
    compute(in[0], out[0]);
  }

 private:
  [[nodiscard]] virtual MatShape outputShape(const MatShape& input) const = 0;
  virtual void compute(const cv::Mat& input, cv::Mat& output) const = 0;
};

class PermuteByBlocks : public OneBlobLayer {
 public:
  PermuteByBlocks(const LayerParams& params, std::vector<int> order)
      : OneBlobLayer(params), order_(std::move(order)) {}

 private:
  [[nodiscard]] MatShape outputShape(const MatShape& input) const override {
    CV_Assert(input.size() == order_.size());
    MatShape shape(order_.size());
    for (std::size_t axis = 0; axis < order_.size(); ++axis) {
      shape[axis] = input[static_cast<std::size_t>(order_[axis])];
    }
    return shape;
  }

  void compute(const cv::Mat& input, cv::Mat& output) const override {
    if (swapsInnermostTwo(order_)) {
      transposePlanes(input, output);
    } else {
      copyBlocks(input, output);
    }
  }

  static void transposePlanes(const cv::Mat& input, cv::Mat& output) {
    const int rows = input.size[input.dims - 2];
    const int cols = input.size[input.dims - 1];
    const std::size_t plane = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
    const std::size_t planes = input.total() / std::max<std::size_t>(plane, 1);
    for (std::size_t p = 0; p < planes; ++p) {
      const cv::Mat from(rows, cols, CV_32F, const_cast<float*>(input.ptr<float>()) + p * plane);
      cv::Mat to(cols, rows, CV_32F, output.ptr<float>() + p * plane);
      cv::transpose(from, to);
    }
  }

  // The axes the permutation leaves in place at the end form contiguous blocks in both blobs.
  void copyBlocks(const cv::Mat& input, cv::Mat& output) const {
    const int dims = input.dims;
    const int outer = dims - keptInnerAxes(order_);
    if (outer == 0) {
      input.copyTo(output);
      return;
    }
    std::vector<std::size_t> input_step(static_cast<std::size_t>(dims), 1);
    for (int axis = dims - 2; axis >= 0; --axis) {
      input_step[static_cast<std::size_t>(axis)] = input_step[static_cast<std::size_t>(axis) + 1] *
                                                   static_cast<std::size_t>(input.size[axis + 1]);
    }
    const std::size_t block = input_step[static_cast<std::size_t>(outer) - 1];
    const std::size_t blocks = output.total() / block;
    std::vector<int> index(static_cast<std::size_t>(outer), 0);
    const float* from = input.ptr<float>();
    float* to = output.ptr<float>();
    for (std::size_t b = 0; b < blocks; ++b) {
      std::size_t offset = 0;
      for (std::size_t axis = 0; axis < index.size(); ++axis) {
        offset += static_cast<std::size_t>(index[axis]) *
                  input_step[static_cast<std::size_t>(order_[axis])];
      }
      std::memcpy(to + b * block, from + offset, block * sizeof(float));
      for (int axis = outer - 1; axis >= 0; --axis) {
        if (++index[static_cast<std::size_t>(axis)] < output.size[axis]) break;
        index[static_cast<std::size_t>(axis)] = 0;
      }
    }
  }

  std::vector<int> order_;
};

// Where each output row or column samples the input with align_corners: output i lies at input
// coordinate i * (in - 1) / (out - 1), between `low` and `high` with weight `t` on `high`.
struct Samples {
  std::vector<int> low;
  std::vector<int> high;
  std::vector<float> t;
};

Samples alignedCornerSamples(int in, int out) {
  const float scale = out > 1 ? static_cast<float>(in - 1) / static_cast<float>(out - 1) : 0.f;
  Samples samples;
  for (int i = 0; i < out; ++i) {
    const float at = static_cast<float>(i) * scale;
    const int low = std::min(static_cast<int>(at), in - 1);
    samples.low.push_back(low);
    samples.high.push_back(std::min(low + 1, in - 1));
    samples.t.push_back(at - static_cast<float>(low));
  }
  return samples;
}

class AlignedCornersBilinearResize : public OneBlobLayer {
 public:
  explicit AlignedCornersBilinearResize(const LayerParams& params)
      : OneBlobLayer(params),
        height_(params.get<int>("height", 0)),
        width_(params.get<int>("width", 0)),
        zoom_y_(params.get<float>("zoom_factor_y", 0.f)),
        zoom_x_(params.get<float>("zoom_factor_x", 0.f)) {}

  static bool handles(const LayerParams& params) {
    const bool sized = (params.get<int>("height", 0) > 0 && params.get<int>("width", 0) > 0) ||
                       (params.get<float>("zoom_factor_y", 0.f) > 0.f &&
                        params.get<float>("zoom_factor_x", 0.f) > 0.f);
    return sized && params.get<cv::String>("interpolation", "") == "bilinear" &&
           params.get<bool>("align_corners", false) &&
           !params.get<bool>("half_pixel_centers", false);
  }

 private:
  [[nodiscard]] MatShape outputShape(const MatShape& input) const override {
    CV_Assert(input.size() == 4);
    MatShape shape = input;
    // A zoom factor wins over a size, as in OpenCV's layer.
    shape[2] = zoom_y_ > 0.f ? static_cast<int>(static_cast<float>(shape[2]) * zoom_y_) : height_;
    shape[3] = zoom_x_ > 0.f ? static_cast<int>(static_cast<float>(shape[3]) * zoom_x_) : width_;
    return shape;
  }

  void compute(const cv::Mat& input, cv::Mat& output) const override {
    const int in_rows = input.size[2];
    const int in_cols = input.size[3];
    const int out_rows = output.size[2];
    const int out_cols = output.size[3];
    const Samples rows = alignedCornerSamples(in_rows, out_rows);
    const Samples cols = alignedCornerSamples(in_cols, out_cols);
    const std::size_t in_plane = static_cast<std::size_t>(in_rows) * in_cols;
    const std::size_t out_plane = static_cast<std::size_t>(out_rows) * out_cols;
    const int planes = input.size[0] * input.size[1];
    // Each output row blends two input rows (contiguous, vectorised), then samples the blend.
    cv::parallel_for_(cv::Range(0, planes), [&](const cv::Range& range) {
      std::vector<float> blend(static_cast<std::size_t>(in_cols));
      for (int p = range.start; p < range.end; ++p) {
        const float* from = input.ptr<float>() + static_cast<std::size_t>(p) * in_plane;
        float* to = output.ptr<float>() + static_cast<std::size_t>(p) * out_plane;
        for (int y = 0; y < out_rows; ++y) {
          const float* low = from + static_cast<std::size_t>(rows.low[y]) * in_cols;
          const float* high = from + static_cast<std::size_t>(rows.high[y]) * in_cols;
          const float t = rows.t[y];
          for (int x = 0; x < in_cols; ++x) blend[x] = low[x] + t * (high[x] - low[x]);
          float* row = to + static_cast<std::size_t>(y) * out_cols;
          for (int x = 0; x < out_cols; ++x) {
            const float left = blend[cols.low[x]];
            row[x] = left + cols.t[x] * (blend[cols.high[x]] - left);
          }
        }
      }
    });
  }

  int height_;
  int width_;
  float zoom_y_;
  float zoom_x_;
};

cv::Ptr<cv::dnn::Layer> createPermute(LayerParams& params) {
  std::vector<int> order = permutationOrder(params);
  if (swapsInnermostTwo(order) || (!order.empty() && keptInnerAxes(order) > 0)) {
    return cv::makePtr<PermuteByBlocks>(params, std::move(order));
  }
  return cv::dnn::PermuteLayer::create(params);
}

cv::Ptr<cv::dnn::Layer> createResize(LayerParams& params) {
  if (AlignedCornersBilinearResize::handles(params)) {
    return cv::makePtr<AlignedCornersBilinearResize>(params);
  }
  return cv::dnn::ResizeLayer::create(params);
}

// OpenCV's layer factory keeps a stack of constructors per type; ours go on top while any
// FastDnnLayers lives.
std::mutex& registrationMutex() {
  static std::mutex mutex;
  return mutex;
}
int& registrations() {
  static int count = 0;
  return count;
}

}  // namespace

FastDnnLayers::FastDnnLayers() {
  std::lock_guard lock(registrationMutex());
  if (registrations()++ > 0) return;
  cv::dnn::LayerFactory::registerLayer("Permute", createPermute);
  cv::dnn::LayerFactory::registerLayer("Resize", createResize);
}

FastDnnLayers::~FastDnnLayers() {
  std::lock_guard lock(registrationMutex());
  if (--registrations() > 0) return;
  cv::dnn::LayerFactory::unregisterLayer("Permute");
  cv::dnn::LayerFactory::unregisterLayer("Resize");
}

}  // namespace segslam::segmentation
