// Reference JavaScript port of eigendance.music.breeding.breed (docs/design.md#breeding), checked
// against Python by tests/music/test_gallery.py: the same seed and parents must give
// bit-identical children.
// Usage: node breed_reference.mjs < {"parents": [{transfer, amplification}], "size", "seed"}

function mulberry32(seed) {
  let a = seed >>> 0;
  const next = () => {
    a = (a + 0x6D2B79F5) | 0;
    let t = Math.imul(a ^ (a >>> 15), a | 1);
    t = (t + Math.imul(t ^ (t >>> 7), t | 61)) ^ t;
    return (t ^ (t >>> 14)) >>> 0;
  };
  const uniform = () => next() / 4294967296;
  const below = (count) => Math.min(count - 1, Math.floor(uniform() * count));
  return { next, uniform, below };
}

function resample(a, k) {
  const K = a.length;
  if (K === k) return a.slice();
  return Array.from({ length: k }, (_, v) => a[Math.min(K - 1, Math.floor((v + 0.5) * K / k))]);
}

function cross(first, second, random, meanSegment) {
  const length = first.length;
  if (meanSegment === undefined) meanSegment = length / 4;
  const p = meanSegment > 0 ? Math.min(1, 1 / meanSegment) : 1;
  const child = new Array(length);
  let filled = 0;
  while (filled < length) {
    const left = length - filled;
    let n = 1;
    while (n < left && !(random.uniform() < p)) n += 1;
    const r = random.uniform();
    for (let i = filled; i < filled + n; i++) child[i] = r * first[i] + (1 - r) * second[i];
    filled += n;
  }
  return child;
}

export function breed(parents, size, seed, meanSegment) {
  const K = parents[0].amplification.length;
  const transfers = parents.map((p) => p.transfer);
  const amplifications = parents.map((p) => resample(p.amplification, K));
  const random = mulberry32(seed);
  const children = [];
  for (let c = 0; c < size; c++) {
    let i = 0, j = 0;
    if (parents.length > 1) {
      i = random.below(parents.length);
      j = random.below(parents.length - 1);
      if (j >= i) j += 1;
    }
    const genes = [];
    for (const vectors of [transfers, amplifications]) {
      if (random.uniform() < 0.5) genes.push(cross(vectors[i], vectors[j], random, meanSegment));
      else genes.push((random.uniform() < 0.5 ? vectors[i] : vectors[j]).slice());
    }
    children.push({ transfer: genes[0].map((x) => Math.min(1, Math.max(0, x))),
                    amplification: genes[1], seed });
  }
  return children;
}

let input = "";
process.stdin.on("data", (chunk) => { input += chunk; });
process.stdin.on("end", () => {
  const { parents, size, seed } = JSON.parse(input);
  process.stdout.write(JSON.stringify(breed(parents, size, seed)));
});
