#include "segslam/place/vocabulary_trainer.h"

#include <algorithm>
#include <cctype>
#include <opencv2/imgcodecs.hpp>

#include "segslam/io/frame_images.h"
#include "segslam/io/tum_dataset.h"
#include "segslam/util/error.h"

namespace segslam::place {

namespace {

bool isImageFile(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".png" || extension == ".jpg" || extension == ".jpeg";
}

std::vector<TrainingImage> folderImages(const std::filesystem::path& folder) {
  if (!std::filesystem::is_directory(folder)) util::failAt(folder, "not a folder of images");
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.is_regular_file() && isImageFile(entry.path())) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  std::vector<TrainingImage> images;
  for (auto& file : files) images.push_back({std::move(file), std::nullopt});
  return images;
}

std::vector<TrainingImage> sequenceImages(const std::filesystem::path& folder) {
  const auto dataset = io::TumDataset::open(folder);
  std::vector<TrainingImage> images;
  for (const io::FrameRecord& frame : dataset.frames()) {
    images.push_back({frame.rgb_path, frame.mask_path});
  }
  return images;
}

}  // namespace

std::vector<TrainingImage> listTrainingImages(const std::vector<TrainingSource>& sources,
                                              int every) {
  const auto step = static_cast<std::size_t>(std::max(every, 1));
  std::vector<TrainingImage> selected;
  for (const TrainingSource& source : sources) {
    const auto images = source.kind == TrainingSource::Kind::kImageFolder
                            ? folderImages(source.folder)
                            : sequenceImages(source.folder);
    if (images.empty()) util::failAt(source.folder, "no training images (*.png, *.jpg) found");
    for (std::size_t i = 0; i < images.size(); i += step) selected.push_back(images[i]);
  }
  return selected;
}

std::vector<cv::Mat> extractTrainingDescriptors(const std::vector<TrainingImage>& images,
                                                const feature::OrbExtractorOptions& orb_options,
                                                const std::function<void()>& on_image) {
  feature::OrbExtractor extractor(orb_options);
  std::vector<cv::Mat> descriptor_sets;
  descriptor_sets.reserve(images.size());
  for (const TrainingImage& image : images) {
    const cv::Mat gray = cv::imread(image.image.string(), cv::IMREAD_GRAYSCALE);
    if (gray.empty()) util::failAt(image.image, "cannot decode image");
    cv::Mat dynamic_mask;
    if (image.dynamic_mask) dynamic_mask = io::readMaskImage(*image.dynamic_mask, gray.size());
    std::vector<cv::KeyPoint> keypoints;
    cv::Mat descriptors;
    extractor.extract(gray, dynamic_mask, keypoints, descriptors);
    descriptor_sets.push_back(descriptors);
    if (on_image) on_image();
  }
  return descriptor_sets;
}

}  // namespace segslam::place
