#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "segslam/feature/descriptor_distance.h"
#include "segslam/place/bow_vector.h"

namespace segslam::place {

struct VocabularyOptions {
  int k = 10;     // branching factor, 2..255
  int depth = 5;  // levels below the root, 1..10; at most k^depth words
  std::uint64_t seed = 1;
  int max_iterations = 10;  // k-majority iterations per node
};

// What a vocabulary was built from, stored in its file header.
struct VocabularyTrainingSummary {
  std::uint64_t images = 0;
  std::uint64_t descriptors = 0;
  std::string description;  // free text: data sources, options; one line

  friend bool operator==(const VocabularyTrainingSummary&,
                         const VocabularyTrainingSummary&) = default;
};

using OrbDescriptor = std::array<std::uint8_t, feature::kDescriptorBytes>;

// One node of the vocabulary tree; a node without children is a word.
struct VocabularyNode {
  OrbDescriptor centre{};  // zero for the root
  NodeId first_child = 0;  // children are contiguous: first_child .. first_child + count - 1
  std::uint16_t num_children = 0;
  std::uint8_t level = 0;  // 0 = root
  WordId word = 0;         // meaningful for leaves only

  friend bool operator==(const VocabularyNode&, const VocabularyNode&) = default;
};

// Hierarchical k-majority vocabulary tree over binary ORB descriptors (Nister & Stewenius 2006,
// with bitwise majority centres for binary descriptors as in Galvez-Lopez & Tardos 2012), words
// weighted by inverse document frequency. Nodes are stored breadth first, so the leaves' order is
// the words' order and a node's children follow each other.
class Vocabulary {
 public:
  // descriptor_sets: one N x 32 CV_8U matrix per training image (the images are the documents of
  // the IDF weights). Deterministic for a seed. Throws std::invalid_argument for bad options or
  // descriptor types and when there are no descriptors at all.
  static Vocabulary train(const std::vector<cv::Mat>& descriptor_sets,
                          const VocabularyOptions& options, VocabularyTrainingSummary summary = {});

  // Reads a file written by save(); a missing, truncated or corrupt file or an unknown version
  // throws util::Error naming the file.
  static Vocabulary load(const std::filesystem::path& file);
  // Compact little-endian binary: magic, version, options, training summary, nodes, IDF weights.
  // Throws util::Error when the file cannot be written.
  void save(const std::filesystem::path& file) const;

  // descriptors: N x 32 CV_8U. The bag of words (TF-IDF, L1-normalised); with feature_vector,
  // also the direct index at feature_level (1 = children of the root; a word shallower than
  // that level stands for itself).
  [[nodiscard]] BowVector transform(const cv::Mat& descriptors) const;
  [[nodiscard]] BowVector transform(const cv::Mat& descriptors, FeatureVector& feature_vector,
                                    int feature_level) const;
  // The word of one descriptor (32 bytes) and, with level_node, its ancestor at `level`.
  [[nodiscard]] WordId wordOf(const std::uint8_t* descriptor) const;
  [[nodiscard]] WordId wordOf(const std::uint8_t* descriptor, int level, NodeId& level_node) const;

  [[nodiscard]] int k() const { return k_; }
  [[nodiscard]] int depth() const { return depth_; }
  [[nodiscard]] std::size_t numWords() const { return word_nodes_.size(); }
  [[nodiscard]] const std::vector<VocabularyNode>& nodes() const { return nodes_; }
  [[nodiscard]] NodeId wordNode(WordId word) const { return word_nodes_.at(word); }
  [[nodiscard]] float idf(WordId word) const { return idf_.at(word); }
  [[nodiscard]] const VocabularyTrainingSummary& trainingSummary() const { return summary_; }

  friend bool operator==(const Vocabulary&, const Vocabulary&) = default;

 private:
  Vocabulary() = default;
  // Rebuilds children offsets, levels and the word list from the breadth-first child counts;
  // returns what is inconsistent about the tree, empty when nothing is.
  [[nodiscard]] std::string indexNodes();
  void computeIdf(const std::vector<cv::Mat>& descriptor_sets);

  int k_ = 0;
  int depth_ = 0;
  std::vector<VocabularyNode> nodes_;
  std::vector<NodeId> word_nodes_;
  std::vector<float> idf_;
  VocabularyTrainingSummary summary_;
};

// Bitwise majority of binary descriptors: bit b of the centre is set when more than half of the
// descriptors have it set (the centre minimising the summed Hamming distance). Empty input gives
// an all-zero centre.
[[nodiscard]] OrbDescriptor majorityCentre(const std::vector<const std::uint8_t*>& descriptors);

// The vocabulary shipped in config/, relative to the config folder.
inline constexpr const char* kDefaultVocabularyFile = "vocabulary/orb_synth_k10_d4.bin";

}  // namespace segslam::place
