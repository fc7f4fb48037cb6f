// The server's JSON/binary API (eigendance.server).
import { basisFromBundle, parseBundle, spectrumFromBundle } from "./bundle";
import type { Basis, Spectrum } from "./bundle";
import type { Mapping } from "./filter";

/** A job of the server (a basis, an export): `cached` when a basis is read from the disk cache,
 * not solved. */
export interface Job { id: string; kind: string; state: string; done: number; total: number;
  message: string; cached?: boolean; }
/** A model's look as the library lists it: null for a model drawn in clay. */
export type LookInfo = { materials: number; images: number; drawn: number } | null;
export interface MeshInfo { id: string; name: string; k: number; vertices: number; ready: boolean;
  job: Job | null; look?: LookInfo; }
export interface SongInfo { id: string; name: string; duration: number; }
/** A mapping of the library: `origin` "file" (given to `serve`: opens in the player at start)
 * or "upload" (added in the page). */
export interface MappingInfo { id: string; name: string; origin?: "file" | "upload"; }
export interface Library { meshes: MeshInfo[]; songs: SongInfo[]; mappings: MappingInfo[];
  rigs?: { id: string; name: string; ready: boolean; modes?: number; revision?: number;
    look?: LookInfo; origin?: string }[];
  /** the first model given to `serve`: the page opens it first */
  first?: { kind: "mesh" | "rig"; id: string } | null; }

/** The response, or an Error with the server's one-line message. */
export async function checked(response: Response): Promise<Response> {
  if (!response.ok) {
    let message = `${response.status} ${response.statusText}`;
    try { message = (await response.json()).error ?? message; } catch { /* not JSON */ }
    throw new Error(message);
  }
  return response;
}

export async function getJSON<T>(url: string): Promise<T> {
  return (await checked(await fetch(url))).json();
}

export async function postJSON<T>(url: string, body: unknown): Promise<T> {
  return (await checked(await fetch(url, {
    method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(body),
  }))).json();
}

export const library = () => getJSON<Library>("api/library");

/** The server's rules the page follows (`{gallery: {min, max, default}}`), checked by
 * `options.galleryRule`. */
export const config = () => getJSON<unknown>("api/config");

/** The basis of a mesh; `half`: harmonics sent as float16 (half the download). */
export async function basis(meshId: string, half = false): Promise<Basis> {
  const query = half ? "?dtype=float16" : "";
  const response = await checked(await fetch(`api/meshes/${meshId}/basis.bin${query}`));
  return basisFromBundle(parseBundle(await response.arrayBuffer()));
}

export async function spectrum(songId: string): Promise<Spectrum> {
  const response = await checked(await fetch(`api/songs/${songId}/spectrogram.bin`));
  return spectrumFromBundle(parseBundle(await response.arrayBuffer()));
}

export async function audioBytes(songId: string): Promise<ArrayBuffer> {
  return (await checked(await fetch(`api/songs/${songId}/audio`))).arrayBuffer();
}

/** The initial gallery of `size` items (null: the server's default size), calibrated on the
 * song. */
export async function gallery(mesh: string, song: string, size: number | null):
    Promise<Mapping[]> {
  const body = size === null ? { mesh, song } : { mesh, song, size };
  return (await postJSON<{ mappings: Mapping[] }>("api/gallery", body)).mappings;
}

/** Children of `parents`; `on` (the model and song they dance to) bounds them: none grows
 * past 1.3× the model's size over the song (docs/design.md#breeding). */
export async function breed(parents: Mapping[], size: number, seed: number,
  on: { mesh?: string; rig?: string; song: string } | null = null): Promise<Mapping[]> {
  return (await postJSON<{ mappings: Mapping[] }>("api/breed",
    { parents, size, seed, ...(on ?? {}) })).mappings;
}

/** Remove an item from the server's library (not its file on disk): the ids removed with it
 * (a mesh takes the rig of its skin along). */
export async function remove(kind: "mesh" | "song" | "mapping" | "rig", id: string):
    Promise<string[]> {
  const route = kind === "mesh" ? "meshes" : `${kind}s`;
  const response = await checked(await fetch(`api/${route}/${encodeURIComponent(id)}`,
    { method: "DELETE" }));
  return (await response.json()).removed;
}

export async function upload(file: File): Promise<any> {
  // Always as bytes: the server names what it cannot read by its suffix (a .txt would else
  // go as text/plain, which the server's guard refuses in HTTP words).
  const response = await fetch(`api/upload?name=${encodeURIComponent(file.name)}`, {
    method: "POST", body: file, headers: { "Content-Type": "application/octet-stream" },
  });
  return (await checked(response)).json();
}

/** Follow a basis job by server-sent events until it is done (resolves) or fails (rejects). */
export function followJob(jobId: string, onProgress: (job: Job) => void): Promise<Job> {
  return new Promise((resolve, reject) => {
    const source = new EventSource(`api/jobs/${jobId}/events`);
    source.onmessage = (event) => {
      const job = JSON.parse(event.data) as Job;
      onProgress(job);
      if (job.state === "done") { source.close(); resolve(job); }
      if (job.state === "error") { source.close(); reject(new Error(job.message)); }
    };
    source.onerror = () => {
      source.close();
      getJSON<Job>(`api/jobs/${jobId}`).then((job) => {
        if (job.state === "done") resolve(job);
        else if (job.state === "error") reject(new Error(job.message));
        else followJob(jobId, onProgress).then(resolve, reject);
      }, reject);
    };
  });
}

/** Keep a live take (recorded audio) as a song of the library (`POST api/takes`, checked as
 * any upload): the server's reply, with the new song's item. */
export async function saveTake(audio: Blob, name: string): Promise<{ item: SongInfo }> {
  const response = await fetch(`api/takes?name=${encodeURIComponent(name)}`, {
    method: "POST", body: audio,
  });
  return (await checked(response)).json();
}
