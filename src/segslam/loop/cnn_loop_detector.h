#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "segslam/loop/candidate_groups.h"
#include "segslam/loop/loop_candidate_detector.h"
#include "segslam/place/cnn_backbone_config.h"
#include "segslam/place/cnn_place_method.h"

namespace segslam::loop {

struct CnnLoopOptions {
  // The backbone config's layer compared, with masked average pooling: pool2 pooled has the best
  // mean union-mask AUC over the loop bench's sequences and masks (0.883; pool3 0.866), and the
  // network stops early (bench/results/loops.md).
  std::string layer = "pool2";
  // Cosine similarity below which nothing is a candidate. CNN similarities of unrelated indoor
  // views are rarely below 0.5, so the covisible keyframes' scores are what really decide.
  double min_score = 0.5;
  CandidateGroupOptions groups;
};

// Where the network comes from: the backbone config (as `segslam eval loops` reads it) and the
// resolved model file.
struct CnnLoopBackbone {
  place::CnnBackboneConfig config;
  std::filesystem::path config_file;  // for messages
  std::filesystem::path model_file;
};

// Loop candidates by a CNN global descriptor with the union mask (the issue's "CNN + union
// mask"): describe() runs the backbone up to one layer on the keyframe's image and keeps that
// layer's map area-averaged to the config's stored grid (float16) with a small static mask;
// candidates() compares the query with every remembered keyframe by masked average pooling over
// what is static in both (place::CnnPlaceMethod, variant kPooled). A candidate must score above
// the mean score of the query's covisible keyframes (the weakest, as for bag of words, lets
// through most of a room: CNN cosines of indoor views are all about 0.9-1) and `min_score`; the
// margins above that threshold are pooled by bestCandidateGroups. Cost per query is linear in the
// map size (a few microseconds per keyframe); the network runs once per keyframe, on the
// loop-closing thread.
class CnnLoopDetector : public LoopCandidateDetector {
 public:
  // Loads the network: util::Error naming the model file when it cannot, or the config file when
  // it has no layer named options.layer.
  CnnLoopDetector(const CnnLoopBackbone& backbone, CnnLoopOptions options = {});

  [[nodiscard]] std::string name() const override { return "cnn"; }
  void describe(const map::KeyFrame& keyframe) override;
  void add(const map::KeyFrame& keyframe) override;
  void forget(std::uint64_t keyframe_id) override;
  // The keyframe's stored features (CnnFeatureBank::encodeImage); empty when not described.
  [[nodiscard]] std::string savedDescription(std::uint64_t keyframe_id) const override;
  // A restored keyframe is a candidate only with a description this backbone and layer made.
  void addRestored(const map::KeyFrame& keyframe, const std::string& description) override;
  // The query must have been described.
  [[nodiscard]] std::vector<std::uint64_t> candidates(const map::KeyFrame& query,
                                                      const std::set<std::uint64_t>& covisible,
                                                      std::size_t max_candidates) const override;

  // Similarity of two described keyframes over what is static in both.
  [[nodiscard]] double similarity(std::uint64_t a, std::uint64_t b) const;
  [[nodiscard]] std::size_t bytesPerKeyFrame() const { return bank_->bytesPerImage(); }
  // Per described keyframe: wall time, and processor time of the whole process.
  [[nodiscard]] double meanExtractionMilliseconds() const;
  [[nodiscard]] double meanExtractionCpuMilliseconds() const;

 private:
  [[nodiscard]] std::size_t indexOf(std::uint64_t keyframe_id) const;

  CnnLoopOptions options_;
  std::shared_ptr<place::CnnFeatureBank> bank_;
  std::unique_ptr<place::CnnPlaceMethod> method_;
  std::map<std::uint64_t, std::size_t> index_of_keyframe_;    // described keyframes
  std::map<std::uint64_t, const map::KeyFrame*> candidates_;  // added keyframes
};

}  // namespace segslam::loop
