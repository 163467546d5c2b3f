#pragma once

namespace segslam::segmentation {

// Faster CPU versions of two layer types that OpenCV 4.6's dnn module runs on one thread, element
// by element, and that take a third of an ESPNetv2 forward pass (tracking's second core runs it):
// - Permute (ONNX Transpose) that keeps the innermost axes in place (a channel shuffle) is a
//   copy of whole blocks; one that swaps the two innermost axes is a transpose of each plane.
// - Bilinear Resize with align_corners runs row by row over each plane, planes in parallel.
// Any other Permute or Resize is left to OpenCV's own layers. Results equal OpenCV's to float
// rounding (ESPNetv2: the same labels).
//
// While at least one FastDnnLayers object lives, the nets OpenCV builds use these layers: they
// are registered in OpenCV's layer factory, which is process-wide, so other networks loaded
// meanwhile get them as well. Each object, copies included, holds the registration. Thread-safe.
class FastDnnLayers {
 public:
  FastDnnLayers();
  ~FastDnnLayers();
  FastDnnLayers(const FastDnnLayers& /*other*/) : FastDnnLayers() {}
  FastDnnLayers& operator=(const FastDnnLayers& /*other*/) { return *this; }
};

}  // namespace segslam::segmentation
