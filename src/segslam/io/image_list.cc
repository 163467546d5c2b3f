#include "segslam/io/image_list.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <utility>

#include "segslam/util/error.h"
#include "segslam/util/text_file.h"

namespace segslam::io {

namespace {

constexpr std::string_view kImageListFormat = "timestamp filename";
constexpr std::string_view kAssociationFormat = "rgb_timestamp rgb_file depth_timestamp depth_file";

ImageListEntry entryFromFields(const util::TextRow& row, std::size_t first_field,
                               const std::filesystem::path& file) {
  return {row.line, util::parseDouble(row.fields[first_field], file, row.line, "timestamp"),
          row.fields[first_field + 1]};
}

// The entries `timestamp_of` keys by time, as the TUM tools' read_file_list does.
template <typename Entry, typename TimestampOf>
std::vector<Entry> keyedByTimestamp(std::vector<Entry> entries, TimestampOf timestamp_of,
                                    const std::filesystem::path& file) {
  std::vector<double> stamps;
  std::vector<int> lines;
  for (const auto& entry : entries) {
    stamps.push_back(timestamp_of(entry).timestamp);
    lines.push_back(timestamp_of(entry).line);
  }
  const util::TimestampKeyedRows keyed = util::keyRowsByTimestamp(stamps, lines, file);
  if (!keyed.warning.empty()) spdlog::warn("{}", keyed.warning);
  std::vector<Entry> kept;
  kept.reserve(keyed.rows.size());
  for (const std::size_t row : keyed.rows) kept.push_back(std::move(entries[row]));
  return kept;
}

std::vector<ImageListEntry> imageListFromRows(const std::vector<util::TextRow>& rows,
                                              const std::filesystem::path& file) {
  std::vector<ImageListEntry> entries;
  entries.reserve(rows.size());
  for (const auto& row : rows) {
    util::requireFieldCount(row, 2, file, kImageListFormat);
    entries.push_back(entryFromFields(row, 0, file));
  }
  return keyedByTimestamp(
      std::move(entries),
      [](const ImageListEntry& entry) -> const ImageListEntry& { return entry; }, file);
}

void requireUniqueDepthTimestamps(const std::vector<AssociationEntry>& entries,
                                  const std::filesystem::path& file) {
  std::vector<std::pair<double, int>> stamps;  // (depth timestamp, line)
  stamps.reserve(entries.size());
  for (const auto& entry : entries) stamps.emplace_back(entry.depth.timestamp, entry.depth.line);
  std::sort(stamps.begin(), stamps.end());
  const auto repeated =
      std::adjacent_find(stamps.begin(), stamps.end(),
                         [](const auto& a, const auto& b) { return a.first == b.first; });
  if (repeated != stamps.end()) {
    util::failAt(file, std::next(repeated)->second,
                 fmt::format("depth timestamp {} is already used on line {}", repeated->first,
                             repeated->second));
  }
}

std::vector<AssociationEntry> associationListFromRows(const std::vector<util::TextRow>& rows,
                                                      const std::filesystem::path& file) {
  std::vector<AssociationEntry> entries;
  entries.reserve(rows.size());
  for (const auto& row : rows) {
    util::requireFieldCount(row, 4, file, kAssociationFormat);
    entries.push_back({entryFromFields(row, 0, file), entryFromFields(row, 2, file)});
  }
  entries = keyedByTimestamp(
      std::move(entries),
      [](const AssociationEntry& entry) -> const ImageListEntry& { return entry.rgb; }, file);
  requireUniqueDepthTimestamps(entries, file);
  return entries;
}

}  // namespace

std::vector<ImageListEntry> readImageList(const std::filesystem::path& file) {
  return imageListFromRows(util::readTextRows(file), file);
}

std::vector<ImageListEntry> parseImageList(std::string_view text,
                                           const std::filesystem::path& name) {
  return imageListFromRows(util::parseTextRows(text), name);
}

std::vector<AssociationEntry> readAssociationList(const std::filesystem::path& file) {
  return associationListFromRows(util::readTextRows(file), file);
}

std::vector<AssociationEntry> parseAssociationList(std::string_view text,
                                                   const std::filesystem::path& name) {
  return associationListFromRows(util::parseTextRows(text), name);
}

}  // namespace segslam::io
