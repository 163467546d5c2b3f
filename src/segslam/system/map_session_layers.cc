#include "segslam/system/map_session_layers.h"

#include <fmt/format.h>

#include <array>
#include <map>

#include "segslam/dense/ply_io.h"

namespace segslam::system {

namespace {

// Distinct colours for the first sessions, then repeated.
constexpr std::array<dense::Rgb, 6> kSessionColours = {{{74, 163, 255},
                                                        {255, 140, 26},
                                                        {58, 209, 122},
                                                        {230, 25, 75},
                                                        {145, 30, 180},
                                                        {255, 225, 25}}};

struct SessionClouds {
  dense::LabelledCloud points;
  dense::LabelledCloud keyframes;
};

}  // namespace

std::vector<std::filesystem::path> writeSessionLayers(const map::MapFileContents& contents,
                                                      const std::filesystem::path& folder) {
  std::map<std::uint32_t, SessionClouds> sessions;
  const auto colour = [](std::uint32_t session) {
    return kSessionColours[session % kSessionColours.size()];
  };
  for (const auto& point : contents.points) {
    sessions[point.session].points.add(point.position.cast<float>(), colour(point.session));
  }
  for (const auto& keyframe : contents.keyframes) {
    sessions[keyframe.session].keyframes.add(keyframe.T_cw.inverse().translation().cast<float>(),
                                             colour(keyframe.session));
  }
  std::vector<std::filesystem::path> written;
  for (const auto& [session, clouds] : sessions) {
    for (const auto& [kind, cloud] :
         {std::pair{"points", &clouds.points}, std::pair{"keyframes", &clouds.keyframes}}) {
      written.push_back(folder / fmt::format("session_{}_{}.ply", session, kind));
      dense::writePly(written.back(), *cloud);
    }
  }
  return written;
}

}  // namespace segslam::system
