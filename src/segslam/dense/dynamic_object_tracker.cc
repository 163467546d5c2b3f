#include "segslam/dense/dynamic_object_tracker.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <tuple>

namespace segslam::dense {

DynamicObjectTracker::DynamicObjectTracker(DynamicTrackingOptions options) : options_(options) {}

std::vector<std::size_t> DynamicObjectTracker::link(
    double timestamp, const std::vector<LabelSegment>& segments) const {
  const std::size_t none = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> track_of(segments.size(), none);
  // Candidate links, nearest relative to the track's reach first: (distance / reach, segment,
  // track). A person back after a long absence is within reach of their old track, as is another
  // person; the track seen a moment ago nearby is the likelier one.
  std::vector<std::tuple<double, std::size_t, std::size_t>> candidates;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    if (segments[s].instance != 0 || segments[s].indices.size() < options_.min_track_points) {
      continue;
    }
    for (std::size_t t = 0; t < tracks_.size(); ++t) {
      const DynamicTrack& track = tracks_[t];
      const double gap = timestamp - track.last_seen;
      if (track.instance != 0 || track.label != segments[s].label || gap > options_.max_gap) {
        continue;
      }
      const double distance = (segments[s].centroid - track.last_centroid).norm();
      const bool still = track.travelled <= options_.slack;
      const double reach = still && segments[s].indices.size() < options_.min_reach_points
                               ? options_.slack
                               : options_.max_speed * gap + options_.slack;
      if (distance <= reach) candidates.emplace_back(distance / reach, s, t);
    }
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<bool> track_taken(tracks_.size(), false);
  for (const auto& [relative_distance, s, t] : candidates) {
    if (track_of[s] != none || track_taken[t]) continue;
    track_of[s] = t;
    track_taken[t] = true;
  }
  return track_of;
}

std::size_t DynamicObjectTracker::nearbyTrack(const std::vector<LabelSegment>& segments,
                                              const std::vector<std::size_t>& track_of,
                                              std::size_t segment) const {
  std::size_t nearest_track = tracks_.size();
  float nearest = std::numeric_limits<float>::max();
  for (std::size_t other = 0; other < segments.size(); ++other) {
    if (track_of[other] >= tracks_.size() || segments[other].instance != 0 ||
        segments[other].label != segments[segment].label) {
      continue;
    }
    const float gap = boundsGap(segments[segment], segments[other]);
    if (gap <= options_.slack && gap < nearest) {
      nearest = gap;
      nearest_track = track_of[other];
    }
  }
  return nearest_track;
}

void DynamicObjectTracker::extend(std::size_t track, std::uint64_t keyframe_id, double timestamp,
                                  const LabelledCloud& points, const LabelSegment& segment) {
  DynamicTrack& target = tracks_[track];
  // Segments come largest first: the first of a keyframe places the track.
  if (target.keyframes.empty()) target.first_centroid = segment.centroid;
  if (target.keyframes.empty() || target.keyframes.back() != keyframe_id) {
    target.travelled =
        std::max(target.travelled, (segment.centroid - target.first_centroid).norm());
    target.keyframes.push_back(keyframe_id);
    target.keyframe_points += points.size();
    target.last_centroid = segment.centroid;
    target.last_seen = timestamp;
  }
  target.points.append(points.select(segment.indices));
}

void DynamicObjectTracker::addKeyFrame(std::uint64_t keyframe_id, double timestamp,
                                       const LabelledCloud& points,
                                       const std::vector<LabelSegment>& segments) {
  std::vector<std::size_t> track_of = link(timestamp, segments);
  std::vector<std::size_t> largest_first(segments.size());
  std::iota(largest_first.begin(), largest_first.end(), std::size_t{0});
  std::stable_sort(largest_first.begin(), largest_first.end(), [&](std::size_t a, std::size_t b) {
    return segments[a].indices.size() > segments[b].indices.size();
  });
  for (std::size_t s : largest_first) {
    const LabelSegment& segment = segments[s];
    if (segment.instance != 0) {
      const auto same = std::find_if(tracks_.begin(), tracks_.end(), [&](const auto& t) {
        return t.instance == segment.instance && t.label == segment.label;
      });
      track_of[s] = static_cast<std::size_t>(same - tracks_.begin());
    } else if (track_of[s] >= tracks_.size()) {
      track_of[s] = nearbyTrack(segments, track_of, s);
      if (track_of[s] >= tracks_.size() && segment.indices.size() < options_.min_track_points) {
        continue;
      }
    }
    if (track_of[s] >= tracks_.size()) {
      track_of[s] = tracks_.size();
      DynamicTrack& created = tracks_.emplace_back();
      created.label = segment.label;
      created.instance = segment.instance;
    }
    extend(track_of[s], keyframe_id, timestamp, points, segment);
  }
}

}  // namespace segslam::dense
