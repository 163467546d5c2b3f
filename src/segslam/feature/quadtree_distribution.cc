#include "segslam/feature/quadtree_distribution.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <queue>

namespace segslam::feature {
namespace {

// A quadtree node: a rectangle and the candidates inside it, as a range of `order`.
struct Node {
  cv::Rect2f box;
  int begin = 0;
  int end = 0;
  int id = 0;  // creation order, the last tie-breaker

  [[nodiscard]] int size() const { return end - begin; }
  // Nodes smaller than a pixel cannot separate integer-position candidates any further.
  [[nodiscard]] bool splittable() const {
    return size() > 1 && (box.width > 1.0f || box.height > 1.0f);
  }
};

// Split order: larger boxes first (breadth-first, so the image is covered evenly), then the node
// with more candidates, then the older node.
struct SplitsLater {
  bool operator()(const Node& a, const Node& b) const {
    const float area_a = a.box.area();
    const float area_b = b.box.area();
    if (area_a != area_b) return area_a < area_b;
    if (a.size() != b.size()) return a.size() < b.size();
    return a.id > b.id;
  }
};

class Quadtree {
 public:
  Quadtree(const std::vector<cv::KeyPoint>& candidates, const cv::Rect2f& area)
      : candidates_(candidates), order_(candidates.size()) {
    for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<int>(i);
    addRoots(area);
  }

  // Splits until there are at least `count` leaves or nothing can be split.
  void splitUntil(int count) {
    while (static_cast<int>(leaves_.size()) + static_cast<int>(open_.size()) < count &&
           !open_.empty()) {
      const Node node = open_.top();
      open_.pop();
      split(node);
    }
  }

  // The strongest candidate of every node, strongest first.
  [[nodiscard]] std::vector<int> strongestPerNode() const {
    std::vector<int> picks;
    for (const Node& leaf : leaves_) picks.push_back(strongestIn(leaf));
    auto open = open_;
    for (; !open.empty(); open.pop()) picks.push_back(strongestIn(open.top()));
    std::sort(picks.begin(), picks.end(), [this](int a, int b) {
      const float response_a = candidates_[a].response;
      const float response_b = candidates_[b].response;
      return response_a != response_b ? response_a > response_b : a < b;
    });
    return picks;
  }

 private:
  // Roughly square roots: one per `aspect ratio` slice of a wide area, so that splitting gives
  // square cells rather than cells as stretched as the image.
  void addRoots(const cv::Rect2f& area) {
    const int roots = area.height > 0.0f
                          ? std::max(1, static_cast<int>(std::lround(area.width / area.height)))
                          : 1;
    const float width = area.width / static_cast<float>(roots);
    int begin = 0;
    for (int i = 0; i < roots; ++i) {
      const float x0 = area.x + width * static_cast<float>(i);
      const float x1 = i + 1 == roots ? area.x + area.width : x0 + width;
      const auto in_root = [&](int index) {
        const float x = candidates_[index].pt.x;
        return i + 1 == roots || x < x1;
      };
      const auto end = std::stable_partition(order_.begin() + begin, order_.end(), in_root);
      add({cv::Rect2f(x0, area.y, x1 - x0, area.height), begin,
           static_cast<int>(end - order_.begin()), 0});
      begin = static_cast<int>(end - order_.begin());
    }
  }

  void add(Node node) {
    if (node.size() == 0) return;
    node.id = next_id_++;
    if (node.splittable()) {
      open_.push(node);
    } else {
      leaves_.push_back(node);
    }
  }

  void split(const Node& node) {
    const float half_width = node.box.width / 2.0f;
    const float half_height = node.box.height / 2.0f;
    const float mid_x = node.box.x + half_width;
    const float mid_y = node.box.y + half_height;
    const auto first = order_.begin();
    // Top half, then within each half the left part: four contiguous ranges in `order_`.
    const auto top_end = std::stable_partition(first + node.begin, first + node.end,
                                               [&](int i) { return candidates_[i].pt.y < mid_y; });
    const auto is_left = [&](int i) { return candidates_[i].pt.x < mid_x; };
    const auto top_left_end = std::stable_partition(first + node.begin, top_end, is_left);
    const auto bottom_left_end = std::stable_partition(top_end, first + node.end, is_left);
    const std::array<int, 5> bounds = {node.begin, static_cast<int>(top_left_end - first),
                                       static_cast<int>(top_end - first),
                                       static_cast<int>(bottom_left_end - first), node.end};
    const std::array<cv::Rect2f, 4> boxes = {
        cv::Rect2f(node.box.x, node.box.y, half_width, half_height),
        cv::Rect2f(mid_x, node.box.y, half_width, half_height),
        cv::Rect2f(node.box.x, mid_y, half_width, half_height),
        cv::Rect2f(mid_x, mid_y, half_width, half_height)};
    for (std::size_t q = 0; q < boxes.size(); ++q) add({boxes[q], bounds[q], bounds[q + 1], 0});
  }

  [[nodiscard]] int strongestIn(const Node& node) const {
    int best = order_[node.begin];
    for (int k = node.begin + 1; k < node.end; ++k) {
      const int candidate = order_[k];
      const float response = candidates_[candidate].response;
      const float best_response = candidates_[best].response;
      if (response > best_response || (response == best_response && candidate < best)) {
        best = candidate;
      }
    }
    return best;
  }

  const std::vector<cv::KeyPoint>& candidates_;
  std::vector<int> order_;
  std::vector<Node> leaves_;  // nodes that cannot be split further
  std::priority_queue<Node, std::vector<Node>, SplitsLater> open_;
  int next_id_ = 0;
};

}  // namespace

std::vector<cv::KeyPoint> distributeWithQuadtree(const std::vector<cv::KeyPoint>& candidates,
                                                 const cv::Rect2f& area, int count) {
  std::vector<cv::KeyPoint> kept;
  if (count <= 0 || candidates.empty()) return kept;
  Quadtree tree(candidates, area);
  tree.splitUntil(count);
  std::vector<int> picks = tree.strongestPerNode();
  if (static_cast<int>(picks.size()) > count) picks.resize(count);
  // Back to candidate order, so that the output order depends on position, not on response ties.
  std::sort(picks.begin(), picks.end());
  kept.reserve(picks.size());
  for (const int pick : picks) kept.push_back(candidates[pick]);
  return kept;
}

}  // namespace segslam::feature
