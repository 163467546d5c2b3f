#include "segslam/place/vocabulary.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <deque>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <set>
#include <stdexcept>
#include <utility>

#include "segslam/util/error.h"

namespace segslam::place {

namespace {

using DescriptorRefs = std::vector<const std::uint8_t*>;

struct Cluster {
  OrbDescriptor centre;
  DescriptorRefs members;
};

void validateOptions(const VocabularyOptions& options) {
  if (options.k < 2 || options.k > 255) {
    throw std::invalid_argument("vocabulary: k must be in 2..255");
  }
  if (options.depth < 1 || options.depth > 10) {
    throw std::invalid_argument("vocabulary: depth must be in 1..10");
  }
  if (options.max_iterations < 1) {
    throw std::invalid_argument("vocabulary: max_iterations must be positive");
  }
}

OrbDescriptor toDescriptor(const std::uint8_t* bytes) {
  OrbDescriptor descriptor;
  std::memcpy(descriptor.data(), bytes, descriptor.size());
  return descriptor;
}

// Uniform in [0, 1) from the generator's raw output: the same numbers on every standard library.
double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// k-means++ seeding (Arthur & Vassilvitskii 2007) with squared Hamming distances. Returns fewer
// than k centres when the descriptors have fewer distinct values.
std::vector<OrbDescriptor> seedCentres(const DescriptorRefs& descriptors, int k,
                                       std::mt19937_64& rng) {
  std::vector<OrbDescriptor> centres;
  centres.push_back(toDescriptor(descriptors[rng() % descriptors.size()]));
  std::vector<double> weight(descriptors.size());
  for (std::size_t i = 0; i < descriptors.size(); ++i) {
    const double d = feature::descriptorDistance(descriptors[i], centres[0].data());
    weight[i] = d * d;
  }
  while (static_cast<int>(centres.size()) < k) {
    double total = 0.0;
    for (const double w : weight) total += w;
    if (total <= 0.0) break;
    const double target = uniform01(rng) * total;
    std::size_t chosen = 0;
    double cumulative = weight[0];
    while (cumulative <= target && chosen + 1 < descriptors.size()) cumulative += weight[++chosen];
    centres.push_back(toDescriptor(descriptors[chosen]));
    for (std::size_t i = 0; i < descriptors.size(); ++i) {
      const double d = feature::descriptorDistance(descriptors[i], centres.back().data());
      weight[i] = std::min(weight[i], d * d);
    }
  }
  return centres;
}

int nearestCentre(const std::uint8_t* descriptor, const std::vector<OrbDescriptor>& centres) {
  int best = 0;
  int best_distance = std::numeric_limits<int>::max();
  for (std::size_t c = 0; c < centres.size(); ++c) {
    const int distance = feature::descriptorDistance(descriptor, centres[c].data());
    if (distance < best_distance) {
      best_distance = distance;
      best = static_cast<int>(c);
    }
  }
  return best;
}

std::vector<Cluster> groupByAssignment(const DescriptorRefs& descriptors,
                                       const std::vector<int>& assignment, std::size_t clusters) {
  std::vector<Cluster> groups(clusters);
  for (std::size_t i = 0; i < descriptors.size(); ++i) {
    groups[static_cast<std::size_t>(assignment[i])].members.push_back(descriptors[i]);
  }
  return groups;
}

// k-majority (k-means with Hamming distance and bitwise majority centres). Empty clusters are
// dropped.
std::vector<Cluster> kMajority(const DescriptorRefs& descriptors, int k, int max_iterations,
                               std::mt19937_64& rng) {
  std::vector<OrbDescriptor> centres = seedCentres(descriptors, k, rng);
  std::vector<int> assignment(descriptors.size(), -1);
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    bool changed = false;
    for (std::size_t i = 0; i < descriptors.size(); ++i) {
      const int nearest = nearestCentre(descriptors[i], centres);
      changed = changed || nearest != assignment[i];
      assignment[i] = nearest;
    }
    // Ending on an assignment keeps the partition the nearest-centre one, which is the path
    // transform() takes: every training descriptor lands in the leaf it was clustered into.
    if (!changed || iteration + 1 == max_iterations) break;
    const auto groups = groupByAssignment(descriptors, assignment, centres.size());
    for (std::size_t c = 0; c < centres.size(); ++c) {
      if (!groups[c].members.empty()) centres[c] = majorityCentre(groups[c].members);
    }
  }
  auto groups = groupByAssignment(descriptors, assignment, centres.size());
  std::vector<Cluster> clusters;
  for (std::size_t c = 0; c < groups.size(); ++c) {
    if (groups[c].members.empty()) continue;
    groups[c].centre = centres[c];
    clusters.push_back(std::move(groups[c]));
  }
  return clusters;
}

// Splits a node's descriptors into at most k children: each distinct value its own child when
// there are at most k of them, k-majority clusters otherwise.
std::vector<Cluster> splitNode(const DescriptorRefs& descriptors, int k, int max_iterations,
                               std::mt19937_64& rng) {
  if (descriptors.size() <= static_cast<std::size_t>(k)) {
    std::vector<Cluster> distinct;
    for (const std::uint8_t* descriptor : descriptors) {
      const OrbDescriptor value = toDescriptor(descriptor);
      auto same = std::find_if(distinct.begin(), distinct.end(),
                               [&](const Cluster& cluster) { return cluster.centre == value; });
      if (same == distinct.end()) {
        distinct.push_back({value, {descriptor}});
      } else {
        same->members.push_back(descriptor);
      }
    }
    return distinct;
  }
  return kMajority(descriptors, k, max_iterations, rng);
}

void validateDescriptors(const cv::Mat& descriptors) {
  if (!descriptors.empty() &&
      (descriptors.type() != CV_8UC1 || descriptors.cols != feature::kDescriptorBytes)) {
    throw std::invalid_argument("vocabulary: descriptors must be N x 32 CV_8U");
  }
}

// Little-endian serialisation, independent of the host's byte order.
class ByteWriter {
 public:
  template <typename Unsigned>
  void put(Unsigned value) {
    for (std::size_t i = 0; i < sizeof(Unsigned); ++i) {
      bytes_.push_back(static_cast<char>((value >> (8 * i)) & 0xFF));
    }
  }
  void putFloat(float value) { put(std::bit_cast<std::uint32_t>(value)); }
  void putBytes(const void* data, std::size_t size) {
    const char* begin = static_cast<const char*>(data);
    bytes_.insert(bytes_.end(), begin, begin + size);
  }
  [[nodiscard]] const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

class ByteReader {
 public:
  ByteReader(std::string bytes, std::filesystem::path file)
      : bytes_(std::move(bytes)), file_(std::move(file)) {}

