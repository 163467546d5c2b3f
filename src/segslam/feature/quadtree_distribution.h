#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace segslam::feature {

// Picks min(count, candidates.size()) keypoints spread evenly over `area` (the region the
// candidates were detected in): the area is split as a quadtree, largest nodes first and, among
// equal sizes, the most crowded first, until there are `count` non-empty nodes or every node holds
// a single candidate; each node then keeps its strongest candidate (highest response). When the
// last round of splits overshoots, the weakest of those survivors are dropped.
//
// Empty nodes are discarded as soon as they appear, so regions without candidates (a blank wall,
// a masked person) take no share and the budget goes to the regions that have corners.
// Deterministic: ties are broken by candidate order.
std::vector<cv::KeyPoint> distributeWithQuadtree(const std::vector<cv::KeyPoint>& candidates,
                                                 const cv::Rect2f& area, int count);

}  // namespace segslam::feature
