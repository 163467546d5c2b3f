// Reads a TUM trajectory ("t tx ty tz qx qy qz qw" per line, '#' comments): camera positions and
// orientations, camera-to-world.
export function parseTum(text, name) {
  const poses = [];
  text.split("\n").forEach((line, index) => {
    const trimmed = line.trim();
    if (!trimmed || trimmed.startsWith("#")) return;
    const values = trimmed.split(/\s+/).map(Number);
    if (values.length < 8 || values.some(Number.isNaN)) {
      throw new Error(`${name}:${index + 1}: expected "t tx ty tz qx qy qz qw"`);
    }
    poses.push({ t: values[0], position: values.slice(1, 4), quaternion: values.slice(4, 8) });
  });
  return poses;
}
