#include "segslam/place/cnn_place_method.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "segslam/place/masked_similarity.h"
#include "segslam/place/union_mask.h"
#include "segslam/util/byte_stream.h"
#include "segslam/util/elapsed_time.h"

namespace segslam::place {

namespace {

cv::Size blobGrid(const cv::Mat& blob) {
  return blob.dims == 4 ? cv::Size(blob.size[3], blob.size[2]) : cv::Size(1, 1);
}

int blobChannels(const cv::Mat& blob) {
  return blob.dims == 4 ? blob.size[1] : static_cast<int>(blob.total());
}

// C x cells float16 from a 1 x C x H x W (or 1 x C) blob, each channel area-averaged to `grid`.
cv::Mat storedLayer(const cv::Mat& blob, cv::Size grid) {
  const int channels = blobChannels(blob);
  const cv::Size size = blobGrid(blob);
  cv::Mat stored(channels, grid.area(), CV_32F);
  for (int c = 0; c < channels; ++c) {
    const cv::Mat plane(size, CV_32F, const_cast<float*>(blob.ptr<float>()) + c * size.area());
    cv::Mat resized;
    if (size == grid) {
      resized = plane;
    } else {
      cv::resize(plane, resized, grid, 0, 0, cv::INTER_AREA);
    }
    resized.reshape(1, 1).copyTo(stored.row(c));
  }
  cv::Mat half;
  stored.convertTo(half, CV_16F);
  return half;
}

cv::Mat storedMask(const cv::Mat& static_mask) {
  if (static_mask.empty()) return {};
  cv::Mat small;
  cv::resize(static_mask, small, cv::Size(CnnFeatureBank::kMaskWidth, CnnFeatureBank::kMaskHeight),
             0, 0, cv::INTER_AREA);
  cv::threshold(small, small, 127, 255, cv::THRESH_BINARY);
  return small;
}

cv::Mat asFloat(const cv::Mat& half) {
  cv::Mat values;
  half.convertTo(values, CV_32F);
  return values;
}

}  // namespace

CnnFeatureBank::CnnFeatureBank(CnnFeatureExtractor extractor) : extractor_(std::move(extractor)) {
  const cv::Mat blank(config().input_size, CV_8UC3, cv::Scalar::all(0));
  const cv::Size stored = config().stored_grid;
  for (const auto& blob : extractor_.extract(blank)) {
    const cv::Size size = blobGrid(blob);
    grids_.emplace_back(std::min(size.width, stored.width), std::min(size.height, stored.height));
    channels_.push_back(blobChannels(blob));
  }
}

void CnnFeatureBank::add(std::size_t index, const PlaceImage& image) {
  if (index < images_.size()) {
    if (sources_[index] != image.bgr.data) {
      throw std::logic_error("CNN place methods of one bank were given different images");
    }
    return;
  }
  if (index != images_.size()) throw std::logic_error("CNN place images added out of order");
  images_.push_back(compute(image));
  sources_.push_back(image.bgr.data);
}

namespace {

void putMat(util::ByteWriter& out, const cv::Mat& mat) {
  const cv::Mat continuous = mat.isContinuous() ? mat : mat.clone();
  out.putI32(continuous.rows);
  out.putI32(continuous.cols);
  out.putI32(continuous.type());
  out.putBytes(continuous.data, continuous.total() * continuous.elemSize());
}

cv::Mat getMat(util::ByteReader& in) {
  const int rows = in.getI32();
  const int cols = in.getI32();
  const int type = in.getI32();
  const bool known = type == CV_16FC1 || type == CV_8UC1;
  if (!known || rows < 0 || cols < 0) in.fail("a feature map of an unknown layout");
  cv::Mat mat(rows, cols, type);
  in.getBytes(mat.data, mat.total() * mat.elemSize());
  return mat;
}

}  // namespace

std::string CnnFeatureBank::encodeImage(std::size_t index) const {
  const CnnImageFeatures& features = images_.at(index);
  util::ByteWriter out;
  out.putString(config().name);
  out.putU32(static_cast<std::uint32_t>(features.layers.size()));
  for (std::size_t l = 0; l < features.layers.size(); ++l) {
    out.putString(config().layers.at(l).name);
    putMat(out, features.layers[l]);
  }
  putMat(out, features.static_mask);
  return out.bytes();
}

bool CnnFeatureBank::addEncoded(std::size_t index, std::string_view bytes) {
  if (index != images_.size()) throw std::logic_error("CNN place images added out of order");
  util::ByteReader in(bytes, config().name, "CNN place description");
  if (in.getString() != config().name) return false;
  CnnImageFeatures features;
  const std::size_t layers = in.getCount(12);
  if (layers != grids_.size()) return false;
  for (std::size_t l = 0; l < layers; ++l) {
    if (in.getString() != config().layers.at(l).name) return false;
    features.layers.push_back(getMat(in));
    const cv::Mat& layer = features.layers.back();
    if (layer.type() != CV_16FC1 || layer.rows != channels_[l] || layer.cols != grids_[l].area()) {
      return false;
    }
  }
  features.static_mask = getMat(in);
  const cv::Mat& mask = features.static_mask;
  if (!mask.empty() &&
      (mask.type() != CV_8UC1 || mask.size() != cv::Size(kMaskWidth, kMaskHeight))) {
    return false;
  }
  images_.push_back(std::move(features));
  sources_.push_back(nullptr);
  return true;
}

void CnnFeatureBank::release(std::size_t index) {
  images_.at(index) = {};
  sources_.at(index) = nullptr;
}

CnnImageFeatures CnnFeatureBank::compute(const PlaceImage& image) {
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  const std::vector<cv::Mat> blobs = extractor_.extract(image.bgr);
  CnnImageFeatures features;
  for (std::size_t l = 0; l < blobs.size(); ++l) {
    features.layers.push_back(storedLayer(blobs[l], grids_[l]));
  }
  features.static_mask = storedMask(image.static_mask);
  ++extracted_;
  extraction_ms_ += util::millisecondsSince(start);
  extraction_cpu_ms_ += 1000.0 * static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  return features;
}

std::size_t CnnFeatureBank::bytesPerImage() const {
  std::size_t bytes = static_cast<std::size_t>(kMaskWidth) * kMaskHeight;
  for (std::size_t l = 0; l < grids_.size(); ++l) {
    bytes += sizeof(cv::float16_t) * static_cast<std::size_t>(channels_[l]) * grids_[l].area();
  }
  return bytes;
}

double CnnFeatureBank::meanExtractionMilliseconds() const {
  return extracted_ == 0 ? 0.0 : extraction_ms_ / static_cast<double>(extracted_);
}

double CnnFeatureBank::meanExtractionCpuMilliseconds() const {
  return extracted_ == 0 ? 0.0 : extraction_cpu_ms_ / static_cast<double>(extracted_);
}

CnnPlaceMethod::CnnPlaceMethod(std::shared_ptr<CnnFeatureBank> bank, std::size_t layer,
                               CnnVariant variant)
    : bank_(std::move(bank)), layer_(layer), variant_(variant) {}

std::string CnnPlaceMethod::name() const {
  const std::string& layer = bank_->config().layers.at(layer_).name;
  switch (variant_) {
    case CnnVariant::kFlattened:
      return fmt::format("cnn:{}", layer);
    case CnnVariant::kPooled:
      return fmt::format("cnn:{}:pooled", layer);
    case CnnVariant::kPooledOwnStaticArea:
      return fmt::format("cnn:{}:pooled:static", layer);
  }
  return fmt::format("cnn:{}", layer);
}

void CnnPlaceMethod::add(const PlaceImage& image) {
  bank_->add(count_, image);
  ++count_;
}

bool CnnPlaceMethod::addEncoded(std::string_view bytes) {
  if (!bank_->addEncoded(count_, bytes)) return false;
  ++count_;
  return true;
}

double CnnPlaceMethod::similarity(std::size_t i, std::size_t j, bool union_mask) const {
  const CnnImageFeatures& first = bank_->image(i);
  const CnnImageFeatures& second = bank_->image(j);
  const cv::Size grid = bank_->grids()[layer_];
  const cv::Mat a = asFloat(first.layers[layer_]);
  const cv::Mat b = asFloat(second.layers[layer_]);
  if (variant_ == CnnVariant::kPooledOwnStaticArea && union_mask) {
    return pooledOwnMaskCosine(a, b, poolingWeights(first.static_mask),
                               poolingWeights(second.static_mask), grid,
                               bank_->config().pooling_grid);
  }
  cv::Mat weights(grid, CV_32F, cv::Scalar(1.0));
  if (union_mask) {
    const cv::Mat both = unionStaticMask(first.static_mask, second.static_mask);
    weights =
        variant_ == CnnVariant::kFlattened ? staticFraction(both, grid) : poolingWeights(both);
  }
  const cv::Mat row_weights = weights.reshape(1, 1);
  if (variant_ == CnnVariant::kFlattened) return maskedCosine(a, b, row_weights);
  return pooledMaskedCosine(a, b, row_weights, grid, bank_->config().pooling_grid);
}

cv::Mat CnnPlaceMethod::poolingWeights(const cv::Mat& static_mask) const {
  // Features see beyond their cell: the static area is eroded by the layer's reach.
  const double mask_pixels_per_input_pixel =
      static_cast<double>(CnnFeatureBank::kMaskWidth) / bank_->config().input_size.width;
  const int erosion = bank_->config().layers[layer_].erosion_px;
  const cv::Mat eroded = erodeStaticMask(
      static_mask, static_cast<int>(std::ceil(erosion * mask_pixels_per_input_pixel)));
  return staticFraction(eroded, bank_->grids()[layer_]).reshape(1, 1);
}

std::vector<std::unique_ptr<PlaceDescriptorMethod>> makeCnnPlaceMethods(
    const std::shared_ptr<CnnFeatureBank>& bank) {
  std::vector<std::unique_ptr<PlaceDescriptorMethod>> methods;
  for (std::size_t l = 0; l < bank->grids().size(); ++l) {
    methods.push_back(std::make_unique<CnnPlaceMethod>(bank, l, CnnVariant::kFlattened));
  }
  for (std::size_t l = 0; l < bank->grids().size(); ++l) {
    if (bank->grids()[l].area() > 1) {
      methods.push_back(std::make_unique<CnnPlaceMethod>(bank, l, CnnVariant::kPooled));
      methods.push_back(
          std::make_unique<CnnPlaceMethod>(bank, l, CnnVariant::kPooledOwnStaticArea));
    }
  }
  return methods;
}

}  // namespace segslam::place
