// Scenes the web tests generate: many random faces, and the stress families' hard cases
// (coordinates of ±1e9, slivers, vertices on a 2^-8 grid). Seeded, so every run draws the same.

// mulberry32: a small seeded generator (the tests need repeatability, not quality).
export function random(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

function scene(width, height, tris, rnd) {
  const vertices = [], vcolors = [], depth = [], faces = [];
  for (const t of tris) {
    faces.push([vertices.length, vertices.length + 1, vertices.length + 2]);
    for (const v of t) {
      vertices.push(v);
      vcolors.push([rnd(), rnd(), rnd()]);
      depth.push(rnd() * 1000);
    }
  }
  return { width, height, background: [1, 1, 1], vertices, vcolors, faces, depth };
}

// `count` random triangles on a width × height canvas, some reaching past its edges.
export function manyFaces(count, width, height, seed = 1) {
  const rnd = random(seed);
  const tris = [];
  for (let i = 0; i < count; ++i) {
    const cx = rnd() * width * 1.1 - width * 0.05, cy = rnd() * height * 1.1 - height * 0.05;
    const r = 2 + rnd() * rnd() * 60;
    tris.push([0, 1, 2].map(() => [cx + (rnd() - 0.5) * 2 * r, cy + (rnd() - 0.5) * 2 * r]));
  }
  return scene(width, height, tris, rnd);
}

// Faces whose arithmetic needs the fill's 64- and 128-bit paths, thin slivers, and vertices on
// the 2^-8 grid (exactly representable, so the snapping decides ties).
export function hardCases(seed = 7) {
  const rnd = random(seed);
  const tris = [
    [[-1e9, -1e9], [1e9, 3.5], [200.25, 1e9]],
    [[1e9, -1e9], [-1e9, 100.5], [300, 1e9]],
    [[-999999999.5, 256], [999999999.25, 255.75], [256, 257.125]],
    [[0, 0], [511.9, 0.6], [0.2, 0.1]],
    [[10, 500], [500, 10], [10.0001, 499.999]],
    [[100, 100.5], [400, 100.50390625], [250, 100.49609375]],
  ];
  for (let i = 0; i < 200; ++i) {
    const g = () => Math.round(rnd() * 512 * 256) / 256;
    tris.push([[g(), g()], [g(), g()], [g(), g()]]);
  }
  for (let i = 0; i < 50; ++i) {
    const x = rnd() * 512, y = rnd() * 512, dx = (rnd() - 0.5) * 400, dy = (rnd() - 0.5) * 400;
    const e = (rnd() - 0.5) * 1e-3;
    tris.push([[x, y], [x + dx, y + dy], [x + dx / 2 + e, y + dy / 2 - e]]);
  }
  return scene(512, 512, tris, rnd);
}
