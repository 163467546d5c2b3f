// Reads the vertices of a PLY point cloud (binary little-endian or ASCII): positions and, when
// the file has red/green/blue, colours scaled to 0..1.

const TYPES = {
  char: ["getInt8", 1], int8: ["getInt8", 1], uchar: ["getUint8", 1], uint8: ["getUint8", 1],
  short: ["getInt16", 2], int16: ["getInt16", 2], ushort: ["getUint16", 2], uint16: ["getUint16", 2],
  int: ["getInt32", 4], int32: ["getInt32", 4], uint: ["getUint32", 4], uint32: ["getUint32", 4],
  float: ["getFloat32", 4], float32: ["getFloat32", 4], double: ["getFloat64", 8], float64: ["getFloat64", 8],
};

function parseHeader(bytes, name) {
  const end = "end_header\n";
  const text = new TextDecoder("latin1").decode(bytes.subarray(0, Math.min(bytes.length, 4096)));
  const stop = text.indexOf(end);
  if (!text.startsWith("ply") || stop < 0) throw new Error(`${name}: not a PLY file`);
  const header = { format: "", vertices: 0, properties: [], firstElement: "", bodyOffset: stop + end.length };
  let inVertex = false;
  for (const line of text.slice(0, stop).split("\n")) {
    const words = line.trim().split(/\s+/);
    if (words[0] === "format") header.format = words[1];
    if (words[0] === "element") {
      if (!header.firstElement) header.firstElement = words[1];
      inVertex = words[1] === "vertex";
      if (inVertex) header.vertices = Number(words[2]);
    }
    if (words[0] === "property" && inVertex) {
      if (words[1] === "list") throw new Error(`${name}: list properties on vertices are not supported`);
      if (!TYPES[words[1]]) throw new Error(`${name}: unknown property type ${words[1]}`);
      header.properties.push({ type: words[1], name: words[2] });
    }
  }
  if (header.firstElement !== "vertex") throw new Error(`${name}: the first element must be vertex`);
  return header;
}

function columnsOf(header, name) {
  const index = (property) => header.properties.findIndex((p) => p.name === property);
  const position = ["x", "y", "z"].map(index);
  if (position.some((i) => i < 0)) throw new Error(`${name}: vertices need x, y, z`);
  const colour = ["red", "green", "blue"].map(index);
  return { position, colour: colour.every((i) => i >= 0) ? colour : null };
}

function colourScale(header, columns) {
  if (!columns.colour) return 1;
  const type = header.properties[columns.colour[0]].type;
  return type.startsWith("float") || type === "double" ? 1 : 1 / 255;
}

function readBinary(bytes, header, columns, name) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const offsets = [];
  let stride = 0;
  for (const property of header.properties) {
    offsets.push(stride);
    stride += TYPES[property.type][1];
  }
  if (header.bodyOffset + stride * header.vertices > bytes.length) {
    throw new Error(`${name}: file ends before its ${header.vertices} vertices`);
  }
  const read = (vertex, column) => {
    const [getter] = TYPES[header.properties[column].type];
    return view[getter](header.bodyOffset + vertex * stride + offsets[column], true);
  };
  return fill(header.vertices, columns, read, colourScale(header, columns));
}

function readAscii(bytes, header, columns, name) {
  const rows = new TextDecoder("latin1").decode(bytes.subarray(header.bodyOffset)).trim().split("\n");
  if (rows.length < header.vertices) throw new Error(`${name}: file ends before its ${header.vertices} vertices`);
  const values = rows.slice(0, header.vertices).map((row) => row.trim().split(/\s+/).map(Number));
  return fill(header.vertices, columns, (vertex, column) => values[vertex][column], colourScale(header, columns));
}

function fill(count, columns, read, scale) {
  const positions = new Float32Array(count * 3);
  const colours = columns.colour ? new Float32Array(count * 3) : null;
  for (let v = 0; v < count; ++v) {
    for (let k = 0; k < 3; ++k) {
      positions[3 * v + k] = read(v, columns.position[k]);
      if (colours) colours[3 * v + k] = read(v, columns.colour[k]) * scale;
    }
  }
  return { count, positions, colours };
}

export function parsePly(buffer, name) {
  const bytes = new Uint8Array(buffer);
  const header = parseHeader(bytes, name);
  const columns = columnsOf(header, name);
  if (header.format === "binary_little_endian") return readBinary(bytes, header, columns, name);
  if (header.format === "ascii") return readAscii(bytes, header, columns, name);
  throw new Error(`${name}: PLY format ${header.format} is not supported`);
}
