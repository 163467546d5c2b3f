#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "segslam/feature/orb_extractor.h"

namespace segslam::place {

// Where training images come from: a folder of *.png / *.jpg / *.jpeg images (sorted by name),
// or a TUM-layout sequence (its colour frames, with mask.txt's dynamic masks when it has them).
struct TrainingSource {
  enum class Kind { kImageFolder, kTumDataset };
  Kind kind = Kind::kImageFolder;
  std::filesystem::path folder;
};

struct TrainingImage {
  std::filesystem::path image;
  std::optional<std::filesystem::path> dynamic_mask;  // keypoints stay off its non-zero pixels
};

// Every `every`-th image of each source, in order. Throws util::Error naming the folder when it
// does not exist, holds no images, or (for a sequence) fails to open.
std::vector<TrainingImage> listTrainingImages(const std::vector<TrainingSource>& sources,
                                              int every);

// ORB descriptors of each image (one N x 32 matrix per image, the vocabulary's documents).
// Throws util::Error naming an image that cannot be decoded. `on_image` runs after each image.
std::vector<cv::Mat> extractTrainingDescriptors(const std::vector<TrainingImage>& images,
                                                const feature::OrbExtractorOptions& orb_options,
                                                const std::function<void()>& on_image = nullptr);

}  // namespace segslam::place
