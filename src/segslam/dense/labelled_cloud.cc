#include "segslam/dense/labelled_cloud.h"

#include <algorithm>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "segslam/dense/voxel_key.h"

namespace segslam::dense {

namespace {

struct SortEntry {
  std::uint64_t voxel;
  std::uint32_t label_instance;  // label << 16 | instance
  std::uint32_t index;
  bool operator<(const SortEntry& other) const {
    return std::tie(voxel, label_instance, index) <
           std::tie(other.voxel, other.label_instance, other.index);
  }
};

// The longest run of equal values of `value(entry)` in [begin, end), the first on ties.
template <typename Value>
std::pair<const SortEntry*, const SortEntry*> longestRun(const SortEntry* begin,
                                                         const SortEntry* end, Value value) {
  std::pair<const SortEntry*, const SortEntry*> best{begin, begin};
  for (const SortEntry* run = begin; run != end;) {
    const SortEntry* run_end = run;
    while (run_end != end && value(*run_end) == value(*run)) ++run_end;
    if (run_end - run > best.second - best.first) best = {run, run_end};
    run = run_end;
  }
  return best;
}

// One point for the entries of one voxel (sorted by label and instance).
void addMergedPoint(const LabelledCloud& cloud, const SortEntry* begin, const SortEntry* end,
                    LabelledCloud& out) {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d colour = Eigen::Vector3d::Zero();
  for (const SortEntry* e = begin; e != end; ++e) {
    position += cloud.points[e->index].cast<double>();
    for (int c = 0; c < 3; ++c) colour[c] += cloud.colours[e->index][c];
  }
  const auto [label_begin, label_end] =
      longestRun(begin, end, [](const SortEntry& e) { return e.label_instance >> 16; });
  const auto [instance_begin, instance_end] =
      longestRun(label_begin, label_end, [](const SortEntry& e) { return e.label_instance; });
  const double n = static_cast<double>(end - begin);
  const Eigen::Vector3d mean_colour = colour / n;
  out.add((position / n).cast<float>(),
          {static_cast<std::uint8_t>(mean_colour[0] + 0.5),
           static_cast<std::uint8_t>(mean_colour[1] + 0.5),
           static_cast<std::uint8_t>(mean_colour[2] + 0.5)},
          static_cast<std::uint8_t>(instance_begin->label_instance >> 16),
          static_cast<std::uint16_t>(instance_begin->label_instance & 0xffff));
}

}  // namespace

void LabelledCloud::reserve(std::size_t n) {
  points.reserve(n);
  colours.reserve(n);
  labels.reserve(n);
  instances.reserve(n);
}

void LabelledCloud::add(const Eigen::Vector3f& point, const Rgb& colour, std::uint8_t label,
                        std::uint16_t instance) {
  points.push_back(point);
  colours.push_back(colour);
  labels.push_back(label);
  instances.push_back(instance);
}

void LabelledCloud::append(const LabelledCloud& other) {
  points.insert(points.end(), other.points.begin(), other.points.end());
  colours.insert(colours.end(), other.colours.begin(), other.colours.end());
  labels.insert(labels.end(), other.labels.begin(), other.labels.end());
  instances.insert(instances.end(), other.instances.begin(), other.instances.end());
}

LabelledCloud LabelledCloud::select(const std::vector<std::size_t>& indices) const {
  LabelledCloud out;
  out.reserve(indices.size());
  for (std::size_t i : indices) out.add(points[i], colours[i], labels[i], instances[i]);
  return out;
}

LabelledCloud transformed(const LabelledCloud& cloud, const Eigen::Isometry3d& transform) {
  LabelledCloud out = cloud;
  const Eigen::Isometry3f transform_f = transform.cast<float>();
  for (auto& point : out.points) point = transform_f * point;
  return out;
}

LabelledCloud voxelDownsample(const LabelledCloud& cloud, double voxel_size) {
  if (!(voxel_size > 0.0)) throw std::invalid_argument("voxelDownsample: voxel size must be > 0");
  std::vector<SortEntry> entries(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    entries[i] = {voxelKey(cloud.points[i], voxel_size),
                  static_cast<std::uint32_t>(cloud.labels[i]) << 16 | cloud.instances[i],
                  static_cast<std::uint32_t>(i)};
  }
  std::sort(entries.begin(), entries.end());
  // Reserved exactly: a keyframe keeps its cloud for as long as it lives, and a vector grown by
  // doubling would keep up to twice the memory its points need.
  std::size_t voxels = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (i == 0 || entries[i].voxel != entries[i - 1].voxel) ++voxels;
  }
  LabelledCloud out;
  out.reserve(voxels);
  const SortEntry* const end = entries.data() + entries.size();
  for (const SortEntry* voxel = entries.data(); voxel != end;) {
    const SortEntry* voxel_end = voxel;
    while (voxel_end != end && voxel_end->voxel == voxel->voxel) ++voxel_end;
    addMergedPoint(cloud, voxel, voxel_end, out);
    voxel = voxel_end;
  }
  return out;
}

}  // namespace segslam::dense
