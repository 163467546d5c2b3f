#include "segslam/io/trajectory_io.h"

#include <fmt/format.h>
#include <fmt/os.h>
#include <spdlog/spdlog.h>

#include <cmath>

#include "segslam/util/error.h"
#include "segslam/util/output_folder.h"
#include "segslam/util/text_file.h"

namespace segslam::io {

namespace {

constexpr const char* kTumFormat = "timestamp tx ty tz qx qy qz qw";

core::StampedPose parsePoseRow(const util::TextRow& row, const std::filesystem::path& file) {
  util::requireFieldCount(row, 8, file, kTumFormat);
  static constexpr const char* kNames[] = {"timestamp", "tx", "ty", "tz", "qx", "qy", "qz", "qw"};
  double v[8];
  for (int i = 0; i < 8; ++i) v[i] = util::parseDouble(row.fields[i], file, row.line, kNames[i]);
  const Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);
  // Finite components can still overflow the norm (1e200), which would normalise to zero.
  const double norm = q.norm();
  if (norm < 1e-9) util::failAt(file, row.line, "quaternion is zero");
  if (!std::isfinite(norm)) util::failAt(file, row.line, "quaternion is too large to normalise");
  return {v[0], geometry::poseFromTranslationQuaternion({v[1], v[2], v[3]}, q)};
}

core::Trajectory trajectoryFromRows(const std::vector<util::TextRow>& rows,
                                    const std::filesystem::path& file) {
  if (rows.empty()) util::failAt(file, "trajectory file has no poses");
  std::vector<core::StampedPose> poses;
  std::vector<double> stamps;
  std::vector<int> lines;
  poses.reserve(rows.size());
  for (const auto& row : rows) {
    poses.push_back(parsePoseRow(row, file));
    stamps.push_back(poses.back().timestamp);
    lines.push_back(row.line);
  }
  const util::TimestampKeyedRows keyed = util::keyRowsByTimestamp(stamps, lines, file);
  if (!keyed.warning.empty()) spdlog::warn("{}", keyed.warning);
  std::vector<core::StampedPose> kept;
  kept.reserve(keyed.rows.size());
  for (const std::size_t row : keyed.rows) kept.push_back(poses[row]);
  return core::Trajectory(std::move(kept));
}

}  // namespace

core::Trajectory readTumTrajectory(const std::filesystem::path& file) {
  return trajectoryFromRows(util::readTextRows(file), file);
}

core::Trajectory parseTumTrajectory(std::string_view text, const std::filesystem::path& name) {
  return trajectoryFromRows(util::parseTextRows(text), name);
}

void writeTumTrajectory(const std::filesystem::path& file, const core::Trajectory& trajectory,
                        const std::string& header_comment) {
  util::createFolderFor(file);
  try {
    auto out = fmt::output_file(file.string());
    if (!header_comment.empty()) out.print("# {}\n", header_comment);
    out.print("# {}\n", kTumFormat);
    for (const auto& p : trajectory.poses()) {
      const Eigen::Vector3d t = p.T_wc.translation();
      const Eigen::Quaterniond q(p.T_wc.linear());
      out.print("{:.6f} {:.9f} {:.9f} {:.9f} {:.9f} {:.9f} {:.9f} {:.9f}\n", p.timestamp, t.x(),
                t.y(), t.z(), q.x(), q.y(), q.z(), q.w());
    }
  } catch (const std::system_error& e) {
    util::failAt(file, fmt::format("cannot write: {}", e.what()));
  }
}

}  // namespace segslam::io
