#include "segslam/dense/object_association.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "segslam/dense/voxel_key.h"

namespace segslam::dense {

std::uint8_t ObservedObject::label() const {
  std::uint8_t best = 0;
  int best_votes = 0;
  for (const auto& [label, votes] : label_votes) {
    if (votes > best_votes) {
      best = label;
      best_votes = votes;
    }
  }
  return best;
}

double ObservedObject::confidence() const {
  int total = 0;
  for (const auto& [label, votes] : label_votes) total += votes;
  const auto it = label_votes.find(label());
  return total > 0 && it != label_votes.end() ? static_cast<double>(it->second) / total : 0.0;
}

Eigen::Vector3f ObservedObject::centroid() const {
  if (point_count == 0) return Eigen::Vector3f::Zero();
  return (point_sum / static_cast<double>(point_count)).cast<float>();
}

ObjectAssociator::ObjectAssociator(double cell_size, ObjectAssociationOptions options)
    : cell_size_(cell_size), options_(options) {}

std::size_t ObjectAssociator::resolve(std::size_t object) const {
  while (merged_into_[object] != object) object = merged_into_[object];
  return object;
}

std::map<std::size_t, std::size_t> ObjectAssociator::overlaps(const LabelSegment& segment) const {
  std::map<std::size_t, std::size_t> shared;
  std::vector<std::size_t> here;
  for (std::uint64_t cell : segment.cells) {
    here.clear();
    const Eigen::Vector3i centre = unpackCell(cell);
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = objects_at_cell_.find(packCell(centre + Eigen::Vector3i(dx, dy, dz)));
          if (it == objects_at_cell_.end()) continue;
          for (std::size_t object : it->second) here.push_back(resolve(object));
        }
      }
    }
    std::sort(here.begin(), here.end());
    here.erase(std::unique(here.begin(), here.end()), here.end());
    for (std::size_t object : here) ++shared[object];
  }
  return shared;
}

std::vector<std::size_t> ObjectAssociator::matches(const LabelSegment& segment) const {
  if (segment.instance != 0) {
    for (std::size_t object = 0; object < objects_.size(); ++object) {
      if (merged_into_[object] == object && objects_[object].instance == segment.instance) {
        return {object};
      }
    }
    return {};
  }
  std::vector<std::pair<std::size_t, std::size_t>> same_label;  // (shared cells, object)
  std::vector<std::pair<std::size_t, std::size_t>> other_label;
  const double segment_cells = static_cast<double>(segment.cells.size());
  for (const auto& [object, shared] : overlaps(segment)) {
    const double object_cells = static_cast<double>(objects_[object].cell_counts.size());
    const double share = static_cast<double>(shared) / std::min(segment_cells, object_cells);
    if (share < options_.min_overlap) continue;
    if (objects_[object].label() == segment.label) {
      same_label.emplace_back(shared, object);
    } else if (static_cast<double>(shared) >= options_.min_overlap_other_label * segment_cells) {
      other_label.emplace_back(shared, object);
    }
  }
  const auto most_shared_first = [](auto& list) {
    std::sort(list.begin(), list.end(), [](const auto& a, const auto& b) {
      return a.first != b.first ? a.first > b.first : a.second < b.second;
    });
  };
  most_shared_first(same_label);
  most_shared_first(other_label);
  std::vector<std::size_t> result;
  if (!same_label.empty()) {
    result.push_back(same_label.front().second);
    for (std::size_t k = 1; k < same_label.size(); ++k) {
      const auto [shared, object] = same_label[k];
      const auto object_cells = static_cast<double>(objects_[object].cell_counts.size());
      if (static_cast<double>(shared) >= options_.min_merge_cover * object_cells) {
        result.push_back(object);
      }
    }
  } else if (!other_label.empty()) {
    result.push_back(other_label.front().second);
  }
  return result;
}

void ObjectAssociator::merge(std::size_t from, std::size_t into) {
  merge(objects_[from], objects_[into]);
  merged_into_[from] = into;
}

void ObjectAssociator::merge(ObservedObject& source, ObservedObject& target) {
  for (const auto& [label, votes] : source.label_votes) target.label_votes[label] += votes;
  std::vector<std::uint64_t> keyframes;
  std::set_union(target.keyframes.begin(), target.keyframes.end(), source.keyframes.begin(),
                 source.keyframes.end(), std::back_inserter(keyframes));
  target.keyframes = std::move(keyframes);
  for (const auto& [cell, count] : source.cell_counts) {
    int& target_count = target.cell_counts[cell];
    target_count = std::max(target_count, count);
  }
  target.point_sum += source.point_sum;
  target.point_count += source.point_count;
  source = ObservedObject();
}

