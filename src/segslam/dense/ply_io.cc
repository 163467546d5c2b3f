#include "segslam/dense/ply_io.h"

#include <fmt/format.h>

#include <bit>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "segslam/util/error.h"

namespace segslam::dense {

namespace {

struct VertexProperty {
  std::string name;
  std::string type;
  std::size_t offset = 0;
};

std::size_t scalarSize(const std::string& type) {
  static const std::map<std::string, std::size_t> sizes = {
      {"char", 1},  {"uchar", 1},   {"int8", 1},   {"uint8", 1},  {"short", 2}, {"ushort", 2},
      {"int16", 2}, {"uint16", 2},  {"int", 4},    {"uint", 4},   {"int32", 4}, {"uint32", 4},
      {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
  const auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

struct PlyHeader {
  std::size_t vertices = 0;
  std::size_t vertex_size = 0;
  std::vector<VertexProperty> properties;
};

PlyHeader readHeader(std::istream& in, const std::filesystem::path& file) {
  PlyHeader header;
  std::string line;
  int line_number = 0;
  const auto next = [&] {
    if (!std::getline(in, line)) util::failAt(file, line_number, "PLY header ends early");
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
  };
  next();
  if (line != "ply") util::failAt(file, 1, "not a PLY file (no 'ply' magic)");
  bool in_vertex = false;
  bool seen_vertex = false;
  bool format_ok = false;
  while (true) {
    next();
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "end_header") break;
    if (keyword == "format") {
      std::string format;
      words >> format;
      if (format != "binary_little_endian") {
        util::failAt(file, line_number, fmt::format("unsupported PLY format '{}'", format));
      }
      format_ok = true;
    } else if (keyword == "element") {
      std::string name;
      long long count = -1;
      words >> name >> count;
      if (!words || count < 0) util::failAt(file, line_number, "malformed element line");
      in_vertex = name == "vertex" && !seen_vertex;
      if (in_vertex) {
        if (!header.properties.empty() || header.vertices != 0) {
          util::failAt(file, line_number, "the vertex element must come first");
        }
        header.vertices = static_cast<std::size_t>(count);
        seen_vertex = true;
      } else if (!seen_vertex) {
        util::failAt(file, line_number, "the vertex element must come first");
      }
    } else if (keyword == "property" && in_vertex) {
      std::string type;
      std::string name;
      words >> type >> name;
      if (type == "list") util::failAt(file, line_number, "list properties in vertices");
      const std::size_t size = scalarSize(type);
      if (size == 0 || name.empty()) {
        util::failAt(file, line_number, fmt::format("unsupported property '{}'", line));
      }
      header.properties.push_back({name, type, header.vertex_size});
      header.vertex_size += size;
    }
  }
  if (!format_ok) util::failAt(file, "PLY header has no binary_little_endian format line");
  if (!seen_vertex) util::failAt(file, "PLY header has no vertex element");
  return header;
}

const VertexProperty* findProperty(const PlyHeader& header, const std::string& name) {
  for (const auto& property : header.properties) {
    if (property.name == name) return &property;
  }
  return nullptr;
}

float readCoordinate(const char* vertex, const VertexProperty& property) {
  if (property.type == "double" || property.type == "float64") {
    double value = 0.0;
    std::memcpy(&value, vertex + property.offset, sizeof value);
    return static_cast<float>(value);
  }
  float value = 0.0f;
  std::memcpy(&value, vertex + property.offset, sizeof value);
  return value;
}

}  // namespace

void writePly(const std::filesystem::path& file, const LabelledCloud& cloud) {
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary);
  if (!out) util::failAt(file, "cannot open for writing");
  out << "ply\nformat binary_little_endian 1.0\ncomment segslam dense map\n"
      << "element vertex " << cloud.size() << "\n"
      << "property float x\nproperty float y\nproperty float z\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  static_assert(std::endian::native == std::endian::little, "PLY writer assumes little endian");
  std::vector<char> data(cloud.size() * 15);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    std::memcpy(data.data() + i * 15, cloud.points[i].data(), 12);
    std::memcpy(data.data() + i * 15 + 12, cloud.colours[i].data(), 3);
  }
  out.write(data.data(), static_cast<std::streamsize>(data.size()));
  if (!out) util::failAt(file, "write failed");
}

LabelledCloud readPly(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) util::failAt(file, "cannot open PLY file");
  const PlyHeader header = readHeader(in, file);
  const VertexProperty* x = findProperty(header, "x");
  const VertexProperty* y = findProperty(header, "y");
  const VertexProperty* z = findProperty(header, "z");
  if (!x || !y || !z) util::failAt(file, "PLY vertices lack x, y or z");
  for (const auto* coordinate : {x, y, z}) {
    if (scalarSize(coordinate->type) < 4 || coordinate->type.find("int") != std::string::npos) {
      util::failAt(file,
                   fmt::format("PLY coordinate '{}' is not float or double", coordinate->name));
    }
  }
  const VertexProperty* colour[3] = {findProperty(header, "red"), findProperty(header, "green"),
                                     findProperty(header, "blue")};
  for (const auto* channel : colour) {
    if (channel && scalarSize(channel->type) != 1) {
      util::failAt(file, fmt::format("PLY colour '{}' is not 8-bit", channel->name));
    }
  }
  std::vector<char> data(header.vertices * header.vertex_size);
  in.read(data.data(), static_cast<std::streamsize>(data.size()));
  if (static_cast<std::size_t>(in.gcount()) != data.size()) {
    util::failAt(file, fmt::format("PLY data truncated: {} vertices announced, {} bytes of {} read",
                                   header.vertices, in.gcount(), data.size()));
  }
  LabelledCloud cloud;
  cloud.reserve(header.vertices);
  for (std::size_t i = 0; i < header.vertices; ++i) {
    const char* vertex = data.data() + i * header.vertex_size;
    Rgb rgb = {0, 0, 0};
    for (int c = 0; c < 3; ++c) {
      if (colour[c]) rgb[c] = static_cast<std::uint8_t>(vertex[colour[c]->offset]);
    }
    cloud.add({readCoordinate(vertex, *x), readCoordinate(vertex, *y), readCoordinate(vertex, *z)},
              rgb);
  }
  return cloud;
}

}  // namespace segslam::dense
