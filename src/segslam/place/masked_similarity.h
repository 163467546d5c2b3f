#pragma once

#include <opencv2/core.hpp>

// Similarities of two feature maps under a mask. Maps are CV_32F, one row per channel and one
// column per cell of a grid (row-major); weights are CV_32F 1 x cells, the static share of each
// cell (the union mask on the map's grid).
namespace segslam::place {

// Cosine similarity of two equally sized matrices; 0 when either is all zeros.
double cosineSimilarity(const cv::Mat& a, const cv::Mat& b);

// The method's equation 1: the weights broadcast over the channels, multiplied element-wise into
// both maps, then their cosine similarity.
double maskedCosine(const cv::Mat& a, const cv::Mat& b, const cv::Mat& weights);

// Masked average pooling: `grid` is split into `cells` (width x height); in each, both maps are
// averaged with the weights, normalised by the cell's static area, and the concatenated cell
// means are compared by cosine similarity. Cells with less than a tenth static area are left
// out of both; 0 when none is left.
double pooledMaskedCosine(const cv::Mat& a, const cv::Mat& b, const cv::Mat& weights, cv::Size grid,
                          cv::Size cells);

// The same with each map averaged over its own weights (its own image's static area), so that
// what the other image's moving objects hide is not removed from this one; a cell is left out
// of both when either has less than a tenth static area there.
double pooledOwnMaskCosine(const cv::Mat& a, const cv::Mat& b, const cv::Mat& weights_a,
                           const cv::Mat& weights_b, cv::Size grid, cv::Size cells);

}  // namespace segslam::place
