// The session (issue 30): every model's gallery history — its generations, the one on screen and
// the tiles selected — and every rig's (its dances' generations, the one shown, the dances
// selected, and the player's mapping with its palette), and the song chosen with where it was
// left, and the model on screen, kept in the browser's storage, so that a reload shows them again
// (the song paused where it was), and written to a file (*save session*) that *open session*
// reads back.
import type * as api from "./api";
import type { App } from "./app";
import type { Mapping } from "./filter";
import type { Generation } from "./history";

export const SESSION_FORMAT = "eigendance.session";
const KEY = "eigendance-session";

/** One model's gallery history as saved. */
export interface SavedHistory { generations: Generation<Mapping>[]; current: number;
  selected: number[]; }

/** One rig's galleries as saved: its dances' generations, the one shown and the dances selected,
 * and what its player plays (the mapping with its palette, as *save mapping* writes it). */
export interface SavedRig { generations: Mapping[][]; generation: number; selected: number[];
  player: { mapping: Mapping; source: string } | null; }

/** The song chosen (the library's id) and where it was left (s). */
export interface SavedSong { id: string; time: number; }

/** The model on screen: a mesh or a rig (the library's id). */
export interface SavedModel { kind: "mesh" | "rig"; id: string; }

/** The session file: the gallery history of each model and the galleries of each rig (by the
 * library's ids), the song, and the model on screen. */
export interface Session { format: string; version: 1; histories: Record<string, SavedHistory>;
  rigs?: Record<string, SavedRig>; song?: SavedSong; model?: SavedModel;
  /** the names of the library's models and songs by id, in a file (namesOf) */
  names?: Record<string, string>; }

export function sessionOf(histories: Record<string, SavedHistory>,
                          rigs: Record<string, SavedRig> = {}, song?: SavedSong,
                          model?: SavedModel): Session {
  return { format: SESSION_FORMAT, version: 1, histories, rigs, ...(song ? { song } : {}),
    ...(model ? { model } : {}) };
}

/** Keep parts of the session in the browser, the others as they are kept (with their names). */
export function keepInSession(part: { histories?: Record<string, SavedHistory>;
  rigs?: Record<string, SavedRig>; song?: SavedSong; model?: SavedModel }): void {
  const kept = storedSession();
  storeSession(named(sessionOf(part.histories ?? kept?.histories ?? {},
    part.rigs ?? kept?.rigs ?? {}, part.song ?? kept?.song, part.model ?? kept?.model),
  kept?.names));
}

/** the library's names by id as last read (Library.refresh calls rememberNames) */
let libraryNames: Record<string, string> = {};

/** Remember the names of the library's models, rigs and songs: a session (kept in the browser
 * or in a file) names what it holds, since a server started again gives its items new ids. */
export function rememberNames(library: api.Library): void {
  libraryNames = {};
  for (const item of [...library.meshes, ...library.rigs ?? [], ...library.songs]) {
    libraryNames[item.id] = item.name;
  }
}

/** `session` with `names` (`{id: name}`) for each model, rig and song it holds: the library's
 * name, else the one it had (`older`: an item not served now keeps its name). */
export function named(session: Session, older: Record<string, string> = {}): Session {
  const names: Record<string, string> = {};
  for (const id of heldIds(session)) {
    const name = libraryNames[id] ?? older[id];
    if (name !== undefined) names[id] = name;
  }
  return { ...session, names };
}

function heldIds(session: Session): string[] {
  return [...Object.keys(session.histories), ...Object.keys(session.rigs ?? {}),
    ...(session.song ? [session.song.id] : []), ...(session.model ? [session.model.id] : [])];
}

/** A session matched to the library: its ids that the library no longer has (a server started
 * again) found by name, `count` models and rigs the library has, and `missing`: one line naming
 * what is not served any more, or whose name several items share (never guessed), or "". */
export interface Matched { session: Session; count: number; missing: string; }

/** Match `session` to `library`: an id the library lacks becomes the id of the library's one
 * item of that kind with the name the session gives it. */
