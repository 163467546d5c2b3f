#include "segslam/dense/dynamic_object_tracker.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <tuple>

namespace segslam::dense {

DynamicObjectTracker::DynamicObjectTracker(DynamicTrackingOptions options) : options_(options) {}

namespace {

// Whether `segment` can be the person of a track who moved on: the track's last place was seen
// empty since they were last seen there, or this keyframe shows that very segment there or behind
// it. A person in front of the place may be someone else walking past the still one.
bool placeLeftFor(const DynamicTrack& track, const PlaceSight& sight, std::size_t segment) {
  return track.place_left ||
         (sight.kind == PlaceSight::Kind::kSegment && sight.segment == segment && !sight.in_front);
}

}  // namespace

std::vector<std::size_t> DynamicObjectTracker::link(double timestamp,
                                                    const std::vector<LabelSegment>& segments,
                                                    const std::vector<PlaceSight>& last_places,
                                                    const std::vector<bool>& stayed) const {
  const std::size_t none = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> track_of(segments.size(), none);
  // Candidate links within reach, nearest first: (distance, segment, track). A person back after
  // a long absence is within reach of their old track, as is another person; the track seen a
  // moment ago nearby is the likelier one. Relative to each track's reach, the long-unseen track
  // won: a walker 0.12 m from their place of 0.37 s before went to a track 0.40 m away and 7.4 s
  // old (0.40 / 15.3 m of walking reach against 0.12 / 1.23), and came back as a second track.
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
      // A track not yet seen moving goes only as far as slack unless its person can have got up
      // and walked: seen whole, and their place seen left.
      const bool still = track.travelled <= options_.slack && !track.came_back;
      const bool may_walk = segments[s].indices.size() >= options_.min_reach_points &&
                            placeLeftFor(track, last_places[t], s);
      const double walking_reach = options_.max_speed * gap + options_.slack;
      // Nor does anyone walk to where something stood before: a chair beside a seated person,
      // labelled a person in a few keyframes, took a walker's track 1.8 m across the room, and
      // the walker came back as a second track.
      const double reach = (still && !may_walk) || stayed[s] ? options_.slack : walking_reach;
      if (distance <= reach) candidates.emplace_back(distance, s, t);
    }
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<bool> track_taken(tracks_.size(), false);
  for (const auto& [distance, s, t] : candidates) {
    if (track_of[s] != none || track_taken[t]) continue;
    track_of[s] = t;
    track_taken[t] = true;
  }
  return track_of;
}

std::size_t DynamicObjectTracker::nearbyTrack(const std::vector<LabelSegment>& segments,
                                              const std::vector<std::size_t>& track_of,
                                              std::size_t segment,
                                              const KeyFrameDepthView& view) const {
  // A segment as large as a person seen on their own, with the room seen between it and a
  // tracked one, is someone else walking beside them (two walkers side by side made one track).
  const bool whole = segments[segment].indices.size() >= options_.min_reach_points;
  std::size_t nearest_track = tracks_.size();
  float nearest = std::numeric_limits<float>::max();
  for (std::size_t other = 0; other < segments.size(); ++other) {
    if (track_of[other] >= tracks_.size() || segments[other].instance != 0 ||
        segments[other].label != segments[segment].label) {
      continue;
    }
    if (whole &&
        view.showsBackgroundBetween(segments[segment].centroid, segments[other].centroid)) {
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
  // Linked segments come first: the first of a keyframe places the track.
  if (target.keyframes.empty()) target.first_centroid = segment.centroid;
  if (target.keyframes.empty() || target.keyframes.back() != keyframe_id) {
    target.travelled =
        std::max(target.travelled, (segment.centroid - target.first_centroid).norm());
    target.keyframes.push_back(keyframe_id);
    target.keyframe_points += points.size();
    target.last_centroid = segment.centroid;
    target.last_seen = timestamp;
    if (target.place_left) target.came_back = true;
    target.place_left = false;
    // Only the segment that places the track: a blob joining a seated person by touching them
    // stood where a keyframe had seen the room empty.
    if (!target.arrived) target.arrived = seenEmptyBefore(segment.centroid);
  }
  target.points.append(points.select(segment.indices));
}

void DynamicObjectTracker::addKeyFrame(std::uint64_t keyframe_id, double timestamp,
                                       const LabelledCloud& points,
                                       const std::vector<LabelSegment>& segments,
                                       KeyFrameDepthView view) {
  std::vector<PlaceSight> last_places;
  for (DynamicTrack& track : tracks_) {
    last_places.push_back(view.look(track.last_centroid));
    if (last_places.back().kind == PlaceSight::Kind::kEmpty) {
      track.place_left = true;
      track.left_a_place = true;
    }
  }
  std::vector<bool> stayed(segments.size(), false);
  for (std::size_t s = 0; s < segments.size(); ++s) {
    stayed[s] = stoodThereBefore(segments[s].centroid);
  }
  std::vector<std::size_t> track_of = link(timestamp, segments, last_places, stayed);
  // The linked segments first: each places its track, and a segment that only joins a track by
  // touching its segment must not (a blob beside a seated person moved their track 0.9 m, and the
  // person, seen again where they sat, was then taken by a walker's track). Then the largest.
  std::vector<std::size_t> order(segments.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const bool a_linked = track_of[a] < tracks_.size();
    const bool b_linked = track_of[b] < tracks_.size();
    if (a_linked != b_linked) return a_linked;
    return segments[a].indices.size() > segments[b].indices.size();
  });
  for (std::size_t s : order) {
    const LabelSegment& segment = segments[s];
    if (segment.instance != 0) {
      const auto same = std::find_if(tracks_.begin(), tracks_.end(), [&](const auto& t) {
        return t.instance == segment.instance && t.label == segment.label;
      });
      track_of[s] = static_cast<std::size_t>(same - tracks_.begin());
    } else if (track_of[s] >= tracks_.size()) {
      track_of[s] = nearbyTrack(segments, track_of, s, view);
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
    spdlog::debug(
        "dynamic objects: keyframe {} segment of {} points at ({:.2f}, {:.2f}, {:.2f}){} -> track "
        "{}",
        keyframe_id, segment.indices.size(), segment.centroid.x(), segment.centroid.y(),
        segment.centroid.z(), stayed[s] ? ", where something stood before," : "", track_of[s]);
  }
  earlier_views_.push_back(std::move(view));
}

bool DynamicObjectTracker::seenEmptyBefore(const Eigen::Vector3f& place) const {
  return std::any_of(earlier_views_.begin(), earlier_views_.end(), [&](const auto& view) {
    return view.look(place).kind == PlaceSight::Kind::kEmpty;
  });
}

bool DynamicObjectTracker::stoodThereBefore(const Eigen::Vector3f& place) const {
  int static_views = 0;
  int empty_views = 0;
  for (const KeyFrameDepthView& view : earlier_views_) {
    const PlaceSight::Kind kind = view.look(place).kind;
    static_views += kind == PlaceSight::Kind::kStatic ? 1 : 0;
    empty_views += kind == PlaceSight::Kind::kEmpty ? 1 : 0;
  }
  return static_views > empty_views;
}

}  // namespace segslam::dense