  template <typename Unsigned>
  Unsigned get() {
    const char* data = take(sizeof(Unsigned));
    Unsigned value = 0;
    for (std::size_t i = 0; i < sizeof(Unsigned); ++i) {
      value |= static_cast<Unsigned>(static_cast<unsigned char>(data[i])) << (8 * i);
    }
    return value;
  }
  float getFloat() { return std::bit_cast<float>(get<std::uint32_t>()); }
  void getBytes(void* out, std::size_t size) { std::memcpy(out, take(size), size); }
  [[nodiscard]] std::size_t remaining() const { return bytes_.size() - offset_; }
  [[noreturn]] void fail(const std::string& message) const {
    util::failAt(file_, "corrupt vocabulary file: " + message);
  }

 private:
  const char* take(std::size_t size) {
    if (size > remaining()) {
      util::failAt(file_, "truncated vocabulary file (" + std::to_string(bytes_.size()) +
                              " bytes, needs more at offset " + std::to_string(offset_) + ")");
    }
    const char* data = bytes_.data() + offset_;
    offset_ += size;
    return data;
  }

  std::string bytes_;
  std::filesystem::path file_;
  std::size_t offset_ = 0;
};

constexpr char kMagic[8] = {'S', 'E', 'G', 'S', 'B', 'O', 'W', 'V'};
constexpr std::uint32_t kVersion = 1;
constexpr std::size_t kNodeBytes = feature::kDescriptorBytes + sizeof(std::uint16_t);
constexpr std::uint32_t kMaxDescriptionBytes = 1 << 16;

std::string readFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) util::failAt(file, "cannot open vocabulary file");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) util::failAt(file, "cannot read vocabulary file");
  return bytes;
}

}  // namespace

OrbDescriptor majorityCentre(const std::vector<const std::uint8_t*>& descriptors) {
  std::array<std::size_t, feature::kDescriptorBits> ones{};
  for (const std::uint8_t* descriptor : descriptors) {
    for (int bit = 0; bit < feature::kDescriptorBits; ++bit) {
      ones[static_cast<std::size_t>(bit)] += (descriptor[bit / 8] >> (bit % 8)) & 1U;
    }
  }
  OrbDescriptor centre{};
  for (int bit = 0; bit < feature::kDescriptorBits; ++bit) {
    if (2 * ones[static_cast<std::size_t>(bit)] > descriptors.size()) {
      centre[static_cast<std::size_t>(bit / 8)] |= static_cast<std::uint8_t>(1U << (bit % 8));
    }
  }
  return centre;
}