export function matched(session: Session, library: api.Library): Matched {
  const names = session.names ?? {};
  const gone = new Set<string>(), shared = new Set<string>(), moved = new Map<string, string>();
  const finder = (items: { id: string; name: string }[]) => (id: string): string => {
    if (items.some((item) => item.id === id)) return id;
    const same = items.filter((item) => id in names && item.name === names[id]);
    if (same.length === 1) moved.set(id, same[0].id);
    else (same.length ? shared : gone).add(names[id] ?? id);
    return moved.get(id) ?? id;
  };
  const mesh = finder(library.meshes), rig = finder(library.rigs ?? []);
  const song = finder(library.songs);
  const rekeyed = <T>(record: Record<string, T>, find: (id: string) => string) =>
    Object.fromEntries(Object.entries(record).map(([id, value]) => [find(id), value]));
  const model = session.model;
  const histories = rekeyed(session.histories, mesh), rigs = rekeyed(session.rigs ?? {}, rig);
  const out: Session = { ...session, histories, rigs,
    ...(session.song ? { song: { ...session.song, id: song(session.song.id) } } : {}),
    ...(model ? { model: { ...model, id: (model.kind === "rig" ? rig : mesh)(model.id) } } : {}) };
  out.names = Object.fromEntries(Object.entries(names).map(([id, name]) => [
    moved.get(id) ?? id, name]));
  const held = (items: { id: string }[]) => (id: string) => items.some((item) => item.id === id);
  const count = Object.keys(histories).filter(held(library.meshes)).length
    + Object.keys(rigs).filter(held(library.rigs ?? [])).length;
  const missing = [gone.size ? `not served any more: ${[...gone].join(", ")}` : "",
    shared.size ? `served twice, not guessed: ${[...shared].join(", ")}` : ""];
  return { session: out, count, missing: missing.filter(Boolean).join("; ") };
}

/** Restore a matched session (kept in the browser, or a file opened): its models' and rigs'
 * galleries in place of theirs (others stay), kept in the browser with this run's ids. The
 * song and the model are the caller's to resume (startModel, loadStartSong; resumeSong,
 * resumeModel). One line: "N models restored" and what is missing. */
export function restoreSession(app: App, { session, count, missing }: Matched,
                               original: Session): string {
  app.gallery.restore(session.histories);
  app.rigs.restore(session.rigs ?? {});
  const kept = storedSession();
  const others = <T>(record: Record<string, T> | undefined, ...replaced: Record<string, unknown>[]) =>
    Object.fromEntries(Object.entries(record ?? {}).filter(
      ([id]) => !replaced.some((ids) => id in ids)));
  storeSession(named(sessionOf(
    { ...others(kept?.histories, original.histories, session.histories), ...session.histories },
    { ...others(kept?.rigs, original.rigs ?? {}, session.rigs ?? {}), ...session.rigs },
    session.song ?? kept?.song, session.model ?? kept?.model),
  { ...kept?.names, ...session.names }));
  const restored = `${count} ${count === 1 ? "model" : "models"} restored`;
  return missing ? `${restored}; ${missing}` : restored;
}

/** At start (a reload): the session kept in the browser restored as *open session* restores a
 * file (matched to this run's library by name); what it holds that is not served any more, or
 * whose name several items share, is said in one line. Returns `library`. */
export function restoreStored(app: App, library: api.Library): api.Library {
  const stored = storedSession();
  if (!stored) return library;
  const match = matched(stored, library);
  restoreSession(app, match, stored);
  if (match.missing) {
    app.messages.error(`The session kept in this browser: ${match.missing} (kept for when `
      + "it is served again); the rest is restored");
  }
  return library;
}

/** The model on screen: the rig shown, else the mesh (undefined before one is loaded). */
export function modelOf(app: App): SavedModel | undefined {
  if (app.rigs.active) return app.rigs.rig ? { kind: "rig", id: app.rigs.rig.id } : undefined;
  return app.library.meshId ? { kind: "mesh", id: app.library.meshId } : undefined;
}

/** What a start (or a reload) shows: `?mesh=` (a mesh); else the session's model while the
 * library has it; else the rig `firstRig` opens, or the library's first mesh (mesh: null). */
export function startModel(library: api.Library, meshOption: string | null):
    { rig: string | null; mesh: string | null } {
  const kept = meshOption ? undefined : storedSession()?.model;
  if (kept && inLibrary(library, kept)) {
    return kept.kind === "rig" ? { rig: kept.id, mesh: null } : { rig: null, mesh: kept.id };
  }
  return { rig: firstRig(library, meshOption), mesh: null };
}

/** The rig the page opens first: the first model given to `serve` when it is a rig (a skinned
 * glTF), or, in a library without meshes, the last rig added from a file; none with `?mesh=`. */
export function firstRig(library: api.Library, meshOption: string | null): string | null {
  if (meshOption) return null;
  const rigs = library.rigs ?? [];
  const first = library.first;
  if (first?.kind === "rig" && rigs.some((rig) => rig.id === first.id)) return first.id;
  if (library.meshes.length) return null;
  const added = rigs.filter((rig) => rig.origin === "file" || rig.origin === "upload");
  return added.length ? added[added.length - 1].id : null;
}

/** A session file's model shown, when the library has it and another is on screen. */
export async function resumeModel(app: App, model: SavedModel | undefined,
                                  library: api.Library): Promise<void> {
  const shown = modelOf(app);
  if (!model || !inLibrary(library, model)
      || (shown?.kind === model.kind && shown.id === model.id)) return;
  if (model.kind === "rig") await app.openRig(model.id); else await app.showMesh(model.id);
}