bool ObjectAssociator::fragmentsOfOne(const ObservedObject& a, const ObservedObject& b) const {
  if (a.instance != 0 || b.instance != 0) return false;  // the ids have decided
  const bool a_smaller = a.cell_counts.size() < b.cell_counts.size();
  const ObservedObject& smaller = a_smaller ? a : b;
  const ObservedObject& larger = a_smaller ? b : a;
  std::size_t shared = 0;
  for (const auto& [cell, count] : smaller.cell_counts) shared += larger.cell_counts.count(cell);
  const auto smaller_cells = static_cast<double>(smaller.cell_counts.size());
  if (static_cast<double>(shared) >= options_.min_fragment_overlap * smaller_cells) return true;
  return smaller_cells <=
             options_.max_part_share * static_cast<double>(larger.cell_counts.size()) &&
         withinReach(smaller, larger);
}

bool ObjectAssociator::withinReach(const ObservedObject& part, const ObservedObject& whole) const {
  const int reach = static_cast<int>(std::ceil(options_.fragment_reach / cell_size_));
  const auto bounds = [](const ObservedObject& object) {
    Eigen::AlignedBox3i box;
    for (const auto& [cell, count] : object.cell_counts) box.extend(unpackCell(cell));
    return box;
  };
  Eigen::AlignedBox3i part_box = bounds(part);
  part_box.extend(part_box.min() - Eigen::Vector3i::Constant(reach));
  part_box.extend(part_box.max() + Eigen::Vector3i::Constant(reach));
  if (!part_box.intersects(bounds(whole))) return false;
  for (const auto& [cell, count] : part.cell_counts) {
    const Eigen::Vector3i centre = unpackCell(cell);
    for (int dx = -reach; dx <= reach; ++dx) {
      for (int dy = -reach; dy <= reach; ++dy) {
        for (int dz = -reach; dz <= reach; ++dz) {
          if (whole.cell_counts.count(packCell(centre + Eigen::Vector3i(dx, dy, dz)))) return true;
        }
      }
    }
  }
  return false;
}

void ObjectAssociator::record(std::size_t object, std::uint64_t keyframe_id, KeyFrameView view) {
  ObservedObject& target = objects_[object];
  const auto most_points =
      std::max_element(view.label_points.begin(), view.label_points.end(),
                       [](const auto& a, const auto& b) { return a.second < b.second; });
  ++target.label_votes[most_points->first];
  if (target.keyframes.empty() || target.keyframes.back() != keyframe_id) {
    target.keyframes.push_back(keyframe_id);
  }
  std::sort(view.cells.begin(), view.cells.end());
  view.cells.erase(std::unique(view.cells.begin(), view.cells.end()), view.cells.end());
  for (std::uint64_t cell : view.cells) {
    if (target.cell_counts[cell]++ == 0) objects_at_cell_[cell].push_back(object);
  }
  target.point_sum += view.point_sum;
  target.point_count += view.point_count;
}

void ObjectAssociator::addKeyFrame(std::uint64_t keyframe_id,
                                   const std::vector<LabelSegment>& segments) {
  std::map<std::size_t, KeyFrameView> views;
  for (const LabelSegment& segment : segments) {
    const std::vector<std::size_t> found = matches(segment);
    std::size_t object = 0;
    if (found.empty()) {
      object = objects_.size();
      objects_.emplace_back().instance = segment.instance;
      merged_into_.push_back(object);
    } else {
      object = found.front();
      for (std::size_t k = 1; k < found.size(); ++k) {
        merge(found[k], object);
        if (auto it = views.find(found[k]); it != views.end()) {
          KeyFrameView& into = views[object];
          for (const auto& [label, points] : it->second.label_points) {
            into.label_points[label] += points;
          }
          into.cells.insert(into.cells.end(), it->second.cells.begin(), it->second.cells.end());
          into.point_sum += it->second.point_sum;
          into.point_count += it->second.point_count;
          views.erase(it);
        }
      }
    }
    KeyFrameView& view = views[object];
    view.label_points[segment.label] += segment.indices.size();
    view.cells.insert(view.cells.end(), segment.cells.begin(), segment.cells.end());
    view.point_sum += segment.centroid.cast<double>() * static_cast<double>(segment.indices.size());
    view.point_count += segment.indices.size();
  }
  for (auto& [object, view] : views) record(object, keyframe_id, std::move(view));
}

std::vector<ObservedObject> ObjectAssociator::objects() const {
  std::vector<ObservedObject> result;
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    if (merged_into_[i] == i) result.push_back(objects_[i]);
  }
  // Merging can make a new overlap, so until nothing changes.
  for (bool merged = true; merged;) {
    merged = false;
    for (std::size_t a = 0; a < result.size(); ++a) {
      for (std::size_t b = a + 1; b < result.size(); ++b) {
        if (result[a].label() != result[b].label() || !fragmentsOfOne(result[a], result[b])) {
          continue;
        }
        merge(result[b], result[a]);
        result.erase(result.begin() + static_cast<std::ptrdiff_t>(b));
        merged = true;
        --b;
      }
    }
  }
  return result;
}

}  // namespace segslam::dense
