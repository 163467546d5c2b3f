// Writes small run folders for the browser test, in the layout `segslam run` and the map writer
// produce: TUM trajectories, map/static.ply, map/dynamic.ply, map/objects.json + objects/*.ply.
import { mkdirSync, writeFileSync } from "node:fs";
import { join } from "node:path";

function plyBytes(points) {
  const header = "ply\nformat binary_little_endian 1.0\n" +
    `element vertex ${points.length}\n` +
    "property float x\nproperty float y\nproperty float z\n" +
    "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  const body = Buffer.alloc(points.length * 15);
  points.forEach(([x, y, z, r, g, b], i) => {
    body.writeFloatLE(x, 15 * i);
    body.writeFloatLE(y, 15 * i + 4);
    body.writeFloatLE(z, 15 * i + 8);
    body.writeUInt8(r, 15 * i + 12);
    body.writeUInt8(g, 15 * i + 13);
    body.writeUInt8(b, 15 * i + 14);
  });
  return Buffer.concat([Buffer.from(header, "latin1"), body]);
}

// A `side` x `side` patch of points in a horizontal plane (camera frames have y down).
function patch(x0, y, z0, side, step, colour) {
  const points = [];
  for (let i = 0; i < side; ++i) {
    for (let j = 0; j < side; ++j) points.push([x0 + step * i, y, z0 + step * j, ...colour]);
  }
  return points;
}

function trajectory(count, zStep) {
  const lines = ["# timestamp tx ty tz qx qy qz qw"];
  for (let k = 0; k < count; ++k) {
    lines.push(`${(100 + 0.1 * k).toFixed(4)} ${(0.02 * k).toFixed(4)} 0 ${(zStep * k).toFixed(4)} 0 0 0 1`);
  }
  return lines.join("\n") + "\n";
}

const OBJECTS = [
  { id: "chair_1", label: "chair", instance: 1, dynamic: false, confidence: 0.9, keyframes: 10, points: patch(-0.4, 0.6, 1.2, 6, 0.04, [150, 90, 40]) },
  { id: "chair_2", label: "chair", instance: 2, dynamic: false, confidence: 0.75, keyframes: 4, points: patch(0.4, 0.6, 1.4, 5, 0.04, [150, 90, 40]) },
  { id: "person_1", label: "person", instance: 1, dynamic: true, confidence: 1, keyframes: 6, points: patch(0.0, 0.2, 2.0, 4, 0.05, [220, 180, 160]) },
];

export function writeFixtureRun(dir, withMap) {
  mkdirSync(dir, { recursive: true });
  writeFileSync(join(dir, "CameraTrajectory.txt"), trajectory(30, 0.02));
  writeFileSync(join(dir, "KeyFrameTrajectory.txt"), trajectory(6, 0.1));
  writeFileSync(join(dir, "GroundTruthAligned.txt"), trajectory(30, 0.021));
  if (!withMap) return;
  mkdirSync(join(dir, "map", "objects"), { recursive: true });
  writeFileSync(join(dir, "map", "static.ply"), plyBytes(patch(-1.5, 1.0, 0.5, 40, 0.075, [120, 130, 140])));
  writeFileSync(join(dir, "map", "dynamic.ply"), plyBytes(patch(-0.1, 0.2, 1.9, 6, 0.05, [250, 60, 90])));
  const index = { voxel_size: 0.05, objects: [] };
  for (const { points, ...object } of OBJECTS) {
    const file = `objects/${object.id}.ply`;
    writeFileSync(join(dir, "map", file), plyBytes(points));
    const xs = (k) => points.map((p) => p[k]);
    index.objects.push({
      ...object, points: points.length, file,
      centroid: [0, 1, 2].map((k) => xs(k).reduce((a, b) => a + b) / points.length),
      bbox_min: [0, 1, 2].map((k) => Math.min(...xs(k))),
      bbox_max: [0, 1, 2].map((k) => Math.max(...xs(k))),
      oriented_box: {
        centre: [0, 1, 2].map((k) => (Math.min(...xs(k)) + Math.max(...xs(k))) / 2),
        extent: [0, 1, 2].map((k) => Math.max(...xs(k)) - Math.min(...xs(k))),
        axes: [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
      },
    });
  }
  writeFileSync(join(dir, "map", "objects.json"), JSON.stringify(index, null, 1));
  writeOccupancy(join(dir, "map"));
}

// An occupancy map as system::OccupancyOutput writes it: the occupied voxels' centres (a wall of
// 10 x 4 voxels), occupancy.json with the floor grid's frame, and a 6 x 4 grid (P5 PGM) with
// 5 occupied cells, 12 free and 7 unknown.
function writeOccupancy(mapDir) {
  const voxels = [];
  for (let i = 0; i < 10; ++i) {
    for (let j = 0; j < 4; ++j) voxels.push([-0.5 + 0.1 * i, 0.6 - 0.1 * j, 2.5, 200, 200, 200]);
  }
  writeFileSync(join(mapDir, "occupancy_occupied.ply"), plyBytes(voxels));
  const cells = [0, 0, 0, 0, 0, 254, 254, 254, 254, 254, 254, 254, 254, 254, 254, 254, 254,
    205, 205, 205, 205, 205, 205, 205];
  writeFileSync(join(mapDir, "occupancy_2d.pgm"),
    Buffer.concat([Buffer.from("P5\n# segslam\n6 4\n255\n", "latin1"), Buffer.from(cells)]));
  writeFileSync(join(mapDir, "occupancy.json"), JSON.stringify({
    resolution_m: 0.1, occupied_voxels: voxels.length, free_voxels: 500,
    grid: {
      image: "occupancy_2d.pgm", rows: 4, cols: 6, resolution_m: 0.1, origin: [-0.3, 1.0],
      u_axis: [1, 0, 0], v_axis: [0, 0, 1], up: [0, -1, 0], floor_height_m: -1.0,
    },
  }));
}