function inLibrary(library: api.Library, model: SavedModel): boolean {
  const items = model.kind === "rig" ? library.rigs ?? [] : library.meshes;
  return items.some((item) => item.id === model.id);
}

/** The page's song and where it is now (undefined before a song is loaded; its start while a
 * live input plays, whose clock is not the song's). */
export function songOf(app: App): SavedSong | undefined {
  const id = app.library.songId, transport = app.transport;
  return id ? { id, time: transport.following ? 0 : transport.now() } : undefined;
}

/** Load the song a start (or a reload) plays: `?song=`, else the session's while the library
 * still has it, else the library's first; the session's song paused where it was left. */
export async function loadStartSong(app: App, library: api.Library): Promise<void> {
  const kept = storedSession()?.song;
  const known = kept && library.songs.some((song) => song.id === kept.id);
  await app.library.loadSong(app.options.song ?? (known ? kept.id : library.songs[0].id));
  if (kept?.id === app.library.songId) seekTo(app, kept.time);
  keepInSession({ song: songOf(app) }); // the session's song is the one playing
}

/** A session file's song: chosen as in the song menu (the galleries calibrated on it) when the
 * library has it and another plays, then paused where it was left. False: not in the library. */
export async function resumeSong(app: App, song: SavedSong | undefined,
                                 library: api.Library): Promise<boolean> {
  if (!song) return true;
  if (!library.songs.some((item) => item.id === song.id)) return false;
  if (song.id !== app.library.songId || app.transport.following) await app.changeSong(song.id);
  app.transport.pause();
  seekTo(app, song.time);
  return true;
}

/** Paused at `time` (s) of the song; at its end, the start. */
function seekTo(app: App, time: number): void {
  const duration = app.transport.duration;
  app.transport.seek(time < duration - 0.5 ? time : 0);
  app.viewer.requestDraw();
}

/** A session file's text checked; throws one line saying what is wrong. */
export function readSession(text: string): Session {
  let data: unknown;
  try { data = JSON.parse(text); } catch { throw new Error("this file is not JSON"); }
  const session = data as Session;
  if (!session || session.format !== SESSION_FORMAT || typeof session.histories !== "object"
      || session.histories === null) {
    throw new Error(`this file is not an eigendance session (format "${SESSION_FORMAT}")`);
  }
  for (const [id, history] of Object.entries(session.histories)) {
    if (!Array.isArray(history?.generations) || !history.generations.every(
      (g) => Array.isArray(g?.mappings) && g.mappings.every((m) => Array.isArray(m?.transfer)))) {
      throw new Error(`the gallery of model ${id} in this session is not readable`);
    }
  }
  for (const [id, rig] of Object.entries(session.rigs ?? {})) {
    if (!Array.isArray(rig?.generations) || !rig.generations.every((g) => Array.isArray(g)
      && g.every((m) => Array.isArray(m?.transfer))) || !Array.isArray(rig.selected)) {
      throw new Error(`the galleries of rig ${id} in this session are not readable`);
    }
  }
  const song = session.song;
  if (song !== undefined && (typeof song?.id !== "string" || !Number.isFinite(song.time))) {
    throw new Error("the song of this session is not readable");
  }
  const model = session.model;
  if (model !== undefined && (typeof model?.id !== "string"
      || (model.kind !== "mesh" && model.kind !== "rig"))) {
    throw new Error("the model of this session is not readable");
  }
  if (session.names !== undefined && (typeof session.names !== "object" || session.names === null
      || !Object.values(session.names).every((name) => typeof name === "string"))) {
    throw new Error("the names of this session are not readable");
  }
  return session;
}

/** Keep the session in the browser (nothing is said when storage is off or full). */
export function storeSession(session: Session): void {
  try { localStorage.setItem(KEY, JSON.stringify(session)); } catch { /* private mode, full */ }
}

/** `session` without what it keeps of the library's item `id` (its gallery history or rig
 * galleries, its name, and the song or model on screen when it is that item). */
export function without(session: Session, id: string): Session {
  const drop = <T>(record: Record<string, T> | undefined) =>
    Object.fromEntries(Object.entries(record ?? {}).filter(([key]) => key !== id));
  const { song, model, ...rest } = session;
  return { ...rest, histories: drop(session.histories), rigs: drop(session.rigs),
    names: drop(session.names), ...(song && song.id !== id ? { song } : {}),
    ...(model && model.id !== id ? { model } : {}) };
}

/** Forget the library's item `id` in the session kept in the browser: removed on purpose (✕),
 * a reload does not say it is "not served any more". */
export function forgetInSession(app: App, id: string): void {
  app.gallery.forget(id);
  app.rigs.sessions.forget(id);
  const kept = storedSession();
  if (kept) storeSession(without(kept, id));
}

/** The session kept in the browser, or null. */
export function storedSession(): Session | null {
  try {
    const text = localStorage.getItem(KEY);
    return text ? readSession(text) : null;
  } catch {
    return null;
  }
}
