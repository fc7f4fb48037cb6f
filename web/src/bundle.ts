// Binary bundles written by eigendance.server.binary: b"EDB1", uint32 header length, JSON
// header {meta, arrays: {name: {dtype, shape, offset}}}, then 4-byte aligned arrays.

export interface Bundle {
  meta: Record<string, any>;
  arrays: Record<string, { data: Float32Array | Uint32Array | Uint16Array | Uint8Array;
    shape: number[] }>;
}

let halfTable: Float32Array | null = null;

/** IEEE half-precision bits → float (all 65536 values tabulated once). */
export function halfToFloat(bits: number): number {
  if (!halfTable) {
    halfTable = new Float32Array(65536);
    for (let h = 0; h < 65536; h++) {
      const sign = h & 0x8000 ? -1 : 1, exponent = (h >> 10) & 0x1f, fraction = h & 0x3ff;
      halfTable[h] = exponent === 0 ? sign * fraction * 2 ** -24
        : exponent === 31 ? (fraction ? NaN : sign * Infinity)
          : sign * (1 + fraction / 1024) * 2 ** (exponent - 15);
    }
  }
  return halfTable[bits];
}

export function parseBundle(buffer: ArrayBuffer): Bundle {
  const bytes = new Uint8Array(buffer);
  if (bytes.length < 8 || String.fromCharCode(...bytes.subarray(0, 4)) !== "EDB1") {
    throw new Error("not an eigendance bundle");
  }
  const length = new DataView(buffer).getUint32(4, true);
  const header = JSON.parse(new TextDecoder().decode(bytes.subarray(8, 8 + length)));
  const start = 8 + length;
  const arrays: Bundle["arrays"] = {};
  for (const [name, entry] of Object.entries<any>(header.arrays)) {
    const count = entry.shape.reduce((a: number, b: number) => a * b, 1);
    const offset = start + entry.offset;
    const size = entry.dtype === "float16" || entry.dtype === "uint16" ? 2
      : entry.dtype === "uint8" ? 1 : 4;
    if (offset + size * count > buffer.byteLength) {
      throw new Error(`bundle array ${name} truncated`);
    }
    if (entry.dtype === "float16") { // decoded to float32 (the textures are RGBA32F)
      const bits = new Uint16Array(buffer, offset, count);
      const data = new Float32Array(count);
      halfToFloat(0);
      for (let i = 0; i < count; i++) data[i] = halfTable![bits[i]];
      arrays[name] = { data, shape: entry.shape };
      continue;
    }
    const Type = entry.dtype === "uint32" ? Uint32Array : entry.dtype === "uint16" ? Uint16Array
      : entry.dtype === "uint8" ? Uint8Array : Float32Array;
    arrays[name] = { data: new Type(buffer, offset, count), shape: entry.shape };
  }
  return { meta: header.meta, arrays };
}

export interface Basis {
  name: string;
  n: number;
  k: number;
  /** texels (4 harmonics each) per vertex */
  k4: number;
  vertices: Float32Array; // n*3 normalised
  faces: Uint32Array; // m*3
  eigenvalues: Float32Array; // k
  coefficients: Float32Array; // k*3
  /** four harmonics per texel: n * 4*k4 of the vertices, or (reduced) m * 4*k4 of the samples */
  harmonics: Float32Array;
  /** a reduced basis (docs/design.md#reduced-basis): U = P U_r, `harmonics` holding U_r */
  reduced?: Interpolation;
}

/** P of a reduced basis: vertex i = Σ_j weights[8i + j] · sample indices[8i + j]. */
export interface Interpolation {
  /** samples m: the rows of `harmonics` */
  m: number;
  /** the samples asked of the sampler, which placed these m (null where the server did not say) */
  asked: number | null;
  /** n*8, ≥ 0, each vertex's summing to 1 (multiples of 2⁻¹¹: exact in float16) */
  weights: Float32Array;
  indices: Uint16Array | Uint32Array; // n*8 sample rows
}

/** Rows of a basis's harmonics texture: the vertices, or the samples of a reduced basis. */
export function harmonicRows(basis: Basis): number {
  return basis.reduced ? basis.reduced.m : basis.n;
}

export function basisFromBundle(bundle: Bundle): Basis {
  const a = bundle.arrays;
  const n = a.vertices.shape[0];
  const k = a.eigenvalues.shape[0];
  const harmonics = a.harmonics ?? a.coarse; // a reduced basis sends U_r as `coarse`
  return {
    name: bundle.meta.name ?? "mesh", n, k, k4: harmonics.shape[1] / 4,
    vertices: a.vertices.data as Float32Array, faces: a.faces.data as Uint32Array,
    eigenvalues: a.eigenvalues.data as Float32Array,
    coefficients: a.coefficients.data as Float32Array,
    harmonics: harmonics.data as Float32Array,
    reduced: a.coarse ? { m: a.coarse.shape[0], asked: bundle.meta.samples ?? null, weights: a.weights.data as Float32Array,
      indices: a.indices.data as Uint16Array | Uint32Array } : undefined,
  };
}

export interface Spectrum {
  name: string;
  rate: number;
  frames: number;
  bands: number;
  duration: number;
  times: Float32Array;
  values: Float32Array; // frames*bands in [0,1]
  bandEdges: Float32Array;
  /** the song's beats and onsets, s (docs/design.md#rhythm; empty without them) */
  beats: Float32Array;
  onsets: Float32Array;
  /** the beats that start a bar and the starts of the song's parts after the first, s
   * (docs/design.md#rhythm; empty without them: a live take has neither) */
  downbeats: Float32Array;
  sections: Float32Array;
  /** beats per minute, 0: no beat */
  tempo: number;
  /** beats per bar, 0: no bars */
  meter: number;
}

export function spectrumFromBundle(bundle: Bundle): Spectrum {
  const a = bundle.arrays;
  return {
    name: bundle.meta.name ?? "song", rate: bundle.meta.rate, frames: a.values.shape[0],
    bands: a.values.shape[1], duration: bundle.meta.duration,
    times: a.times.data as Float32Array, values: a.values.data as Float32Array,
    bandEdges: a.band_edges.data as Float32Array,
    beats: (a.beats?.data as Float32Array) ?? new Float32Array(0),
    onsets: (a.onsets?.data as Float32Array) ?? new Float32Array(0),
    downbeats: (a.downbeats?.data as Float32Array) ?? new Float32Array(0),
    sections: (a.sections?.data as Float32Array) ?? new Float32Array(0),
    tempo: bundle.meta.tempo ?? 0, meter: bundle.meta.meter ?? 0,
  };
}
