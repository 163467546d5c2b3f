#include "segslam/synth/room_layout.h"

#include <algorithm>
#include <array>
#include <numbers>
#include <random>

#include "segslam/geometry/angles.h"

namespace segslam::synth {

namespace {

using core::SemanticClass;
using V = Eigen::Vector3d;

constexpr double kRoomX = 5.2;
constexpr double kRoomY = 5.0;
constexpr double kRoomZ = 2.7;
constexpr double kBoard = 0.02;  // thickness of shelf boards and sides

geometry::Pose placement(double x, double y, double yaw) {
  geometry::Pose pose = geometry::Pose::Identity();
  pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  pose.translation() = V(x, y, 0.0);
  return pose;
}

void addRoomSurfaces(SceneBuilder& builder) {
  struct Surface {
    int face;  // index into boxFaces(): +x, -x, +y, -y, +z, -z
    SemanticClass semantic_class;
    const char* name;
    Material material;
  };
  static constexpr std::array<Surface, 6> kSurfaces{{
      {5, SemanticClass::kFloor, "floor", Material::kFloorPlanks},
      {4, SemanticClass::kCeiling, "ceiling", Material::kCeilingTiles},
      {0, SemanticClass::kWall, "wall_x_max", Material::kWallpaper},
      {1, SemanticClass::kWall, "wall_x_min", Material::kWallpaper},
      {2, SemanticClass::kWall, "wall_y_max", Material::kWallpaper},
      {3, SemanticClass::kWall, "wall_y_min", Material::kWallpaper},
  }};
  const auto faces = boxFaces(V::Zero(), V(kRoomX, kRoomY, kRoomZ));
  for (const Surface& surface : kSurfaces) {
    builder.beginObject(surface.semantic_class, surface.name);
    // Seen from inside the room: the box faces turned around.
    builder.addRect(flipped(faces[surface.face]), surface.material);
  }
}

void addTable(SceneBuilder& builder) {
  builder.beginObject(SemanticClass::kTable, "table");
  builder.addBox({2.75, 1.9, 0.71}, {3.65, 3.1, 0.75}, Material::kWood);
  for (double x : {2.79, 3.56}) {
    for (double y : {1.94, 3.01})
      builder.addBox({x, y, 0.0}, {x + 0.05, y + 0.05, 0.71}, Material::kWood);
  }
}

void addMonitor(SceneBuilder& builder) {
  builder.beginObject(SemanticClass::kMonitor, "monitor");
  builder.addBox({3.30, 2.2, 0.86}, {3.34, 2.8, 1.2}, Material::kScreen);
  builder.addBox({3.33, 2.47, 0.75}, {3.37, 2.53, 0.86}, Material::kLaminate);
  builder.addBox({3.25, 2.38, 0.75}, {3.45, 2.62, 0.765}, Material::kLaminate);
}

void addBox(SceneBuilder& builder, const char* name, const V& low, const V& high) {
  builder.beginObject(SemanticClass::kBox, name);
  builder.addBox(low, high, Material::kCardboard);
}

// A chair in its own frame: seat centred over the origin, backrest on the -y side, so it faces +y.
void addChairParts(SceneBuilder& builder) {
  constexpr double kHalf = 0.225;
  constexpr double kLeg = 0.035;
  constexpr double kSeatLow = 0.43;
  constexpr double kSeatHigh = 0.47;
  builder.addBox({-kHalf, -kHalf, kSeatLow}, {kHalf, kHalf, kSeatHigh}, Material::kFabric);
  for (double x : {-kHalf, kHalf - kLeg}) {
    for (double y : {-kHalf, kHalf - kLeg}) {
      builder.addBox({x, y, 0.0}, {x + kLeg, y + kLeg, kSeatLow}, Material::kWood);
    }
  }
  builder.addBox({-kHalf, -kHalf, kSeatHigh}, {kHalf, -kHalf + kLeg, 0.92}, Material::kWood);
}

void addCabinet(SceneBuilder& builder) {
  builder.beginObject(SemanticClass::kCabinet, "cabinet");
  builder.addBox({4.75, 0.5, 0.0}, {5.2, 1.7, 1.05}, Material::kLaminate);
  for (double z : {0.05, 0.37, 0.69}) {
    builder.addBox({4.735, 0.55, z}, {4.75, 1.65, z + 0.3}, Material::kWood);
    builder.addBox({4.715, 1.0, z + 0.2}, {4.735, 1.2, z + 0.23}, Material::kLaminate);
  }
}

void addSideboard(SceneBuilder& builder) {
  builder.beginObject(SemanticClass::kCabinet, "sideboard");
  builder.addBox({1.0, 4.55, 0.0}, {2.6, 5.0, 0.8}, Material::kLaminate);
  for (double x : {1.05, 1.82}) {
    builder.addBox({x, 4.535, 0.05}, {x + 0.73, 4.55, 0.75}, Material::kWood);
    builder.addBox({x + 0.33, 4.52, 0.55}, {x + 0.4, 4.535, 0.57}, Material::kLaminate);
  }
}

// Books (and now and then a small box) standing on one board, from y = y0 to y1, against the back
// of a shelf whose back is at x = back.
void addBooks(SceneBuilder& builder, double back, double y0, double y1, double z,
              double clearance) {
  std::mt19937_64& rng = builder.rng();
  const auto uniform = [&](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
  };
  double y = y0;
  while (true) {
    if (uniform(0, 1) < 0.12) y += uniform(0.05, 0.15);
    const bool box = uniform(0, 1) < 0.1;
    const double width = box ? uniform(0.12, 0.2) : uniform(0.02, 0.055);
    if (y + width > y1) break;
    const double height = clearance * (box ? uniform(0.3, 0.6) : uniform(0.6, 0.92));
    const double depth = (back - kBoard) * uniform(0.6, 0.95);
    builder.addBox({back - depth, y, z}, {back, y + width, z + height},
                   box ? Material::kCardboard : Material::kBook);
    y += width + uniform(0.0, 0.006);
  }
}

// A shelf in its own frame, open towards -x: front at x = 0, back at x = depth, y in [0, width].
void addShelfParts(SceneBuilder& builder, double depth, double width, double height,
                   const std::vector<double>& boards) {
  builder.addBox({0.0, 0.0, 0.0}, {depth, kBoard, height}, Material::kWood);
  builder.addBox({0.0, width - kBoard, 0.0}, {depth, width, height}, Material::kWood);
  builder.addBox({0.0, kBoard, height - kBoard}, {depth, width - kBoard, height}, Material::kWood);
  builder.addBox({depth - kBoard, kBoard, 0.0}, {depth, width - kBoard, height - kBoard},
                 Material::kWood);
  for (std::size_t i = 0; i < boards.size(); ++i) {
    const double z = boards[i];
    const double next = i + 1 < boards.size() ? boards[i + 1] : height - kBoard;
    builder.addBox({0.0, kBoard, z}, {depth - kBoard, width - kBoard, z + kBoard}, Material::kWood);
    addBooks(builder, depth - kBoard, 2 * kBoard, width - 2 * kBoard, z + kBoard,
             next - z - kBoard - 0.03);
  }
}

void addShelves(SceneBuilder& builder) {
  builder.beginObject(SemanticClass::kShelf, "bookshelf");
  addShelfParts(builder, 0.4, 1.6, 2.0, {0.0, 0.48, 0.96, 1.44});
  builder.placeCurrentObject(placement(4.8, 2.7, 0.0));
  builder.beginObject(SemanticClass::kShelf, "low_shelf");
  addShelfParts(builder, 0.35, 1.2, 1.2, {0.0, 0.4, 0.8});
  builder.placeCurrentObject(placement(1.6, 0.35, -std::numbers::pi / 2));
}

}  // namespace

Eigen::AlignedBox3d roomBox() { return {V::Zero(), V(kRoomX, kRoomY, kRoomZ)}; }

std::vector<WalkLane> walkLanes() {
  return {
      {{4.2, 1.05}, {4.2, 3.6}},
      {{2.3, 3.5}, {2.3, 1.1}},
      {{1.2, 4.1}, {3.7, 4.1}},
      {{3.8, 0.62}, {1.3, 0.62}},
  };
}

PushMotion chairPush(double duration) {
  return {placement(3.175, 1.2, 12.0 * geometry::kDegree), placement(3.175, 1.75, 0.0),
          0.3 * duration, 0.55 * duration};
}

std::uint16_t buildRoom(SceneBuilder& builder, bool chair_moves) {
  addRoomSurfaces(builder);
  addTable(builder);
  addMonitor(builder);
  addBox(builder, "box_on_table", {2.9, 2.75, 0.75}, {3.1, 3.0, 0.9});
  const std::uint16_t chair = builder.beginObject(SemanticClass::kChair, "chair_1", chair_moves);
  addChairParts(builder);
  if (!chair_moves) builder.placeCurrentObject(chairPush(1.0).start);
  builder.beginObject(SemanticClass::kChair, "chair_2");
  addChairParts(builder);
  builder.placeCurrentObject(placement(3.175, 3.525, std::numbers::pi));
  addCabinet(builder);
  addBox(builder, "box_on_cabinet_1", {4.8, 0.6, 1.05}, {5.1, 0.95, 1.3});
  addBox(builder, "box_on_cabinet_2", {4.85, 1.1, 1.05}, {5.15, 1.5, 1.2});
  addShelves(builder);
  addSideboard(builder);
  addBox(builder, "box_on_sideboard_1", {1.3, 4.6, 0.8}, {1.7, 4.95, 1.1});
  addBox(builder, "box_on_sideboard_2", {2.0, 4.65, 0.8}, {2.3, 4.9, 0.95});
  addBox(builder, "box_corner_1", {4.2, 4.5, 0.0}, {4.7, 4.95, 0.4});
  addBox(builder, "box_corner_2", {4.3, 4.55, 0.4}, {4.65, 4.9, 0.65});
  return chair;
}

}  // namespace segslam::synth
