// A small animated glTF for the browser tests: an emissive unit quad facing +z, two animations of it ("Slide":
// from x = -1 to x = 1 over 0..2 s; "Rise": from y = -1 to y = 1 over 0..1 s) and two cameras ("front" at
// z = 6, "side" at x = 6), each looking at the quad.
import fs from 'node:fs';
import path from 'node:path';

export function writeAnimatedScene(folder) {
  const floats = [];
  const views = [];
  const accessors = [];
  const bytes = () => floats.length * 4;
  const add = (values, type) => {
    views.push({ buffer: 0, byteOffset: bytes(), byteLength: values.length * 4 });
    floats.push(...values);
    const components = { SCALAR: 1, VEC3: 3 }[type];
    accessors.push({ bufferView: views.length - 1, componentType: 5126, count: values.length / components, type });
    return accessors.length - 1;
  };
  const positions = add([-0.5, -0.5, 0, 0.5, -0.5, 0, 0.5, 0.5, 0, -0.5, 0.5, 0], 'VEC3');
  accessors[positions].min = [-0.5, -0.5, 0];
  accessors[positions].max = [0.5, 0.5, 0];
  const slideTimes = add([0, 2], 'SCALAR');
  const slide = add([-1, 0, 0, 1, 0, 0], 'VEC3');
  const riseTimes = add([0, 1], 'SCALAR');
  const rise = add([0, -1, 0, 0, 1, 0], 'VEC3');
  // The indices, two triangles, after the floats.
  const indexOffset = bytes();
  views.push({ buffer: 0, byteOffset: indexOffset, byteLength: 12 });
  accessors.push({ bufferView: views.length - 1, componentType: 5123, count: 6, type: 'SCALAR' });
  const buffer = Buffer.alloc(indexOffset + 12);
  floats.forEach((f, i) => buffer.writeFloatLE(f, 4 * i));
  [0, 1, 2, 0, 2, 3].forEach((index, i) => buffer.writeUInt16LE(index, indexOffset + 2 * i));

  const translationOf = (node, input, output) => ({
    samplers: [{ input, output }],
    channels: [{ sampler: 0, target: { node, path: 'translation' } }],
  });
  const camera = (name) => ({ name, type: 'perspective', perspective: { yfov: 0.6, znear: 0.1 } });
  const gltf = {
    asset: { version: '2.0' },
    buffers: [{ byteLength: buffer.length, uri: 'animated.bin' }],
    bufferViews: views,
    accessors,
    meshes: [{ primitives: [{ attributes: { POSITION: positions }, indices: accessors.length - 1, material: 0 }] }],
    materials: [{ emissiveFactor: [1, 1, 1], pbrMetallicRoughness: { baseColorFactor: [0, 0, 0, 1] } }],
    cameras: [camera('front'), camera('side')],
    nodes: [
      { mesh: 0 },
      { camera: 0, translation: [0, 0, 6] },
      { camera: 1, translation: [6, 0, 0], rotation: [0, Math.SQRT1_2, 0, Math.SQRT1_2] },
    ],
    scenes: [{ nodes: [0, 1, 2] }],
    animations: [{ name: 'Slide', ...translationOf(0, slideTimes, slide) },
                 { name: 'Rise', ...translationOf(0, riseTimes, rise) }],
  };
  fs.mkdirSync(folder, { recursive: true });
  fs.writeFileSync(path.join(folder, 'animated.bin'), buffer);
  const file = path.join(folder, 'animated.gltf');
  fs.writeFileSync(file, JSON.stringify(gltf));
  return file;
}
