// Binary bundles written by eigendance.server.binary: b"EDB1", uint32 header length, JSON
// header {meta, arrays: {name: {dtype, shape, offset}}}, then 4-byte aligned arrays.

export interface Bundle {
  meta: Record<string, any>;
  arrays: Record<string, { data: Float32Array | Uint32Array; shape: number[] }>;
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
    if (offset + 4 * count > buffer.byteLength) throw new Error(`bundle array ${name} truncated`);
    const Type = entry.dtype === "uint32" ? Uint32Array : Float32Array;
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
  harmonics: Float32Array; // n * 4*k4, four harmonics per texel
}

export function basisFromBundle(bundle: Bundle): Basis {
  const a = bundle.arrays;
  const n = a.vertices.shape[0];
  const k = a.eigenvalues.shape[0];
  return {
    name: bundle.meta.name ?? "mesh", n, k, k4: a.harmonics.shape[1] / 4,
    vertices: a.vertices.data as Float32Array, faces: a.faces.data as Uint32Array,
    eigenvalues: a.eigenvalues.data as Float32Array,
    coefficients: a.coefficients.data as Float32Array,
    harmonics: a.harmonics.data as Float32Array,
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
}

export function spectrumFromBundle(bundle: Bundle): Spectrum {
  const a = bundle.arrays;
  return {
    name: bundle.meta.name ?? "song", rate: bundle.meta.rate, frames: a.values.shape[0],
    bands: a.values.shape[1], duration: bundle.meta.duration,
    times: a.times.data as Float32Array, values: a.values.data as Float32Array,
    bandEdges: a.band_edges.data as Float32Array,
  };
}
