#include "segslam/segmentation/mask_propagator.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <vector>

namespace segslam::segmentation {

MaskPropagator::MaskPropagator(int history, double flow_scale)
    : history_(history),
      flow_scale_(flow_scale),
      flow_(cv::DISOpticalFlow::create(cv::DISOpticalFlow::PRESET_ULTRAFAST)) {
  if (history < 1 || flow_scale <= 0.0 || flow_scale > 1.0) {
    throw std::invalid_argument("MaskPropagator: history >= 1 and flow_scale in (0, 1]");
  }
}

void MaskPropagator::addFrame(std::uint64_t frame_id, const cv::Mat& image) {
  if (has_frame_ && frame_id == newest_id_) return;
  cv::Mat gray;
  if (image.channels() == 3) {
    cv::cvtColor(image, gray, cv::COLOR_BGR2GRAY);
  } else {
    gray = image;
  }
  cv::Mat small;
  cv::resize(gray, small, cv::Size(), flow_scale_, flow_scale_, cv::INTER_AREA);
  if (has_frame_ && small.size() == previous_gray_.size()) {
    // Backward flow: new(x) ~ previous(x + flow(x)), which is what remapping a previous mask needs.
    // Masks are carried at the flow's resolution: the network's own output is coarser than that,
    // and full-size flow maps cost the tracking thread more than the flow itself.
    cv::Mat flow;
    flow_->calc(small, previous_gray_, flow);
    Step step{newest_id_, cv::Mat(small.size(), CV_32FC1), cv::Mat(small.size(), CV_32FC1)};
    for (int y = 0; y < small.rows; ++y) {
      const auto* f = flow.ptr<cv::Point2f>(y);
      auto* mx = step.map_x.ptr<float>(y);
      auto* my = step.map_y.ptr<float>(y);
      for (int x = 0; x < small.cols; ++x) {
        mx[x] = static_cast<float>(x) + f[x].x;
        my[x] = static_cast<float>(y) + f[x].y;
      }
    }
    steps_.push_back(std::move(step));
    while (static_cast<int>(steps_.size()) > history_) steps_.pop_front();
  } else {
    steps_.clear();
  }
  previous_gray_ = small;
  newest_id_ = frame_id;
  has_frame_ = true;
}

std::optional<std::deque<MaskPropagator::Step>::const_iterator> MaskPropagator::stepsFrom(
    std::uint64_t source_id) const {
  if (!has_frame_ || source_id > newest_id_) return std::nullopt;
  if (source_id == newest_id_) return steps_.end();
  auto first = steps_.begin();
  while (first != steps_.end() && first->from_id != source_id) ++first;
  if (first == steps_.end()) return std::nullopt;
  return first;
}

cv::Mat MaskPropagator::propagate(const cv::Mat& labels, std::uint64_t source_id) const {
  const auto first = stepsFrom(source_id);
  if (!first) return {};
  if (*first == steps_.end()) return labels.clone();
  cv::Mat current = toFlowResolution(labels);
  for (auto it = *first; it != steps_.end(); ++it) {
    cv::Mat next;
    cv::remap(current, next, it->map_x, it->map_y, cv::INTER_NEAREST, cv::BORDER_CONSTANT,
              cv::Scalar(0));
    current = next;
  }
  return toSizeOf(current, labels);
}

cv::Mat MaskPropagator::toFlowResolution(const cv::Mat& image) const {
  cv::Mat small;
  cv::resize(image, small, previous_gray_.size(), 0.0, 0.0, cv::INTER_NEAREST);
  return small;
}

cv::Mat MaskPropagator::toSizeOf(const cv::Mat& small, const cv::Mat& image) {
  cv::Mat full;
  cv::resize(small, full, image.size(), 0.0, 0.0, cv::INTER_NEAREST);
  return full;
}

namespace {

// The largest step of the flow histogram (in flow pixels per frame): the fast walker near the
// camera in the dev suite moves up to 16.
constexpr int kMaxShift = 48;

// The shift most of an object's pixels agree on: the peak of the histogram of their motion,
// smoothed over about a pixel. A mask that has slipped partly off a walking person covers him and
// some background; their median lies between the two motions, so the mask falls further behind
// him each frame until it follows the background (fr1_p2_s12_fast, a person cut by the image
// border carried 12 frames: recall 0.28 by the median, 0.73 by the peak). The peak stays with the
// larger coherent motion. `dx`, `dy`: where each pixel was in the previous frame minus where it is.
cv::Point dominantShift(const std::vector<float>& dx, const std::vector<float>& dy) {
  constexpr int side = 2 * kMaxShift + 1;
  cv::Mat histogram = cv::Mat::zeros(side, side, CV_32FC1);
  for (std::size_t i = 0; i < dx.size(); ++i) {
    const int x = kMaxShift - cvRound(dx[i]);
    const int y = kMaxShift - cvRound(dy[i]);
    if (x >= 0 && x < side && y >= 0 && y < side) histogram.at<float>(y, x) += 1.0F;
  }
  cv::GaussianBlur(histogram, histogram, cv::Size(5, 5), 1.0, 1.0, cv::BORDER_CONSTANT);
  cv::Point peak;
  double most = 0.0;
  cv::minMaxLoc(histogram, nullptr, &most, nullptr, &peak);
  if (most <= 0.0) return {};
  return peak - cv::Point(kMaxShift, kMaxShift);
}

// One step of moveObjects: map_x/map_y say where each pixel of the new frame was in the old one,
// so an object moves by minus the offset most of its pixels share. Objects are labelled
// within the mask's bounding box only: people cover a small part of most frames.
cv::Mat moveEachObject(const cv::Mat& mask, const cv::Mat& map_x, const cv::Mat& map_y) {
  cv::Mat moved = cv::Mat::zeros(mask.size(), mask.type());
  const cv::Rect box = cv::boundingRect(mask);
  if (box.empty()) return moved;
  cv::Mat objects;
  cv::Mat stats;
  cv::Mat centroids;
  const int count =
      cv::connectedComponentsWithStats(mask(box) != 0, objects, stats, centroids, 8, CV_32S);
  std::vector<std::vector<float>> dx(count);
  std::vector<std::vector<float>> dy(count);
  for (int y = 0; y < box.height; ++y) {
    const auto* object = objects.ptr<int>(y);
    const auto* mx = map_x.ptr<float>(box.y + y) + box.x;
    const auto* my = map_y.ptr<float>(box.y + y) + box.x;
    for (int x = 0; x < box.width; ++x) {
      if (object[x] == 0) continue;
      dx[object[x]].push_back(mx[x] - static_cast<float>(box.x + x));
      dy[object[x]].push_back(my[x] - static_cast<float>(box.y + y));
    }
  }
  const cv::Rect image(0, 0, mask.cols, mask.rows);
  for (int id = 1; id < count; ++id) {
    const cv::Point shift = dominantShift(dx[id], dy[id]);
    const cv::Rect part(stats.at<int>(id, cv::CC_STAT_LEFT), stats.at<int>(id, cv::CC_STAT_TOP),
                        stats.at<int>(id, cv::CC_STAT_WIDTH),
                        stats.at<int>(id, cv::CC_STAT_HEIGHT));
    const cv::Rect target = (part + box.tl() + shift) & image;
    if (target.empty()) continue;
    const cv::Rect source = target - shift;
    mask(source).copyTo(moved(target), objects(source - box.tl()) == id);
  }
  return moved;
}

}  // namespace

cv::Mat MaskPropagator::moveObjects(const cv::Mat& mask, std::uint64_t source_id) const {
  const auto first = stepsFrom(source_id);
  if (!first) return {};
  // Most frames show nobody: nothing to move, no components to label at every step.
  if (*first == steps_.end() || cv::countNonZero(mask) == 0) return mask.clone();
  cv::Mat current = toFlowResolution(mask);
  for (auto it = *first; it != steps_.end(); ++it) {
    current = moveEachObject(current, it->map_x, it->map_y);
  }
  return toSizeOf(current, mask);
}

}  // namespace segslam::segmentation
