#pragma once

#include <cstdint>
#include <map>
#include <vector>

namespace segslam::place {

// Index of a leaf of the vocabulary tree.
using WordId = std::uint32_t;
// Index of any node of the vocabulary tree (0 = root).
using NodeId = std::uint32_t;

// Sparse bag-of-words vector: word -> TF-IDF weight (weights are non-negative). Ordered, so that
// two vectors are compared by one merge.
using BowVector = std::map<WordId, double>;

// Direct index of one image: vocabulary node at a chosen tree level -> indices of the image's
// keypoints (descriptor rows) that fall under it. Restricts descriptor matching between two images
// to keypoints under the same node.
using FeatureVector = std::map<NodeId, std::vector<int>>;

// Scales the weights to sum to 1; an all-zero vector stays as it is.
void normaliseL1(BowVector& vector);

// Similarity of two vectors after L1 normalisation: 1 - 0.5 |a/|a| - b/|b||_1, in [0, 1];
// 1 for vectors with the same words in the same proportions, 0 for disjoint words and whenever
// one of them is empty.
[[nodiscard]] double l1Score(const BowVector& a, const BowVector& b);

}  // namespace segslam::place