Vocabulary Vocabulary::train(const std::vector<cv::Mat>& descriptor_sets,
                             const VocabularyOptions& options, VocabularyTrainingSummary summary) {
  validateOptions(options);
  DescriptorRefs all;
  for (const cv::Mat& set : descriptor_sets) {
    validateDescriptors(set);
    for (int row = 0; row < set.rows; ++row) all.push_back(set.ptr<std::uint8_t>(row));
  }
  if (all.empty()) throw std::invalid_argument("vocabulary: no training descriptors");

  Vocabulary vocabulary;
  vocabulary.k_ = options.k;
  vocabulary.depth_ = options.depth;
  vocabulary.summary_ = std::move(summary);
  auto& nodes = vocabulary.nodes_;
  nodes.emplace_back();
  std::mt19937_64 rng(options.seed);
  // Breadth first, in node order: children are appended in the order their parents are split.
  std::deque<std::pair<NodeId, DescriptorRefs>> pending;
  pending.emplace_back(0, std::move(all));
  while (!pending.empty()) {
    auto [node, members] = std::move(pending.front());
    pending.pop_front();
    if (nodes[node].level >= options.depth || members.size() < 2) continue;
    auto clusters = splitNode(members, options.k, options.max_iterations, rng);
    if (clusters.size() < 2) continue;
    const auto level = static_cast<std::uint8_t>(nodes[node].level + 1);
    nodes[node].num_children = static_cast<std::uint16_t>(clusters.size());
    for (auto& cluster : clusters) {
      VocabularyNode child;
      child.centre = cluster.centre;
      child.level = level;
      pending.emplace_back(static_cast<NodeId>(nodes.size()), std::move(cluster.members));
      nodes.push_back(child);
    }
  }
  if (const auto problem = vocabulary.indexNodes(); !problem.empty()) {
    throw std::logic_error("vocabulary: " + problem);
  }
  vocabulary.computeIdf(descriptor_sets);
  return vocabulary;
}

std::string Vocabulary::indexNodes() {
  word_nodes_.clear();
  NodeId next_child = 1;
  for (NodeId node = 0; node < nodes_.size(); ++node) {
    VocabularyNode& current = nodes_[node];
    if (current.num_children == 0) {
      current.word = static_cast<WordId>(word_nodes_.size());
      word_nodes_.push_back(node);
      continue;
    }
    if (current.num_children > k_) return "a node has more than k children";
    if (current.level >= depth_) return "the tree is deeper than its depth";
    if (next_child <= node) return "a node's children come before it";
    if (nodes_.size() - next_child < current.num_children) return "children beyond the last node";
    current.first_child = next_child;
    next_child += current.num_children;
    for (NodeId child = current.first_child; child < next_child; ++child) {
      nodes_[child].level = static_cast<std::uint8_t>(current.level + 1);
    }
  }
  if (next_child != nodes_.size()) return "nodes that are nobody's child";
  if (word_nodes_.size() < 2) return "fewer than two words";
  return {};
}

void Vocabulary::computeIdf(const std::vector<cv::Mat>& descriptor_sets) {
  std::vector<std::uint32_t> documents_with_word(numWords(), 0);
  std::size_t documents = 0;
  for (const cv::Mat& set : descriptor_sets) {
    if (set.empty()) continue;
    ++documents;
    std::set<WordId> words;
    for (int row = 0; row < set.rows; ++row) words.insert(wordOf(set.ptr<std::uint8_t>(row)));
    for (const WordId word : words) ++documents_with_word[word];
  }
  idf_.resize(numWords());
  for (std::size_t word = 0; word < numWords(); ++word) {
    const double with_word = std::max<std::uint32_t>(documents_with_word[word], 1);
    idf_[word] = static_cast<float>(std::log(static_cast<double>(documents) / with_word));
  }
}

WordId Vocabulary::wordOf(const std::uint8_t* descriptor) const {
  NodeId level_node = 0;
  return wordOf(descriptor, 0, level_node);
}

WordId Vocabulary::wordOf(const std::uint8_t* descriptor, int level, NodeId& level_node) const {
  NodeId node = 0;
  level_node = 0;
  while (nodes_[node].num_children > 0) {
    const VocabularyNode& parent = nodes_[node];
    NodeId best = parent.first_child;
    int best_distance = std::numeric_limits<int>::max();
    for (NodeId child = parent.first_child; child < parent.first_child + parent.num_children;
         ++child) {
      const int distance = feature::descriptorDistance(descriptor, nodes_[child].centre.data());
      if (distance < best_distance) {
        best_distance = distance;
        best = child;
      }
    }
    node = best;
    if (nodes_[node].level <= level) level_node = node;
  }
  return nodes_[node].word;
}

BowVector Vocabulary::transform(const cv::Mat& descriptors) const {
  FeatureVector unused;
  return transform(descriptors, unused, 0);
}

BowVector Vocabulary::transform(const cv::Mat& descriptors, FeatureVector& feature_vector,
                                int feature_level) const {
  validateDescriptors(descriptors);
  feature_vector.clear();
  BowVector bow;
  for (int row = 0; row < descriptors.rows; ++row) {
    NodeId level_node = 0;
    const WordId word = wordOf(descriptors.ptr<std::uint8_t>(row), feature_level, level_node);
    if (feature_level > 0) feature_vector[level_node].push_back(row);
    // Term frequency times IDF; the 1 / N of the frequency cancels in the normalisation.
    if (idf_[word] > 0.0F) bow[word] += idf_[word];
  }
  normaliseL1(bow);
  return bow;
}

void Vocabulary::save(const std::filesystem::path& file) const {
  ByteWriter out;
  out.putBytes(kMagic, sizeof kMagic);
  out.put(kVersion);
  out.put(static_cast<std::uint32_t>(feature::kDescriptorBytes));
  out.put(static_cast<std::uint32_t>(k_));
  out.put(static_cast<std::uint32_t>(depth_));
  out.put(summary_.images);
  out.put(summary_.descriptors);
  const std::string description = summary_.description.substr(0, kMaxDescriptionBytes);
  out.put(static_cast<std::uint32_t>(description.size()));
  out.putBytes(description.data(), description.size());
  out.put(static_cast<std::uint32_t>(nodes_.size()));
  for (const VocabularyNode& node : nodes_) {
    out.putBytes(node.centre.data(), node.centre.size());
    out.put(node.num_children);
  }
  out.put(static_cast<std::uint32_t>(idf_.size()));
  for (const float weight : idf_) out.putFloat(weight);

  std::ofstream stream(file, std::ios::binary | std::ios::trunc);
  stream.write(out.bytes().data(), static_cast<std::streamsize>(out.bytes().size()));
  stream.close();
  if (!stream) util::failAt(file, "cannot write vocabulary file");
}

Vocabulary Vocabulary::load(const std::filesystem::path& file) {
  ByteReader in(readFile(file), file);
  char magic[sizeof kMagic];
  in.getBytes(magic, sizeof magic);
  if (std::memcmp(magic, kMagic, sizeof kMagic) != 0) {
    util::failAt(file, "not a segslam vocabulary file (wrong magic number)");
  }
  if (const auto version = in.get<std::uint32_t>(); version != kVersion) {
    util::failAt(file, "unsupported vocabulary file version " + std::to_string(version) +
                           " (this build reads version " + std::to_string(kVersion) + ")");
  }
  if (in.get<std::uint32_t>() != feature::kDescriptorBytes) in.fail("descriptor size is not 32");
  Vocabulary vocabulary;
  vocabulary.k_ = static_cast<int>(in.get<std::uint32_t>());
  vocabulary.depth_ = static_cast<int>(in.get<std::uint32_t>());
  if (vocabulary.k_ < 2 || vocabulary.k_ > 255) in.fail("k outside 2..255");
  if (vocabulary.depth_ < 1 || vocabulary.depth_ > 10) in.fail("depth outside 1..10");
  vocabulary.summary_.images = in.get<std::uint64_t>();
  vocabulary.summary_.descriptors = in.get<std::uint64_t>();
  const auto description_size = in.get<std::uint32_t>();
  if (description_size > kMaxDescriptionBytes) in.fail("description too long");
  vocabulary.summary_.description.resize(description_size);
  in.getBytes(vocabulary.summary_.description.data(), description_size);

  const auto num_nodes = in.get<std::uint32_t>();
  // Checked before allocating, so that a corrupt count cannot ask for gigabytes.
  if (num_nodes > in.remaining() / kNodeBytes) {
    util::failAt(file, "truncated vocabulary file (" + std::to_string(num_nodes) +
                           " nodes announced, fewer stored)");
  }
  vocabulary.nodes_.resize(num_nodes);
  for (VocabularyNode& node : vocabulary.nodes_) {
    in.getBytes(node.centre.data(), node.centre.size());
    node.num_children = in.get<std::uint16_t>();
  }
  if (const auto problem = vocabulary.indexNodes(); !problem.empty()) in.fail(problem);
  if (in.get<std::uint32_t>() != vocabulary.numWords()) in.fail("word count does not match tree");
  vocabulary.idf_.resize(vocabulary.numWords());
  for (float& weight : vocabulary.idf_) {
    weight = in.getFloat();
    if (!std::isfinite(weight) || weight < 0.0F) in.fail("IDF weight not a finite number >= 0");
  }
  if (in.remaining() != 0) in.fail(std::to_string(in.remaining()) + " bytes after the end");
  return vocabulary;
}

}  // namespace segslam::place
